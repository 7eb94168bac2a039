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
        /// <param name="k">Fraction of the non-rigid velocity removed, in [0, 1].</param>
        public static void Apply(ReadOnlySpan<float3> x, Span<float3> v, ReadOnlySpan<float> mass, float k)
        {
            float m = 0f;
            float3 xSum = float3.zero, vSum = float3.zero;
            for (int i = 0; i < x.Length; i++)
            {
                m += mass[i];
                xSum += mass[i] * x[i];
                vSum += mass[i] * v[i];
            }
            if (!(m > 0f))
                return;
            float3 xcm = xSum / m, vcm = vSum / m;
            float3 l = float3.zero;
            float3x3 inertia = float3x3.zero;
            for (int i = 0; i < x.Length; i++)
            {
                float3 r = x[i] - xcm;
                l += mass[i] * math.cross(r, v[i] - vcm);
                inertia += mass[i] * (math.lengthsq(r) * float3x3.identity - Matrix3.Outer(r, r));
            }
            // A rod or a point has a singular inertia tensor: regularise so ω stays finite.
            float trace = inertia.c0.x + inertia.c1.y + inertia.c2.z;
            float3 omega = float3.zero;
            if (trace > 0f)
                omega = math.mul(math.inverse(inertia + (1e-6f * trace) * float3x3.identity), l);
            if (!math.all(math.isfinite(omega)))
                omega = float3.zero;
            for (int i = 0; i < x.Length; i++)
                v[i] += k * (vcm + math.cross(omega, x[i] - xcm) - v[i]);
        }
    }
}
