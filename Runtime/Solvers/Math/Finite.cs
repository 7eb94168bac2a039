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
