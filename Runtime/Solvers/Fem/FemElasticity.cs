using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Per-element continuum mechanics of linear tetrahedra: deformation gradient, energy density Ψ(F) and first
    /// Piola–Kirchhoff stress P = ∂Ψ/∂F of both constitutive models, their stiffness and damping differentials, and
    /// the nodal forces of a stress (Sifakis &amp; Barbič 2012, §4). Pure functions, Burst-compatible.
    /// </summary>
    public static class FemElasticity
    {
        /// <summary>F = Ds Dm⁻¹, Ds = [x₁ − x₀, x₂ − x₀, x₃ − x₀] (dimensionless).</summary>
        public static float3x3 DeformationGradient(float3 x0, float3 x1, float3 x2, float3 x3, in float3x3 inverseRestShape) =>
            math.mul(new float3x3(x1 - x0, x2 - x0, x3 - x0), inverseRestShape);

        /// <summary>cof(F) = ∂ det F / ∂F = [f₁ × f₂, f₂ × f₀, f₀ × f₁] for the columns fₖ of F.</summary>
        public static float3x3 Cofactor(in float3x3 f) =>
            new float3x3(math.cross(f.c1, f.c2), math.cross(f.c2, f.c0), math.cross(f.c0, f.c1));

        /// <summary>Frobenius inner product A : B = tr(AᵀB).</summary>
        public static float DoubleDot(in float3x3 a, in float3x3 b) =>
            math.dot(a.c0, b.c0) + math.dot(a.c1, b.c1) + math.dot(a.c2, b.c2);

        static float Trace(in float3x3 m) => m.c0.x + m.c1.y + m.c2.z;

        /// <summary>
        /// Stable Neo-Hookean λ (Pa) from the linear Lamé parameters: with no log term the energy linearises to
        /// μ‖ε‖² + (λ_snh − μ)/2 tr(ε)² at rest, so λ_snh = λ + μ matches linear elasticity (Smith et al. 2018, §3.4).
        /// </summary>
        public static float NeoHookeanLambda(float mu, float lambda) => lambda + mu;

        /// <summary>ε = ½(RᵀF + FᵀR) − I, the co-rotated small strain.</summary>
        public static float3x3 CoRotatedStrain(in float3x3 f, in float3x3 r)
        {
            float3x3 s = math.mul(math.transpose(r), f);
            return 0.5f * (s + math.transpose(s)) - float3x3.identity;
        }

        /// <summary>Co-rotational energy density Ψ = μ ε : ε + λ/2 tr(ε)² (J/m³), R the rotation of F (Müller &amp; Gross 2004).</summary>
        public static float CoRotationalEnergy(in float3x3 f, in float3x3 r, float mu, float lambda)
        {
            float3x3 e = CoRotatedStrain(f, r);
            float tr = Trace(e);
            return mu * DoubleDot(e, e) + 0.5f * lambda * tr * tr;
        }

        /// <summary>
        /// Co-rotational stress P = R(2μ ε + λ tr(ε) I) (Pa). With R the polar rotation of F this is exactly ∂Ψ/∂F:
        /// Ψ = μ‖F − R‖² + λ/2 (tr(RᵀF) − 3)² and R extremises both terms, so its variation does not contribute.
        /// </summary>
        public static float3x3 CoRotationalStress(in float3x3 f, in float3x3 r, float mu, float lambda)
        {
            float3x3 e = CoRotatedStrain(f, r);
            return math.mul(r, 2f * mu * e + lambda * Trace(e) * float3x3.identity);
        }

        /// <summary>
        /// Warped stiffness differential δP = R(2μ sym(Rᵀ δF) + λ tr(Rᵀ δF) I) (Pa) with R held fixed: the stress change
        /// of K_R = R K₀ Rᵀ (Müller &amp; Gross 2004, eq. 5). Symmetric positive semi-definite; zero for δF = W R, W skew.
        /// </summary>
        public static float3x3 WarpedStressDifferential(in float3x3 r, in float3x3 df, float mu, float lambda)
        {
            float3x3 s = math.mul(math.transpose(r), df);
            return math.mul(r, mu * (s + math.transpose(s)) + lambda * Trace(s) * float3x3.identity);
        }

        /// <summary>Stable Neo-Hookean energy density Ψ = μ/2 (tr(FᵀF) − 3) + λ/2 (det F − α)², α = 1 + μ/λ (J/m³; Smith et al. 2018, eq. 14 without the log term).</summary>
        public static float NeoHookeanEnergy(in float3x3 f, float mu, float lambdaSnh)
        {
            float alpha = 1f + mu / lambdaSnh;
            float j = math.determinant(f) - alpha;
            return 0.5f * mu * (DoubleDot(f, f) - 3f) + 0.5f * lambdaSnh * j * j;
        }

        /// <summary>
        /// Ψ(F + D) − Ψ(F) of the stable Neo-Hookean energy (J/m³) without forming either value (their common offset
        /// would cancel in float32): μ/2 D : (2F + D) + λ/2 ΔJ (2(J − α) + ΔJ), with the exact expansion of the 3×3
        /// determinant ΔJ = det(F + D) − det F = cof(F) : D + F : cof(D) + det D.
        /// </summary>
        public static float NeoHookeanEnergyChange(in float3x3 f, in float3x3 d, float mu, float lambdaSnh)
        {
            float alpha = 1f + mu / lambdaSnh;
            float dj = DoubleDot(Cofactor(f), d) + DoubleDot(f, Cofactor(d)) + math.determinant(d);
            return 0.5f * mu * DoubleDot(d, 2f * f + d) + 0.5f * lambdaSnh * dj * (2f * (math.determinant(f) - alpha) + dj);
        }

        /// <summary>
        /// Stable Neo-Hookean stress P = ∂Ψ/∂F = μ F + λ (J − α) cof(F) (Pa). Finite for every F: an inverted or flat
        /// element (J ≤ 0) is pushed back toward J = α by the cofactor term. Zero at F = I since λ(1 − α) = −μ.
        /// </summary>
        public static float3x3 NeoHookeanStress(in float3x3 f, float mu, float lambdaSnh)
        {
            float alpha = 1f + mu / lambdaSnh;
            return mu * f + lambdaSnh * (math.determinant(f) - alpha) * Cofactor(f);
        }

        /// <summary>
        /// Rotation-invariant stiffness-proportional damping stress (Pa): P_d = β F (2μ Ė + λ tr(Ė) I) with the Green
        /// strain rate Ė = sym(Fᵀ Ḟ). At rest it is β K₀ Ḟ; a rigid spin (Ḟ = W F, W skew) gives Ė = 0 and no force;
        /// its power P_d : Ḟ = β (2μ Ė : Ė + λ tr(Ė)²) ≥ 0 only dissipates.
        /// </summary>
        public static float3x3 StrainRateDampingStress(in float3x3 f, in float3x3 fDot, float beta, float mu, float lambda)
        {
            float3x3 g = math.mul(math.transpose(f), fDot);
            float3x3 eDot = 0.5f * (g + math.transpose(g));
            return beta * math.mul(f, 2f * mu * eDot + lambda * Trace(eDot) * float3x3.identity);
        }

        /// <summary>
        /// Nodal forces of a stress P on an element: H = −V P Dm⁻ᵀ, f₁..f₃ = columns of H, f₀ = −(f₁ + f₂ + f₃)
        /// (Sifakis &amp; Barbič 2012, §4.3). Written to <paramref name="slots"/>[0..4). They sum to zero (to round-off).
        /// </summary>
        public static void NodalForces(in float3x3 p, in TetElement element, Span<float3> slots)
        {
            float3x3 h = -element.RestVolume * math.mul(p, math.transpose(element.InverseRestShape));
            slots[1] = h.c0;
            slots[2] = h.c1;
            slots[3] = h.c2;
            slots[0] = -(h.c0 + h.c1 + h.c2);
        }
    }
}
