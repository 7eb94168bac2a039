using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Particle velocity vᵢ of a soft body (m/s, world), one element per particle. Writing a non-zero
    /// velocity wakes a sleeping body on its next step; <see cref="SoftBodyImpulse"/> does it for the whole body.
    /// </summary>
    [InternalBufferCapacity(0)]
    public struct SoftBodyVelocity : IBufferElementData
    {
        /// <summary>Velocity (m/s, world).</summary>
        public float3 Value;
    }
}
