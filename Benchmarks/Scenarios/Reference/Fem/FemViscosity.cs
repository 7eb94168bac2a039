using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Float64 Kelvin–Voigt viscous stress of the finite-element reference: the stiffness-proportional damping the package's
    /// Neo-Hookean FEM applies (FemElasticity.StrainRateDampingStress), written for any F:
    /// <code>
    ///   P_v = β F (2μ Ė + λ tr(Ė) I),   Ė = sym(Fᵀ Ḟ)  (Green strain rate)
    ///   ∂P_v,iJ / ∂Ḟ_kL = β (μ (F Fᵀ)_ik δ_JL + μ F_iL F_kJ + λ F_iJ F_kL)
    /// </code>
    /// with the small-strain Lamé constants (λ, μ) and the Rayleigh coefficient β (s). At F = I the viscous force is
    /// β K₀ v (K₀ the rest stiffness): a mode of angular frequency ω of the linearised body decays with damping ratio
    /// ζ = β ω / 2, so β = 2ζ/ω_ref gives ratio ζ at ω_ref. A rigid spin (Ḟ = W F, W skew) gives Ė = 0: no force.
    /// Its power P_v : Ḟ = β (2μ Ė : Ė + λ tr(Ė)²) ≥ 0 only dissipates. The rate tangent is symmetric under
    /// (iJ) ↔ (kL) (the direct solver's requirement).
    /// </summary>
    public static class FemViscosity
    {
        /// <summary>P_v (Pa) and, when <paramref name="rateTangent"/> is not empty, ∂P_v/∂Ḟ (Pa·s), at F = I + H with rate Ḟ.</summary>
        /// <param name="h">H = F − I, 9 doubles row-major.</param>
        /// <param name="hDot">Ḟ (1/s), 9 doubles row-major.</param>
        /// <param name="beta">β (s), ≥ 0.</param>
        /// <param name="mu">μ (Pa).</param>
        /// <param name="lambda">λ (Pa).</param>
        /// <param name="p">P_v (Pa), 9 doubles row-major, written.</param>
        /// <param name="rateTangent">∂P_v,iJ/∂Ḟ_kL (Pa·s) at [9(3i + J) + 3k + L], 81 doubles, written unless empty.</param>
        /// <param name="tangentDimension">3, or 2 to write only the in-plane entries (plane strain).</param>
        public static void Evaluate(ReadOnlySpan<double> h, ReadOnlySpan<double> hDot, double beta, double mu, double lambda,
            Span<double> p, Span<double> rateTangent, int tangentDimension = 3)
        {
            Span<double> f = stackalloc double[9];
            h.CopyTo(f);
            f[0] += 1; f[4] += 1; f[8] += 1;
            // Ė = sym(Fᵀ Ḟ); S = 2μ Ė + λ tr(Ė) I; P = β F S.
            Span<double> s = stackalloc double[9];
            double trace = 0;
            for (int m = 0; m < 3; m++)
            for (int j = 0; j < 3; j++)
            {
                double e = 0;
                for (int k = 0; k < 3; k++)
                    e += 0.5 * (f[3 * k + m] * hDot[3 * k + j] + f[3 * k + j] * hDot[3 * k + m]);
                s[3 * m + j] = 2 * mu * e;
                if (m == j)
                    trace += e;
            }
            s[0] += lambda * trace; s[4] += lambda * trace; s[8] += lambda * trace;
            for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                p[3 * i + j] = beta * (f[3 * i] * s[j] + f[3 * i + 1] * s[3 + j] + f[3 * i + 2] * s[6 + j]);
            if (rateTangent.IsEmpty)
                return;
            int d = tangentDimension;
            for (int i = 0; i < d; i++)
            for (int j = 0; j < d; j++)
            for (int k = 0; k < d; k++)
            for (int l = 0; l < d; l++)
            {
                double v = mu * f[3 * i + l] * f[3 * k + j] + lambda * f[3 * i + j] * f[3 * k + l];
                if (j == l)
                    v += mu * (f[3 * i] * f[3 * k] + f[3 * i + 1] * f[3 * k + 1] + f[3 * i + 2] * f[3 * k + 2]);
                rateTangent[9 * (3 * i + j) + 3 * k + l] = beta * v;
            }
        }
    }
}
