using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>Particle position xᵢ of a soft body (m, world), one element per particle (tier 3, runtime state).</summary>
    [InternalBufferCapacity(0)]
    public struct SoftBodyPosition : IBufferElementData
    {
        /// <summary>Position (m, world).</summary>
        public float3 Value;
    }
}
