namespace SoftBodyDynamics.Solvers
{
    /// <summary>Which validator an <see cref="IssueCode"/> comes from, and so which enum names it.</summary>
    public enum IssueDomain : byte
    {
        /// <summary><see cref="MeshBuildIssueCode"/>.</summary>
        MeshBuild,
        /// <summary><see cref="ParticleBodyIssueCode"/>.</summary>
        ParticleBody,
        /// <summary><see cref="ShapeMatchingIssueCode"/>.</summary>
        ShapeMatching,
        /// <summary><see cref="MassSpringIssueCode"/>.</summary>
        MassSpring,
        /// <summary><see cref="FemIssueCode"/>.</summary>
        Fem,
        /// <summary><see cref="TetrahedralMeshIssueCode"/>.</summary>
        TetrahedralMesh,
        /// <summary><see cref="SoftBodyAuthoringIssueCode"/>.</summary>
        SoftBodyAuthoring,
        /// <summary><see cref="ColliderIssueCode"/>.</summary>
        Collider,
        /// <summary><see cref="FluidIssueCode"/>.</summary>
        Fluid,
        /// <summary><see cref="FluidEmissionIssueCode"/>.</summary>
        FluidEmission,
        /// <summary><see cref="FluidSurfaceIssueCode"/>.</summary>
        FluidSurface,
    }
}
