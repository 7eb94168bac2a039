using SoftBodyDynamics.Solvers;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>What the mass-spring and FEM systems share around the solver call: impulses and the NaN-guard log.</summary>
    static class ParticleBodyImpulse
    {
        /// <summary>
        /// Adds <paramref name="impulse"/> to every velocity (linear part, and ω × (xᵢ − c) about the centre of mass) and
        /// wakes the body, as <see cref="SoftBodySimulationSystem"/> does for shape matching.
        /// </summary>
        public static void Apply(ref ParticleBodyState body, DynamicBuffer<SoftBodyPosition> positions,
            DynamicBuffer<SoftBodyVelocity> velocities, in SoftBodyImpulse impulse)
        {
            var x = positions.Reinterpret<float3>().AsNativeArray();
            var v = velocities.Reinterpret<float3>().AsNativeArray();
            for (int i = 0; i < v.Length && i < x.Length; i++)
                v[i] += impulse.LinearVelocityChange + math.cross(impulse.AngularVelocityChange, x[i] - body.Status.LocalCenter);
            ParticleBodyStep.Wake(ref body.Status);
        }
    }
}
