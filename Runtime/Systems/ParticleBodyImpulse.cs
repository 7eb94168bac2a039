using SoftBodyDynamics.Solvers;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>How every simulation system applies a <see cref="SoftBodyImpulse"/>, whatever the body's method.</summary>
    static class ParticleBodyImpulse
    {
        /// <summary>
        /// Adds <paramref name="impulse"/> to every velocity: Δvᵢ = Δv + Δω × (xᵢ − c), with c the centre of mass in the
        /// positions' frame (<see cref="ParticleBodyStatus.LocalCenter"/>), and wakes the body.
        /// </summary>
        public static void Apply(ref ParticleBodyStatus status, DynamicBuffer<SoftBodyPosition> positions,
            DynamicBuffer<SoftBodyVelocity> velocities, in SoftBodyImpulse impulse)
        {
            var x = positions.Reinterpret<float3>().AsNativeArray();
            var v = velocities.Reinterpret<float3>().AsNativeArray();
            for (int i = 0; i < v.Length && i < x.Length; i++)
                v[i] += impulse.LinearVelocityChange + math.cross(impulse.AngularVelocityChange, x[i] - status.LocalCenter);
            ParticleBodyStep.Wake(ref status);
        }
    }
}
