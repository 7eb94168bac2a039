using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Volume normalisation of the linear shape-matching transform (Müller et al. 2005, §4.3):
    /// A ← A / ∛det(A), so that det A = 1 and the linear mode neither grows nor shrinks the body.
    /// The cube root is taken only of a positive determinant: ∛ of det ≤ 0 is either undefined
    /// (math.pow with a negative base is NaN, on the CPU and in HLSL) or a division by zero. Those
    /// cases — flat, collapsed or inverted clusters — fall back to the rigid rotation R.
    /// </summary>
    public static class VolumePreservation
    {
        /// <summary>
        /// Smallest accepted det(A) relative to the cube of A's largest entry. Below it the linear
        /// transform is treated as degenerate. 1e-6 means a cluster squashed to one hundredth of
        /// its size along one axis still uses the linear mode.
        /// </summary>
        public const float DefaultRelativeDeterminantFloor = 1e-6f;

        /// <summary>
        /// Returns A / ∛det(A) when det(A) is finite and above the floor; otherwise returns false and
        /// leaves <paramref name="normalized"/> at identity.
        /// </summary>
        public static bool TryNormalize(in float3x3 a, out float3x3 normalized,
            float relativeDeterminantFloor = DefaultRelativeDeterminantFloor)
        {
            normalized = float3x3.identity;
            if (!Finite.All(a))
                return false;
            float scale = Matrix3.MaxAbs(a);
            if (!(scale > 0f))
                return false;
            // Normalise first so det cannot under- or overflow in float32.
            float3x3 an = a * (1f / scale);
            float det = math.determinant(an);
            if (!(det > relativeDeterminantFloor)) // also rejects NaN
                return false;
            normalized = an * (1f / math.pow(det, 1f / 3f));
            return true;
        }

        /// <summary>
        /// Goal transform of the linear mode: β·Ã + (1 − β)·R with Ã the volume-normalised linear
        /// transform (Müller et al. 2005, eq. 8 and §4.3). Falls back to R when Ã is degenerate.
        /// </summary>
        /// <param name="aLinear">A = A_pq · A_qq⁻¹.</param>
        /// <param name="rotation">The rotational part of A_pq.</param>
        /// <param name="beta">Blend toward the linear transform, 0 (rigid) to 1 (fully linear).</param>
        /// <param name="rigidFallback">True when the linear part was degenerate and R was used.</param>
        public static float3x3 LinearGoalTransform(in float3x3 aLinear, in float3x3 rotation, float beta,
            out bool rigidFallback)
        {
            if (!TryNormalize(aLinear, out float3x3 normalized))
            {
                rigidFallback = true;
                return rotation;
            }
            rigidFallback = false;
            float b = math.saturate(beta);
            return b * normalized + (1f - b) * rotation;
        }
    }
}
