using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Per-instance copy of the quadratic-mode Ã_qq⁻¹ blocks (9 per cluster), which plastic flow
    /// rewrites. Present only on bodies that run the quadratic mode with plasticity; the others read the
    /// shared blob. See <see cref="SoftBodyArchetype.NeedsQuadraticInverse"/>.
    /// </summary>
    [InternalBufferCapacity(0)]
    public struct ShapeMatchingQuadraticInverse : IBufferElementData
    {
        /// <summary>One 3×3 block of the scaled 9×9 inverse.</summary>
        public float3x3 Value;
    }
}
