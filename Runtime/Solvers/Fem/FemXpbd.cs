using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Stable Neo-Hookean elasticity as XPBD constraints (Macklin &amp; Müller 2021, "A Constraint-based Formulation of
    /// Stable Neo-Hookean Materials", §4): per element a deviatoric constraint C_D = √tr(FᵀF) with compliance
    /// 1/(μV) and a hydrostatic constraint C_H = det F − γ, γ = 1 + μ/λ, with compliance 1/(λV) (λ the stable
    /// Neo-Hookean λ + μ), so ½ C_D²/α_D + ½ C_H²/α_H = V Ψ up to a constant. Each is projected with the XPBD update
    /// of Macklin, Müller &amp; Chentanez 2016, eq. 26, including its damping term:
    /// <code>
    ///   Δλ = (−C − α̃ λ − γ_d ∇C · (p − x)) / ((1 + γ_d) Σ wᵢ |∇ᵢC|² + α̃),   pᵢ += wᵢ ∇ᵢC Δλ
    /// </code>
    /// with α̃ = α/h² and γ_d = α̃ β h (β̃ = h² β, β the Rayleigh coefficient of <see cref="FemSolver.DampingCoefficient"/>).
    /// Elements of one colour share no node, so a colour is projected in any order or split with the same bits.
    /// </summary>
    public static class FemXpbd
    {
        /// <summary>
        /// Projects the elements <paramref name="colorElements"/>[<paramref name="start"/> .. <paramref name="end"/>) (all of
        /// one colour) on the predicted positions <paramref name="p"/>; <paramref name="x"/> are the positions at the
        /// substep's start (damping), <paramref name="multipliers"/> the per-element (λ_D, λ_H) of the substep.
        /// </summary>
        public static void Project(in FemModel model, ReadOnlySpan<int> colorElements, ReadOnlySpan<float3> x, Span<float3> p,
            Span<float3> multipliers, float h, float beta, int start, int end)
        {
            float mu = model.Mu;
            float lambdaSnh = FemElasticity.NeoHookeanLambda(mu, model.Lambda);
            float gamma = 1f + mu / lambdaSnh;
            float invH2 = 1f / (h * h);
            ReadOnlySpan<float> w = model.InverseMasses;
            for (int c = start; c < end; c++)
            {
                int e = colorElements[c];
                TetElement element = model.Elements[e];
                int4 n = element.Nodes;
                float3 lambdas = multipliers[e];
                // Deviatoric: C_D = ‖F‖_F, ∂C_D/∂F = F / C_D.
                float3x3 f = FemElasticity.DeformationGradient(p[n.x], p[n.y], p[n.z], p[n.w], element.InverseRestShape);
                float cd = math.sqrt(FemElasticity.DoubleDot(f, f));
                if (cd > 1e-12f)
                    lambdas.x += Apply(element, f * (1f / cd), cd, invH2 / (mu * element.RestVolume), beta * h, lambdas.x, x, p, w);
                // Hydrostatic: C_H = det F − γ, ∂C_H/∂F = cof F (from the positions the deviatoric step left).
                f = FemElasticity.DeformationGradient(p[n.x], p[n.y], p[n.z], p[n.w], element.InverseRestShape);
                float ch = math.determinant(f) - gamma;
                lambdas.y += Apply(element, FemElasticity.Cofactor(f), ch, invH2 / (lambdaSnh * element.RestVolume), beta * h, lambdas.y, x, p, w);
                multipliers[e] = lambdas;
            }
        }

        /// <summary>One constraint's XPBD update (eq. 26 of Macklin et al. 2016) given ∂C/∂F; returns Δλ.</summary>
        static float Apply(in TetElement element, in float3x3 dcdf, float constraint, float alphaTilde, float betaH, float lambda,
            ReadOnlySpan<float3> x, Span<float3> p, ReadOnlySpan<float> w)
        {
            int4 n = element.Nodes;
            // ∇ᵢC: columns of (∂C/∂F) Dm⁻ᵀ for nodes 1..3, minus their sum for node 0.
            float3x3 g = math.mul(dcdf, math.transpose(element.InverseRestShape));
            float3 g0 = -(g.c0 + g.c1 + g.c2);
            float w0 = w[n.x], w1 = w[n.y], w2 = w[n.z], w3 = w[n.w];
            float weighted = w0 * math.lengthsq(g0) + w1 * math.lengthsq(g.c0) + w2 * math.lengthsq(g.c1) + w3 * math.lengthsq(g.c2);
            float dampingGamma = alphaTilde * betaH;
            float velocityTerm = math.dot(g0, p[n.x] - x[n.x]) + math.dot(g.c0, p[n.y] - x[n.y]) + math.dot(g.c1, p[n.z] - x[n.z])
                                 + math.dot(g.c2, p[n.w] - x[n.w]);
            float denominator = (1f + dampingGamma) * weighted + alphaTilde;
            if (!(denominator > 0f))
                return 0f;
            float dl = (-constraint - alphaTilde * lambda - dampingGamma * velocityTerm) / denominator;
            p[n.x] += w0 * dl * g0;
            p[n.y] += w1 * dl * g.c0;
            p[n.z] += w2 * dl * g.c1;
            p[n.w] += w3 * dl * g.c2;
            return dl;
        }
    }
}
