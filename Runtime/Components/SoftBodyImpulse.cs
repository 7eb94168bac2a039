using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// A one-shot velocity change for a whole soft body. Set the value and enable the component: the
    /// next simulation step adds it to every particle, wakes the body and disables the component
    /// again. Add it disabled at creation so that applying it needs no structural change.
    /// </summary>
    public struct SoftBodyImpulse : IComponentData, IEnableableComponent
    {
        /// <summary>Velocity added to every particle (m/s, world).</summary>
        public float3 LinearVelocityChange;
        /// <summary>Angular velocity ω added about the centre of mass: particle i gains ω × (xᵢ − c) (rad/s, world).</summary>
        public float3 AngularVelocityChange;
    }
}
