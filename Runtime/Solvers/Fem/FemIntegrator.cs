namespace SoftBodyDynamics.Solvers
{
    /// <summary>How a finite-element body advances one substep.</summary>
    public enum FemIntegrator
    {
        /// <summary>
        /// Explicit: v += h M⁻¹ (f_elastic + f_damping), then x += h v. Cheapest per substep, stable only for
        /// h &lt; <see cref="FemStability.MaxStableStep(in FemModel, FemMaterialModel)"/> (stiff materials need many substeps).
        /// </summary>
        SymplecticEuler = 0,
        /// <summary>
        /// Linearly implicit backward Euler (Baraff &amp; Witkin 1998) solved by conjugate gradients: on the warped stiffness
        /// (co-rotational, Müller &amp; Gross 2004) or on the Neo-Hookean Hessian projected to positive semi-definite (Smith,
        /// de Goes &amp; Kim 2018), with <see cref="FemParameters.NewtonIterations"/> Newton iterations. Unconditionally
        /// stable; damps high frequencies at large steps. Both models.
        /// </summary>
        ImplicitEuler = 1,
        /// <summary>
        /// Extended position-based dynamics on the Neo-Hookean energy as two constraints per element (Macklin &amp; Müller
        /// 2021): stable at any step, converges to the implicit solution with small substeps. Neo-Hookean only
        /// (co-rotational falls back to <see cref="SymplecticEuler"/> and the step reports it).
        /// </summary>
        Xpbd = 2,
    }
}
