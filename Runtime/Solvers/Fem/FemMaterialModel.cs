namespace SoftBodyDynamics.Solvers
{
    /// <summary>The constitutive model of a finite-element body: how the stress of an element follows from its deformation gradient F.</summary>
    public enum FemMaterialModel
    {
        /// <summary>
        /// Co-rotational linear elasticity (Müller &amp; Gross 2004): the element's rotation R is removed from F and the
        /// rest is linear, P = R(2μ ε + λ tr(ε) I), ε = ½(RᵀF + FᵀR) − I. Exact for large rotations, linear in stretch.
        /// </summary>
        CoRotational = 0,
        /// <summary>
        /// Stable Neo-Hookean (Smith, de Goes &amp; Kim 2018): Ψ = μ/2 (I_C − 3) + λ/2 (J − α)², α = 1 + μ/λ. Non-linear,
        /// volume-stiffening, finite and restoring for inverted elements (no log J).
        /// </summary>
        NeoHookean = 1,
    }
}
