using SoftBodyDynamics.Solvers;
using Unity.Burst;
using Unity.Collections;
using Unity.Entities;
using Unity.Physics;
using Unity.Transforms;
using UnityEngine;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Adds Unity Physics' primitive colliders to the step's collider world, right after <see cref="ColliderWorldSystem"/>
    /// built it (compiled only when com.unity.physics is installed). Every entity with a <see cref="PhysicsCollider"/>
    /// of type sphere, box or capsule becomes a <see cref="ColliderWorldShape"/> at its current pose
    /// (<see cref="LocalToWorld"/>, and <see cref="LocalTransform.Scale"/> when it has one, as Unity Physics reads them),
    /// so particle bodies and fluids collide with static, kinematic and dynamic bodies alike; the rigid bodies feel nothing
    /// back. Other collider types (convex hulls, cylinders, meshes, compounds, terrains, quads, triangles) are left out, and
    /// a warning says how many, once. Updates only while a particle body or a fluid reads the collider world.
    /// </summary>
    [UpdateInGroup(typeof(ParticleSimulationSystemGroup), OrderFirst = true)]
    [UpdateAfter(typeof(ColliderWorldSystem))]
    [BurstCompile]
    public partial struct UnityPhysicsColliderSystem : ISystem
    {
        EntityQuery m_Bodies;
        bool m_Warned;

        [BurstCompile]
        public void OnCreate(ref SystemState state)
        {
            m_Bodies = SystemAPI.QueryBuilder().WithAll<PhysicsCollider, LocalToWorld>().Build();
            ColliderWorldReaders.Require(ref state);
            state.RequireForUpdate<ColliderWorldShape>();
        }

        [BurstCompile]
        public unsafe void OnUpdate(ref SystemState state)
        {
            if (m_Bodies.IsEmpty)
                return;
            NativeArray<Entity> entities = m_Bodies.ToEntityArray(Allocator.Temp);
            NativeArray<PhysicsCollider> colliders = m_Bodies.ToComponentDataArray<PhysicsCollider>(Allocator.Temp);
            NativeArray<LocalToWorld> poses = m_Bodies.ToComponentDataArray<LocalToWorld>(Allocator.Temp);
            DynamicBuffer<ColliderWorldShape> shapes = SystemAPI.GetSingletonBuffer<ColliderWorldShape>();
            int skipped = 0;
            for (int i = 0; i < colliders.Length; i++)
            {
                if (!colliders[i].IsValid)
                    continue;
                Unity.Physics.Collider* collider = colliders[i].ColliderPtr;
                if (!TryLocalShape(collider, out ColliderShape local))
                {
                    skipped++;
                    continue;
                }
                float scale = state.EntityManager.HasComponent<LocalTransform>(entities[i])
                    ? state.EntityManager.GetComponentData<LocalTransform>(entities[i]).Scale
                    : 1f;
                shapes.Add(new ColliderWorldShape { Shape = local.Transformed(poses[i].Position, poses[i].Rotation, scale) });
            }
            if (skipped > 0 && !m_Warned)
            {
                m_Warned = true;
                Debug.LogWarning($"Soft Body Dynamics: {skipped} Unity Physics colliders are not spheres, boxes or capsules; particle bodies and fluids do not collide with them.");
            }
            entities.Dispose();
            colliders.Dispose();
            poses.Dispose();
        }

        /// <summary>The collider in its body's space, for the primitive types the particles collide with.</summary>
        static unsafe bool TryLocalShape(Unity.Physics.Collider* collider, out ColliderShape shape)
        {
            switch (collider->Type)
            {
                case ColliderType.Sphere:
                {
                    SphereGeometry g = ((Unity.Physics.SphereCollider*)collider)->Geometry;
                    shape = ColliderShape.Sphere(g.Center, g.Radius);
                    return true;
                }
                case ColliderType.Box:
                {
                    // The size includes the bevel: the rounded edges are treated as sharp.
                    BoxGeometry g = ((Unity.Physics.BoxCollider*)collider)->Geometry;
                    shape = ColliderShape.Box(g.Center, g.Orientation, 0.5f * g.Size);
                    return true;
                }
                case ColliderType.Capsule:
                {
                    CapsuleGeometry g = ((Unity.Physics.CapsuleCollider*)collider)->Geometry;
                    shape = ColliderShape.Capsule(g.Vertex0, g.Vertex1, g.Radius);
                    return true;
                }
                default:
                    shape = default;
                    return false;
            }
        }
    }
}
