using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The energy Hessian ∂²Ψ/∂F² of the stable Neo-Hookean model at one element's F (the tangent stiffness of the
    /// implicit step), in the closed-form eigen-structure of Smith, de Goes &amp; Kim 2018, §4 ("energy eigenanalysis"),
    /// re-derived for the energy without the log term that the package uses (<see cref="FemElasticity.NeoHookeanEnergy"/>):
    /// Ψ = μ/2 (Σσᵢ² − 3) + λ/2 (J − α)², J = σ₀σ₁σ₂, for F = U diag(σ) Vᵀ with U, V proper rotations (σ signed, so an
    /// inverted element has one σ &lt; 0). In the frame M = Uᵀ δF V the Hessian splits into
    /// <list type="bullet">
    /// <item>the scaling block on (M₀₀, M₁₁, M₂₂): A = μI + λ g gᵀ + λ(J − α) H, gᵢ = ∂J/∂σᵢ = σⱼσₖ, H = ∂²J/∂σ²
    /// (Hᵢⱼ = σₖ off the diagonal, 0 on it);</item>
    /// <item>for each pair (i, j), k the third index, a 2×2 block on (Mᵢⱼ, Mⱼᵢ) = [[μ, −λ(J − α)σₖ], [−λ(J − α)σₖ, μ]]
    /// with the paper's twist eigenvector (1, −1)/√2, eigenvalue μ + λ(J − α)σₖ, and flip eigenvector (1, 1)/√2,
    /// eigenvalue μ − λ(J − α)σₖ.</item>
    /// </list>
    /// The projection to positive semi-definite (the paper's "project the Hessian to semi-positive-definiteness")
    /// clamps each of the nine eigenvalues at 0: the twist/flip ones in closed form, A's by a 3×3 Jacobi decomposition
    /// (A is left untouched when already semi-definite). At rest it is exact linear elasticity,
    /// δP = 2μ sym δF + (λ − μ) tr(δF) I, with a zero twist eigenvalue: rotations cost nothing.
    /// The frame comes from the polar rotation R of F (the warm-started <see cref="RotationExtraction"/>) and the
    /// eigenvectors W of the symmetric sym(RᵀF): U = R W, V = W. Burst-compatible.
    /// </summary>
    public struct NeoHookeanTangent
    {
        /// <summary>W: the eigenvectors of sym(RᵀF) (a proper rotation); U = R W, V = W.</summary>
        public quaternion Frame;
        /// <summary>(A₀₀, A₁₁, A₂₂) of the scaling block (Pa).</summary>
        public float3 ScalingDiagonal;
        /// <summary>(A₀₁, A₀₂, A₁₂) of the scaling block (Pa).</summary>
        public float3 ScalingOffDiagonal;
        /// <summary>Per third index k: ½(λ_twist + λ_flip) of the pair (i, j), the coefficient of Mᵢⱼ in M′ᵢⱼ (Pa).</summary>
        public float3 PairSum;
        /// <summary>Per third index k: ½(λ_flip − λ_twist) of the pair (i, j), the coefficient of Mⱼᵢ in M′ᵢⱼ (Pa).</summary>
        public float3 PairDifference;

        /// <summary>float3s one tangent takes in a span (<see cref="Store"/>, <see cref="Load"/>).</summary>
        public const int Float3Count = 6;

        /// <summary>
        /// The Hessian at F = <paramref name="f"/> with R = <paramref name="r"/> a rotation of F (RᵀF symmetric for the polar
        /// rotation; its skew part, the extraction's residual, is dropped). μ (Pa), λ = <paramref name="lambdaSnh"/> (Pa, the
        /// stable Neo-Hookean λ of <see cref="FemElasticity.NeoHookeanLambda"/>). <paramref name="project"/>: clamp negative
        /// eigenvalues to 0 (the implicit step's K); false gives the exact Hessian (tests).
        /// </summary>
        public static NeoHookeanTangent Compute(in float3x3 f, in float3x3 r, float mu, float lambdaSnh, bool project)
        {
            SymmetricEigen.Decompose(math.mul(math.transpose(r), f), out float3x3 w, out float3 sigma);
            float alpha = 1f + mu / lambdaSnh;
            float s = lambdaSnh * (sigma.x * sigma.y * sigma.z - alpha);
            var g = new float3(sigma.y * sigma.z, sigma.x * sigma.z, sigma.x * sigma.y);
            // A = μI + λ g gᵀ + λ(J − α) ∂²J/∂σ².
            float3 diagonal = mu + lambdaSnh * g * g;
            float3 off = lambdaSnh * new float3(g.x * g.y, g.x * g.z, g.y * g.z) + s * new float3(sigma.z, sigma.y, sigma.x);
            // Twist and flip of the pair (i, j) whose third index is k: μ ± λ(J − α)σₖ.
            float3 twist = mu + s * sigma, flip = mu - s * sigma;
            if (project)
            {
                twist = math.max(twist, 0f);
                flip = math.max(flip, 0f);
                var a = new float3x3(
                    new float3(diagonal.x, off.x, off.y),
                    new float3(off.x, diagonal.y, off.z),
                    new float3(off.y, off.z, diagonal.z));
                SymmetricEigen.Decompose(a, out float3x3 q, out float3 e);
                if (math.cmin(e) < 0f)
                {
                    // A⁺ = Q diag(max(e, 0)) Qᵀ.
                    e = math.max(e, 0f);
                    float3x3 qe = new float3x3(q.c0 * e.x, q.c1 * e.y, q.c2 * e.z);
                    float3x3 projected = math.mul(qe, math.transpose(q));
                    diagonal = new float3(projected.c0.x, projected.c1.y, projected.c2.z);
                    off = new float3(projected.c1.x, projected.c2.x, projected.c2.y);
                }
            }
            return new NeoHookeanTangent
            {
                Frame = new quaternion(w),
                ScalingDiagonal = diagonal,
                ScalingOffDiagonal = off,
                PairSum = 0.5f * (twist + flip),
                PairDifference = 0.5f * (flip - twist),
            };
        }

        /// <summary>
        /// δP = (∂²Ψ/∂F²) : δF (Pa) for the element's rotation R = <paramref name="r"/> (the one the tangent was computed
        /// with): M = Uᵀ δF V, M′ = the blocks applied to M, δP = U M′ Vᵀ.
        /// </summary>
        public float3x3 StressDifferential(in float3x3 r, in float3x3 df)
        {
            var v = new float3x3(Frame);
            float3x3 u = math.mul(r, v);
            float3x3 m = math.mul(math.transpose(u), math.mul(df, v));
            float3 d = new float3(m.c0.x, m.c1.y, m.c2.z);
            float3 a = ScalingDiagonal, o = ScalingOffDiagonal;
            float3 dScaled = new float3(
                a.x * d.x + o.x * d.y + o.y * d.z,
                o.x * d.x + a.y * d.y + o.z * d.z,
                o.y * d.x + o.z * d.y + a.z * d.z);
            float3 sum = PairSum, difference = PairDifference;
            // Entries (row, column): pair (0,1) ↔ k = 2, (0,2) ↔ k = 1, (1,2) ↔ k = 0.
            float m01 = m.c1.x, m10 = m.c0.y, m02 = m.c2.x, m20 = m.c0.z, m12 = m.c2.y, m21 = m.c1.z;
            var mPrime = new float3x3(
                new float3(dScaled.x, difference.z * m01 + sum.z * m10, difference.y * m02 + sum.y * m20),
                new float3(sum.z * m01 + difference.z * m10, dScaled.y, difference.x * m12 + sum.x * m21),
                new float3(sum.y * m02 + difference.y * m20, sum.x * m12 + difference.x * m21, dScaled.z));
            return math.mul(u, math.mul(mPrime, math.transpose(v)));
        }

        /// <summary>Writes the tangent to <paramref name="to"/>[0 .. <see cref="Float3Count"/>).</summary>
        public void Store(Span<float3> to)
        {
            float4 w = Frame.value;
            to[0] = w.xyz;
            to[1] = new float3(w.w, ScalingDiagonal.x, ScalingDiagonal.y);
            to[2] = new float3(ScalingDiagonal.z, ScalingOffDiagonal.x, ScalingOffDiagonal.y);
            to[3] = new float3(ScalingOffDiagonal.z, PairSum.x, PairSum.y);
            to[4] = new float3(PairSum.z, PairDifference.x, PairDifference.y);
            to[5] = new float3(PairDifference.z, 0f, 0f);
        }

        /// <summary>The tangent <see cref="Store"/> wrote to <paramref name="from"/>.</summary>
        public static NeoHookeanTangent Load(ReadOnlySpan<float3> from)
        {
            float3 t0 = from[0], t1 = from[1], t2 = from[2], t3 = from[3], t4 = from[4], t5 = from[5];
            return new NeoHookeanTangent
            {
                Frame = new quaternion(new float4(t0, t1.x)),
                ScalingDiagonal = new float3(t1.y, t1.z, t2.x),
                ScalingOffDiagonal = new float3(t2.y, t2.z, t3.x),
                PairSum = new float3(t3.y, t3.z, t4.x),
                PairDifference = new float3(t4.y, t4.z, t5.x),
            };
        }
    }
}
