using System.Runtime.CompilerServices;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Small 3×3 helpers the solvers share.</summary>
    public static class Matrix3
    {
        /// <summary>Outer product a bᵀ (column j is a·b_j).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static float3x3 Outer(float3 a, float3 b) => new float3x3(a * b.x, a * b.y, a * b.z);

        /// <summary>Σ aᵢⱼ bᵢⱼ = tr(a bᵀ), the Frobenius inner product.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static float Dot(in float3x3 a, in float3x3 b) => math.dot(a.c0, b.c0) + math.dot(a.c1, b.c1) + math.dot(a.c2, b.c2);

        /// <summary>Largest absolute entry: the scale used to normalise a matrix before float32-sensitive work.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static float MaxAbs(in float3x3 m) =>
            math.max(math.cmax(math.abs(m.c0)), math.max(math.cmax(math.abs(m.c1)), math.cmax(math.abs(m.c2))));
    }
}
