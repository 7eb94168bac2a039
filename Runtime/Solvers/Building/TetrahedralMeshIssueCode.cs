namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Problems of a tetrahedralisation and of a tetrahedral mesh (<see cref="LatticeTetrahedralizer"/>, <see cref="TetrahedralizationSettings"/>, <see cref="TetrahedralMeshChecks"/>).
    /// The numbers are unique across domains and stable (they may be stored); new codes take new numbers. An
    /// <see cref="IssueCode"/> carries any domain's code.
    /// </summary>
    public enum TetrahedralMeshIssueCode
    {
        /// <summary>TetrahedralizationSettings.Resolution outside 1..128.</summary>
        TetResolutionOutOfRange = 160,
        /// <summary>TetrahedralizationSettings.MaxNodes is not positive.</summary>
        MaxNodesInvalid = 161,
        /// <summary>The volume mesh would have more nodes than TetrahedralizationSettings.MaxNodes.</summary>
        TooManyNodes = 162,
        /// <summary>The surface has boundary or non-manifold edges (after welding), so it encloses no volume to fill with tetrahedra. Index: the first such triangle.</summary>
        VolumeMeshNotClosed = 163,
        /// <summary>Neighbouring triangles are wound in opposite senses, so the inside of the volume is undefined. Index: the first such triangle.</summary>
        VolumeMeshInconsistentWinding = 164,
        /// <summary>A tetrahedral mesh has no nodes or no tetrahedra.</summary>
        EmptyTetrahedralMesh = 165,
        /// <summary>A tetrahedral-mesh node position is NaN or infinite. Index: the first such node.</summary>
        NonFiniteNode = 166,
        /// <summary>A tetrahedron refers to a node that does not exist. Index: the first such tetrahedron.</summary>
        TetrahedronIndexOutOfRange = 167,
        /// <summary>A tetrahedron has zero volume (a repeated node, or flat to float32 precision). Index: the first such tetrahedron.</summary>
        TetrahedronDegenerate = 168,
        /// <summary>A tetrahedron has negative volume: its nodes are not positively oriented. Index: the first such tetrahedron.</summary>
        TetrahedronInverted = 169,
        /// <summary>Warning: tetrahedra of poor shape (quality below TetrahedralMeshChecks.SliverQuality). Index: the worst one.</summary>
        TetrahedronSliver = 170,
        /// <summary>Warning: nodes that no tetrahedron uses (they get no mass and move freely). Index: the first such node.</summary>
        UnusedNodes = 171,
    }
}
