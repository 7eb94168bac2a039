namespace SoftBodyDynamics.Solvers
{
    /// <summary>How a fluid keeps its density near the rest density.</summary>
    public enum FluidSolverKind : byte
    {
        /// <summary>
        /// Weakly compressible SPH (Müller et al. 2003 forces, Becker &amp; Teschner 2007 Tait equation of state): cheap
        /// per substep, but the substep is limited by the speed of sound (CFL), so stiff water costs many substeps.
        /// </summary>
        WeaklyCompressible = 0,
        /// <summary>
        /// Position-based fluids (Macklin &amp; Müller 2013): a density constraint solved by Jacobi iterations on
        /// predicted positions; large substeps, accuracy set by the iteration count.
        /// </summary>
        PositionBased = 1,
    }

    /// <summary>Which cohesion (cheap surface tension) a fluid uses.</summary>
    public enum FluidCohesionModel : byte
    {
        /// <summary>No cohesion pass.</summary>
        None = 0,
        /// <summary>Flocking rules: steer toward the neighbour centroid, keep a separation, align velocities.</summary>
        Flocking = 1,
        /// <summary>Akinci et al. 2013 cohesion and curvature forces (the physical reference).</summary>
        Akinci = 2,
    }
}
