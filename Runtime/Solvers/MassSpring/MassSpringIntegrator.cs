namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// How a mass-spring body advances in time. Forward (explicit) Euler is not offered: it amplifies every
    /// undamped oscillation by √(1 + ω²h²) per step, so it is unstable at any step size.
    /// </summary>
    public enum MassSpringIntegrator
    {
        /// <summary>
        /// Symplectic (semi-implicit) Euler: v += h M⁻¹ f(x, v), then x += h v. Cheapest; energy stays in a band, no
        /// drift. Stable iff h &lt; 2/ω_max (<see cref="MassSpringStability.MaxStableStep"/>).
        /// </summary>
        SymplecticEuler = 0,
        /// <summary>
        /// Störmer–Verlet, x_{n+1} = 2xₙ − x_{n−1} + h² a(xₙ). Its positions are those of symplectic Euler (the same
        /// sequence, up to round-off); the same stability bound.
        /// </summary>
        Verlet = 1,
        /// <summary>
        /// Linearised backward Euler (Baraff &amp; Witkin 1998) solved by conjugate gradients: unconditionally
        /// stable, numerically damped (strongly when ωh is not small). For stiff springs and large steps.
        /// </summary>
        ImplicitEuler = 2,
        /// <summary>
        /// Extended position-based dynamics (Macklin, Müller &amp; Chentanez 2016): distance constraints with
        /// compliance 1/k, stable at any step, converges to the stiffness with small substeps.
        /// </summary>
        Xpbd = 3,
    }
}
