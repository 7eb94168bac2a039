using System.Runtime.CompilerServices;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>All-components finiteness tests (Unity.Mathematics has no <c>math.isfinite</c> for matrices).</summary>
    public static class Finite
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool All(float4 v) => math.all(math.isfinite(v));

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool All(in float3x3 m) =>
            math.all(math.isfinite(m.c0)) && math.all(math.isfinite(m.c1)) && math.all(math.isfinite(m.c2));

        /// <summary>A setting sanitized to ≥ 0: <paramref name="v"/> when finite, clamped at 0; 0 when NaN or infinite.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static float NonNegative(float v) => math.isfinite(v) ? math.max(0f, v) : 0f;

        /// <summary>A setting sanitized to &gt; 0: <paramref name="v"/> when finite and positive, <paramref name="fallback"/> otherwise.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static float Positive(float v, float fallback) => v > 0f && math.isfinite(v) ? v : fallback;

        /// <summary>True when every matrix of <paramref name="m"/> is finite (true for an empty span).</summary>
        public static bool All(System.ReadOnlySpan<float3x3> m)
        {
            for (int i = 0; i < m.Length; i++)
                if (!All(m[i]))
                    return false;
            return true;
        }
    }
}
