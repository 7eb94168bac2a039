namespace SoftBodyDynamics.Solvers
{
    /// <summary>What holds a soft body's particles together. Every method shares the particle step (<see cref="ParticleBodyStep"/>).</summary>
    public enum SoftBodyMethod
    {
        /// <summary>Meshless shape matching (Müller et al. 2005): particles pulled toward the goals of best-fit cluster transforms.</summary>
        ShapeMatching = 0,
        /// <summary>A network of springs along the edges of the body's tetrahedra (Teschner et al. 2003).</summary>
        MassSpring = 1,
        /// <summary>Linear tetrahedral finite elements (co-rotational or Neo-Hookean).</summary>
        Fem = 2,
    }
}
