namespace SoftBodyDynamics.Solvers
{
    /// <summary>What <see cref="MassSpringNetwork.Build"/> puts in a network besides the structural springs.</summary>
    public struct MassSpringBuildSettings
    {
        /// <summary>
        /// Add bending springs: one between the two opposite nodes of every pair of tetrahedra sharing a face. They
        /// resist the hinge motion of two tetrahedra about their common face more directly; calibration accounts for
        /// them (the fitted factor is computed with the same settings).
        /// </summary>
        public bool BendingSprings;

        /// <summary>Structural springs only.</summary>
        public static MassSpringBuildSettings Default => new MassSpringBuildSettings { BendingSprings = false };
    }
}
