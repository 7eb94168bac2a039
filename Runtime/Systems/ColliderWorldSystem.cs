using Unity.Burst;
using Unity.Collections;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Builds the step's collider world first in <see cref="ParticleSimulationSystemGroup"/>: every
    /// <see cref="ParticleCollider"/>, in query order, copied into the <see cref="ColliderWorldShape"/> buffer of a
    /// singleton entity it creates. Taking the buffer for writing completes the jobs of the previous step that still read
    /// it. A world whose colliders are all gone gets an empty buffer once, then the system does nothing. It updates only
    /// while something reads the collider world: a particle body of any method or a fluid.
    /// </summary>
    [UpdateInGroup(typeof(ParticleSimulationSystemGroup), OrderFirst = true)]
    [BurstCompile]
    public partial struct ColliderWorldSystem : ISystem
    {
        EntityQuery m_Colliders;

        [BurstCompile]
        public void OnCreate(ref SystemState state)
        {
            m_Colliders = SystemAPI.QueryBuilder().WithAll<ParticleCollider>().Build();
            ColliderWorldReaders.Require(ref state);
            Entity world = state.EntityManager.CreateEntity();
            state.EntityManager.AddBuffer<ColliderWorldShape>(world);
        }

        [BurstCompile]
        public void OnUpdate(ref SystemState state)
        {
            if (m_Colliders.IsEmpty && SystemAPI.GetSingletonBuffer<ColliderWorldShape>(true).Length == 0)
                return;
            NativeArray<ParticleCollider> colliders = m_Colliders.ToComponentDataArray<ParticleCollider>(Allocator.Temp);
            DynamicBuffer<ColliderWorldShape> shapes = SystemAPI.GetSingletonBuffer<ColliderWorldShape>();
            shapes.ResizeUninitialized(colliders.Length);
            for (int i = 0; i < colliders.Length; i++)
                shapes[i] = new ColliderWorldShape { Shape = colliders[i].Shape };
            colliders.Dispose();
        }
    }
}
