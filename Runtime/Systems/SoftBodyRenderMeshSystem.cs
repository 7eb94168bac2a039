using Unity.Collections;
using Unity.Entities;
using Unity.Rendering;
using UnityEngine;
using UnityEngine.Rendering;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Owns the per-body render meshes. A rendered soft body (<see cref="SoftBodyRenderMesh"/> with a
    /// <see cref="ShapeMatchingShape"/> or a <see cref="SoftBodyEmbedding"/>, plus Entities
    /// Graphics' <c>MaterialMeshInfo</c> and <c>RenderBounds</c>) gets its own deformable copy of the mesh
    /// (<see cref="SoftBodyMeshInstancing"/>), registered with <c>EntitiesGraphicsSystem.RegisterMesh</c> and
    /// set as the entity's runtime mesh; <see cref="SoftBodyMeshInstance"/> and a
    /// <see cref="SoftBodyMeshVertex"/> buffer are added. When the body is destroyed the mesh is unregistered
    /// and destroyed. Main thread (managed meshes); structural changes only when bodies appear or disappear.
    /// <para>
    /// Without a renderer it does nothing: when the world has no <c>EntitiesGraphicsSystem</c> (server or custom
    /// worlds) or has one that cannot take meshes (no render pipeline asset, no compute support, <c>-nographics</c>,
    /// <c>HYBRID_RENDERER_DISABLED</c>: Entities Graphics then disables itself in <c>OnCreate</c> and never creates
    /// its BatchRendererGroup), bodies keep simulating, are drawn by nothing, and one warning per world says why.
    /// </para>
    /// </summary>
    [UpdateInGroup(typeof(StructuralChangePresentationSystemGroup))]
    public partial struct SoftBodyRenderMeshSystem : ISystem
    {
        EntityQuery m_NeedInstance;
        EntityQuery m_NeedEmbeddedInstance;
        EntityQuery m_Orphaned;
        EntityQuery m_AllInstances;
        bool m_WarnedNoRenderer;

        public void OnCreate(ref SystemState state)
        {
            m_NeedInstance = SystemAPI.QueryBuilder()
                .WithAll<SoftBodyRenderMesh, ShapeMatchingShape>()
                .WithPresent<MaterialMeshInfo>()
                .WithAll<RenderBounds>()
                .WithNone<SoftBodyMeshInstance>()
                .Build();
            m_NeedEmbeddedInstance = SystemAPI.QueryBuilder()
                .WithAll<SoftBodyRenderMesh, SoftBodyEmbedding>()
                .WithPresent<MaterialMeshInfo>()
                .WithAll<RenderBounds>()
                .WithNone<SoftBodyMeshInstance>()
                .Build();
            m_Orphaned = SystemAPI.QueryBuilder().WithAll<SoftBodyMeshInstance>().WithNone<SoftBodyRenderMesh>().Build();
            m_AllInstances = SystemAPI.QueryBuilder().WithAll<SoftBodyMeshInstance>().Build();
            state.RequireAnyForUpdate(m_NeedInstance, m_NeedEmbeddedInstance, m_Orphaned);
        }

        public void OnUpdate(ref SystemState state)
        {
            EntityManager entityManager = state.EntityManager;
            var graphics = state.World.GetExistingSystemManaged<EntitiesGraphicsSystem>();
            ReleaseOrphans(entityManager, graphics);
            if (CanRegisterMeshes(graphics))
            {
                CreateInstances(entityManager, graphics, m_NeedInstance);
                CreateInstances(entityManager, graphics, m_NeedEmbeddedInstance);
            }
            else if (!m_WarnedNoRenderer && (!m_NeedInstance.IsEmpty || !m_NeedEmbeddedInstance.IsEmpty))
            {
                m_WarnedNoRenderer = true;
                Debug.LogWarning($"Soft bodies in world '{state.World.Name}' are simulated but not drawn: Entities Graphics " +
                    "has no renderer here (no render pipeline asset, no compute shader support, -nographics or a server " +
                    "build, or no enabled EntitiesGraphicsSystem in this world). This warning is shown once per world.");
            }
        }

        /// <summary>
        /// Whether <paramref name="graphics"/> can register meshes: the system exists, Entities Graphics is supported
        /// (<c>EntitiesGraphicsSystem.EntitiesGraphicsEnabled</c>) and the system is enabled. A system created while
        /// Entities Graphics was unsupported disables itself and has no BatchRendererGroup, so its
        /// <c>RegisterMesh</c> would throw.
        /// </summary>
        internal static bool CanRegisterMeshes(EntitiesGraphicsSystem graphics) =>
            graphics != null && graphics.Enabled && EntitiesGraphicsSystem.EntitiesGraphicsEnabled;

        public void OnDestroy(ref SystemState state)
        {
            // The world is going away: free the meshes (their registrations go with Entities Graphics).
            NativeArray<SoftBodyMeshInstance> instances = m_AllInstances.ToComponentDataArray<SoftBodyMeshInstance>(Allocator.Temp);
            foreach (SoftBodyMeshInstance instance in instances)
                SoftBodyMeshInstancing.Destroy(instance.Mesh.Value);
            instances.Dispose();
        }

        void ReleaseOrphans(EntityManager entityManager, EntitiesGraphicsSystem graphics)
        {
            if (m_Orphaned.IsEmpty)
                return;
            NativeArray<Entity> orphans = m_Orphaned.ToEntityArray(Allocator.Temp);
            foreach (Entity entity in orphans)
            {
                SoftBodyMeshInstance instance = entityManager.GetComponentData<SoftBodyMeshInstance>(entity);
                // A registered id means the system had its BatchRendererGroup; it keeps it until it is destroyed.
                if (graphics != null && !instance.MeshId.Equals(BatchMeshID.Null))
                    graphics.UnregisterMesh(instance.MeshId);
                SoftBodyMeshInstancing.Destroy(instance.Mesh.Value);
                entityManager.RemoveComponent<SoftBodyMeshInstance>(entity);
                if (entityManager.Exists(entity) && entityManager.HasBuffer<SoftBodyMeshVertex>(entity))
                    entityManager.RemoveComponent<SoftBodyMeshVertex>(entity);
            }
            orphans.Dispose();
        }

        /// <summary>Render vertices a body binds: from its shape-matching blob, or its embedding (mass-spring, FEM).</summary>
        static int BoundVertexCount(EntityManager entityManager, Entity entity) =>
            entityManager.HasComponent<ShapeMatchingShape>(entity)
                ? entityManager.GetComponentData<ShapeMatchingShape>(entity).Blob.Value.VertexCount
                : entityManager.GetComponentData<SoftBodyEmbedding>(entity).Blob.Value.VertexCount;

        void CreateInstances(EntityManager entityManager, EntitiesGraphicsSystem graphics, EntityQuery needInstance)
        {
            if (needInstance.IsEmpty)
                return;
            NativeArray<Entity> entities = needInstance.ToEntityArray(Allocator.Temp);
            foreach (Entity entity in entities)
            {
                Mesh source = entityManager.GetComponentData<SoftBodyRenderMesh>(entity).Mesh.Value;
                int vertexCount = BoundVertexCount(entityManager, entity);
                MaterialMeshInfo materialMesh = entityManager.GetComponentData<MaterialMeshInfo>(entity);
                var instance = new SoftBodyMeshInstance { MeshId = BatchMeshID.Null };

                Mesh copy = null;
                string error;
                if (materialMesh.HasMaterialMeshIndexRange)
                    error = "it is rendered with several materials; soft-body meshes support one material";
                else
                    copy = SoftBodyMeshInstancing.CreateDeformableCopy(source, vertexCount, out error);
                if (copy != null)
                {
                    instance.Mesh = copy;
                    instance.MeshId = graphics.RegisterMesh(copy);
                    materialMesh.MeshID = instance.MeshId;
                    entityManager.SetComponentData(entity, materialMesh);
                }
                else
                {
                    Debug.LogError($"Soft body Entity({entity.Index}:{entity.Version}) is drawn undeformed: {error}.");
                }

                // Added even on failure, so the body is not retried (and the error not repeated) every frame.
                entityManager.AddComponentData(entity, instance);
                DynamicBuffer<SoftBodyMeshVertex> vertices = entityManager.HasBuffer<SoftBodyMeshVertex>(entity)
                    ? entityManager.GetBuffer<SoftBodyMeshVertex>(entity)
                    : entityManager.AddBuffer<SoftBodyMeshVertex>(entity);
                vertices.ResizeUninitialized(copy != null ? vertexCount : 0);
            }
            entities.Dispose();
        }
    }
}
