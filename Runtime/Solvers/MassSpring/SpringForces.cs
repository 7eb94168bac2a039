using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The per-spring passes of the mass-spring integrators, written as range functions (springs [start, end)) so a job
    /// can run them per batch: each spring writes its two slots (2e for A, 2e + 1 for B), and
    /// <see cref="ElementIncidence.Gather"/> sums them per particle in a fixed order. The result has the same bits for
    /// any split of either pass.
    /// </summary>
    public static class SpringForces
    {
        /// <summary>Below this fraction of the rest length the endpoints count as coincident and the rest direction is used.</summary>
        public const float CoincidentFraction = 1e-6f;

        /// <summary>
        /// Unit direction n from A to B and length L of a spring at positions <paramref name="xA"/>, <paramref name="xB"/>.
        /// When the endpoints (nearly) coincide the direction is undefined (0/0): the rest direction is used instead, so
        /// the force stays finite and has the magnitude k |L − L₀| ≤ k L₀.
        /// </summary>
        public static float3 Direction(in Spring s, float3 xA, float3 xB, float3 restA, float3 restB, out float length)
        {
            float3 d = xB - xA;
            length = math.length(d);
            if (length > CoincidentFraction * s.RestLength && length > 0f)
                return d / length;
            return math.normalizesafe(restB - restA, new float3(1f, 0f, 0f));
        }

        /// <summary>
        /// Force on A (N; the force on B is its negative), Teschner et al. 2003 eq. 1 with a dashpot along the spring:
        /// f_A = (k (L − L₀) + c (v_B − v_A)·n) n. A spring of rest length 0 uses the linear form k (x_B − x_A), which
        /// needs no direction.
        /// </summary>
        public static float3 Force(in Spring s, float3 xA, float3 xB, float3 vA, float3 vB, float3 restA, float3 restB)
        {
            float3 n = Direction(s, xA, xB, restA, restB, out float length);
            float damping = s.Damping * math.dot(vB - vA, n);
            if (s.RestLength == 0f)
                return s.Stiffness * (xB - xA) + damping * n;
            return (s.Stiffness * (length - s.RestLength) + damping) * n;
        }

        /// <summary>Spring and dashpot forces of springs [<paramref name="start"/>, <paramref name="end"/>) into their slots.</summary>
        public static void Compute(ReadOnlySpan<Spring> springs, ReadOnlySpan<float3> rest, ReadOnlySpan<float3> x, ReadOnlySpan<float3> v,
            int start, int end, Span<float3> slots)
        {
            for (int e = start; e < end; e++)
            {
                Spring s = springs[e];
                float3 f = Force(s, x[s.A], x[s.B], v[s.A], v[s.B], rest[s.A], rest[s.B]);
                slots[2 * e] = f;
                slots[2 * e + 1] = -f;
            }
        }

        /// <summary>
        /// Implicit Euler, per spring (Baraff &amp; Witkin 1998, eq. 18): the block S = h c nnᵀ + h² k [nnᵀ + s (I − nnᵀ)]
        /// with s = max(0, 1 − L₀/L), so that A = M − h ∂f/∂v − h² ∂f/∂x is M plus S on the diagonal blocks (A, A),
        /// (B, B) and −S off it. The clamp s ≥ 0 keeps the definite part of the spring Jacobian for a compressed spring
        /// (L &lt; L₀), where the transverse term k (1 − L₀/L) would be negative and could make A indefinite.
        /// Writes the frame (n; (h c + h² k, h² k s, 0)) to <paramref name="frames"/>[2e], [2e + 1], and the right-hand
        /// side h (f + h ∂f/∂x v) per slot: slot A = h f_A − h² G (v_A − v_B), G = k [nnᵀ + s (I − nnᵀ)], slot B its negative.
        /// </summary>
        public static void ImplicitFrames(ReadOnlySpan<Spring> springs, ReadOnlySpan<float3> rest, ReadOnlySpan<float3> x,
            ReadOnlySpan<float3> v, float h, int start, int end, Span<float3> frames, Span<float3> slots)
        {
            for (int e = start; e < end; e++)
            {
                Spring s = springs[e];
                float3 n = Direction(s, x[s.A], x[s.B], rest[s.A], rest[s.B], out float length);
                float transverse = s.RestLength == 0f ? 1f : length > 0f ? math.max(0f, 1f - s.RestLength / length) : 0f;
                float axial = h * s.Damping + h * h * s.Stiffness;
                float side = h * h * s.Stiffness * transverse;
                frames[2 * e] = n;
                frames[2 * e + 1] = new float3(axial, side, 0f);
                float3 f = Force(s, x[s.A], x[s.B], v[s.A], v[s.B], rest[s.A], rest[s.B]);
                float3 dv = v[s.A] - v[s.B];
                float along = math.dot(n, dv);
                float3 gdv = s.Stiffness * (along * n + transverse * (dv - along * n));
                float3 b = h * f - h * h * gdv;
                slots[2 * e] = b;
                slots[2 * e + 1] = -b;
            }
        }

        /// <summary>Per slot, the diagonal of S (both corners): a n∘n + b (1 − n∘n), for the Jacobi preconditioner.</summary>
        public static void ImplicitDiagonal(ReadOnlySpan<float3> frames, int start, int end, Span<float3> slots)
        {
            for (int e = start; e < end; e++)
            {
                float3 n = frames[2 * e];
                float3 c = frames[2 * e + 1];
                float3 nn = n * n;
                float3 d = c.x * nn + c.y * (1f - nn);
                slots[2 * e] = d;
                slots[2 * e + 1] = d;
            }
        }

        /// <summary>Per slot, S (p_A − p_B) and its negative: the spring part of the product A p.</summary>
        public static void ImplicitProduct(ReadOnlySpan<Spring> springs, ReadOnlySpan<float3> frames, ReadOnlySpan<float3> p,
            int start, int end, Span<float3> slots)
        {
            for (int e = start; e < end; e++)
            {
                Spring s = springs[e];
                float3 n = frames[2 * e];
                float3 c = frames[2 * e + 1];
                float3 d = p[s.A] - p[s.B];
                float along = math.dot(n, d);
                float3 y = c.x * along * n + c.y * (d - along * n);
                slots[2 * e] = y;
                slots[2 * e + 1] = -y;
            }
        }

        /// <summary>
        /// XPBD (Macklin, Müller &amp; Chentanez 2016, eq. 18 with the damping of eq. 26) for the springs
        /// <paramref name="colorSprings"/>[start, end) of one colour (no two share a particle, so any split of the range
        /// gives the same bits): C = ‖p_A − p_B‖ − L₀, α̃ = 1/(k h²), γ = α̃ β̃ / h with β̃ = h² c (so γ = c/(k h)),
        /// Δλ = (−C − α̃ λ − γ ∇C·(p − x)) / ((1 + γ)(w_A + w_B) + α̃), p_A += w_A Δλ n, p_B −= w_B Δλ n, λ += Δλ.
        /// λ is <paramref name="multipliers"/>[2e].x.
        /// </summary>
        public static void ProjectColor(ReadOnlySpan<Spring> springs, ReadOnlySpan<int> colorSprings, ReadOnlySpan<float3> rest,
            ReadOnlySpan<float3> x, ReadOnlySpan<float> inverseMass, float h, int start, int end, Span<float3> p, Span<float3> multipliers)
        {
            float invH2 = 1f / (h * h);
            for (int k = start; k < end; k++)
            {
                int e = colorSprings[k];
                Spring s = springs[e];
                float wA = inverseMass[s.A], wB = inverseMass[s.B];
                if (!(s.Stiffness > 0f) || wA + wB == 0f)
                    continue;
                // Gradient of C with respect to p_A: n = (p_A − p_B)/‖p_A − p_B‖ (the rest direction when they coincide).
                float3 n = -Direction(s, p[s.A], p[s.B], rest[s.A], rest[s.B], out float length);
                float c = length - s.RestLength;
                float alphaTilde = invH2 / s.Stiffness;
                float gamma = s.Damping / (s.Stiffness * h);
                float lambda = multipliers[2 * e].x;
                float rate = math.dot(n, (p[s.A] - x[s.A]) - (p[s.B] - x[s.B]));
                float dLambda = (-c - alphaTilde * lambda - gamma * rate) / ((1f + gamma) * (wA + wB) + alphaTilde);
                p[s.A] += wA * dLambda * n;
                p[s.B] -= wB * dLambda * n;
                multipliers[2 * e] = new float3(lambda + dLambda, 0f, 0f);
            }
        }
    }
}
