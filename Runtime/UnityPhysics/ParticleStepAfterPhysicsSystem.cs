using Unity.Burst;
using Unity.Entities;
using Unity.Physics.Systems;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Puts the package's fixed step after Unity Physics' in <see cref="FixedStepSimulationSystemGroup"/>: ordered after
    /// <see cref="PhysicsSystemGroup"/> and before <see cref="ParticleSimulationSystemGroup"/>, it chains the two groups
    /// (a group's systems are sorted on every such constraint), so <see cref="UnityPhysicsColliderSystem"/> reads the
    /// rigid bodies at the pose of this step. It never updates (disabled at creation); it only orders.
    /// </summary>
    [UpdateInGroup(typeof(FixedStepSimulationSystemGroup))]
    [UpdateAfter(typeof(PhysicsSystemGroup))]
    [UpdateBefore(typeof(ParticleSimulationSystemGroup))]
    public partial struct ParticleStepAfterPhysicsSystem : ISystem
    {
        [BurstCompile]
        public void OnCreate(ref SystemState state) => state.Enabled = false;
    }
}
