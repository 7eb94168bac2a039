using Unity.Entities;

namespace Unity.Physics.Systems
{
    // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.Systems.PhysicsSystemGroup.html
    // (source: ECS/Base/Systems/PhysicsSystemGroups.cs, 1.4.6: [UpdateInGroup(typeof(FixedStepSimulationSystemGroup))]
    // public partial class PhysicsSystemGroup : ComponentSystemGroup; its members are left out)
    [UpdateInGroup(typeof(FixedStepSimulationSystemGroup))]
    public partial class PhysicsSystemGroup : ComponentSystemGroup
    {
    }
}
