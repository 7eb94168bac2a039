using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Damping that leaves rigid motion alone (Müller et al. 2007, "Position Based Dynamics", §3.5):
    /// with v_cm, ω = I⁻¹L of the body, vᵢ += k (v_cm + ω × rᵢ − vᵢ). Σ mᵢ Δvᵢ = 0 and
    /// Σ mᵢ rᵢ × Δvᵢ = 0, so linear and angular momentum are unchanged; only wobble decays.
    /// </summary>
    public static class RigidMotionDamping
    {
        /// <summary>
        /// I⁻¹ about <paramref name="xcm"/>. A rod or a point has a singular inertia tensor: when det I is below
        /// 10⁻⁶ (tr I / 3)³, I + 10⁻⁶ tr I · 1 is inverted instead, which keeps ω finite. The shift is not applied to
        /// a well-conditioned body, where it would bias ω by 10⁻⁶ relative at every call and, with strong damping,
        /// drain angular momentum. Zero for a body of zero extent.
        /// </summary>
        public static float3x3 InverseInertia(ReadOnlySpan<float3> x, ReadOnlySpan<float> mass, float3 xcm)
        {
            float3x3 inertia = float3x3.zero;
            for (int i = 0; i < x.Length; i++)
            {
                float3 r = x[i] - xcm;
                inertia += mass[i] * (math.lengthsq(r) * float3x3.identity - Matrix3.Outer(r, r));
            }
            float trace = inertia.c0.x + inertia.c1.y + inertia.c2.z;
            if (!(trace > 0f))
                return float3x3.zero;
            float third = trace / 3f;
            if (math.determinant(inertia) > 1e-6f * third * third * third)
                return math.inverse(inertia);
            return math.inverse(inertia + (1e-6f * trace) * float3x3.identity);
        }

        /// <param name="k">Fraction of the non-rigid velocity removed, in [0, 1].</param>
        /// <param name="scratch">One float3 per particle.</param>
        public static void Apply(ReadOnlySpan<float3> x, Span<float3> v, ReadOnlySpan<float> mass, float k, Span<float3> scratch) =>
            Apply(x, v, mass, k, scratch, RigidFrame.Of(x, mass));

        /// <summary>As above, with the positions' <see cref="RigidFrame"/> already computed.</summary>
        public static void Apply(ReadOnlySpan<float3> x, Span<float3> v, ReadOnlySpan<float> mass, float k, Span<float3> scratch,
            in RigidFrame frame)
        {
            float m = frame.Mass;
            if (!(m > 0f))
                return;
            float3 vSum = float3.zero;
            for (int i = 0; i < x.Length; i++)
                vSum += mass[i] * v[i];
            float3 xcm = frame.Center, vcm = vSum / m;
            float3 l = float3.zero;
            for (int i = 0; i < x.Length; i++)
                l += mass[i] * math.cross(x[i] - xcm, v[i] - vcm);
            float3 omega = math.mul(frame.InverseInertia, l);
            if (!math.all(math.isfinite(omega)))
                omega = float3.zero;
            // Σ mᵢ Δvᵢ is zero in exact arithmetic; its float32 residual is removed so damping never
            // pushes the body.
            float3 residual = float3.zero;
            for (int i = 0; i < x.Length; i++)
            {
                scratch[i] = k * (vcm + math.cross(omega, x[i] - xcm) - v[i]);
                residual += mass[i] * scratch[i];
            }
            residual /= m;
            for (int i = 0; i < x.Length; i++)
                v[i] += scratch[i] - residual;
        }
    }
}
