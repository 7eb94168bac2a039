using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Rotation R of one tetrahedron of a finite-element body (tier 3, runtime state), one element per tetrahedron: the
    /// warm start of the co-rotational model's next rotation extraction. Sized and reset by <see cref="FemSimulationSystem"/>.
    /// </summary>
    [InternalBufferCapacity(0)]
    public struct FemElementRotation : IBufferElementData
    {
        /// <summary>The element's rotation from its rest pose.</summary>
        public quaternion Value;
    }
}
