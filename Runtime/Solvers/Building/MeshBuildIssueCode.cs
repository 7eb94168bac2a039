namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Problems of a surface mesh and of the build settings that turn it into a particle body (<see cref="MeshChecks"/>, <see cref="MeshWelding"/>, <see cref="SoftBodyBuildSettingsValidation"/>, <see cref="SoftBodyBuilder"/>; the first two are found by the Unity-side authoring).
    /// The numbers are unique across domains and stable (they may be stored); new codes take new numbers. An
    /// <see cref="IssueCode"/> carries any domain's code.
    /// </summary>
    public enum MeshBuildIssueCode
    {
        /// <summary>No mesh is assigned.</summary>
        NoMesh = 1,
        /// <summary>The mesh's data is not readable on the CPU (Read/Write disabled in its import settings).</summary>
        MeshNotReadable = 2,
        /// <summary>The mesh has no vertices or no triangles.</summary>
        EmptyMesh = 10,
        /// <summary>A vertex position is NaN or infinite. Index: the first such vertex.</summary>
        NonFiniteVertex = 11,
        /// <summary>The triangle index buffer's length is not a multiple of 3.</summary>
        TriangleCountNotMultipleOfThree = 12,
        /// <summary>A triangle refers to a vertex that does not exist. Index: the first such triangle.</summary>
        TriangleIndexOutOfRange = 13,
        /// <summary>All vertices coincide (zero-size bounds), or welding merged them all into one particle.</summary>
        ZeroSize = 14,
        /// <summary>Warning: triangles with zero area or a repeated vertex after welding. Index: the first such triangle.</summary>
        DegenerateTriangles = 15,
        /// <summary>Warning: edges shared by more than two triangles. Index: the first triangle using such an edge.</summary>
        NonManifoldEdges = 16,
        /// <summary>Warning: the mesh has boundary edges, so it has no inside; interior particles were skipped. Index: the first boundary triangle.</summary>
        NotClosed = 17,
        /// <summary>Warning: neighbouring triangles are wound in opposite senses, so inside and outside are undefined; interior particles were skipped. Index: the first such triangle.</summary>
        InconsistentWinding = 18,
        /// <summary>The relative or absolute weld tolerance is negative, NaN or infinite.</summary>
        WeldToleranceInvalid = 30,
        /// <summary>The total mass is zero, negative, NaN or infinite.</summary>
        TotalMassNotPositive = 31,
        /// <summary>The cluster size is negative, NaN, infinite, or so small that the cluster lattice cannot be indexed.</summary>
        ClusterSizeInvalid = 32,
        /// <summary>The interior spacing is negative, NaN, infinite, or so small that the lattice is unreasonably large.</summary>
        InteriorSpacingInvalid = 33,
        /// <summary>The particle limit is not positive.</summary>
        MaxParticlesInvalid = 34,
        /// <summary>The body would have more particles than the limit.</summary>
        TooManyParticles = 35,
        /// <summary>Warning: clusters with fewer than 4 particles or a planar rest shape had to be kept, because they alone cover some particles.</summary>
        WeakClusters = 36,
    }
}
