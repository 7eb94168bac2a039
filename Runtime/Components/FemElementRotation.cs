using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Rotation R of one integration point of a finite-element body (tier 3, runtime state): one per tetrahedron, four per
    /// quadratic one. The warm start of the next rotation extraction. Sized and reset by <see cref="FemSimulationSystem"/>.
    /// </summary>
    [InternalBufferCapacity(0)]
    public struct FemElementRotation : IBufferElementData
    {
        /// <summary>The point's rotation from its rest pose.</summary>
        public quaternion Value;
    }
}
