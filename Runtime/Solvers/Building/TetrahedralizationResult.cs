using System.Collections.Generic;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>What <see cref="LatticeTetrahedralizer.Build"/> produced, and every issue it found.</summary>
    public sealed class TetrahedralizationResult
    {
        /// <summary>The volume mesh (positively oriented tetrahedra); null when the build failed.</summary>
        public TetrahedralMesh Mesh;
        /// <summary>One entry per input render vertex: its tetrahedron and barycentric weights; null when the build failed.</summary>
        public EmbeddedVertex[] Embedding;
        /// <summary>Errors and warnings, in the order they were found.</summary>
        public List<ValidationIssue> Issues = new List<ValidationIssue>();
        /// <summary>Side of the lattice cells (m).</summary>
        public float CellSize;
        /// <summary>Lattice cells kept (each gives 6 tetrahedra).</summary>
        public int CellCount;
        /// <summary>Volume enclosed by the welded surface (m³, divergence theorem, in double): the body's true volume, for masses.</summary>
        public double SurfaceVolume;
        /// <summary>Total volume of the tetrahedra (m³, in double); larger than <see cref="SurfaceVolume"/> by about area × cell size / 2.</summary>
        public double TetrahedralVolume;

        /// <summary>True when the mesh and the embedding were built (no error).</summary>
        public bool Succeeded => Mesh != null && Embedding != null && !ValidationIssue.AnyError(Issues);
    }
}
