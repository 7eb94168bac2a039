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
    }
}
