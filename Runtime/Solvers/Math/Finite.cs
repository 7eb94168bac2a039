using System.Runtime.CompilerServices;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Finiteness tests for the types Unity.Mathematics has no <c>math.isfinite</c> overload for.</summary>
    public static class Finite
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool All(in float3x3 m) =>
            math.all(math.isfinite(m.c0)) && math.all(math.isfinite(m.c1)) && math.all(math.isfinite(m.c2));
    }
}
