using SoftBodyDynamics.Solvers;
using Unity.Burst;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;
using Unity.Rendering;
using UnityEngine;
using UnityEngine.Rendering;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Writes the deformed shape of every rendered soft body into its own mesh, once per frame. A Burst job
    /// per body computes mesh-space vertices, welded normals and bounds with <see cref="MeshDeformation"/> (shape
    /// matching: one particle per welded vertex) or <see cref="EmbeddedMeshDeformation"/> (mass-spring and FEM: render
    /// vertices embedded in tetrahedra, <see cref="SoftBodyEmbedding"/>) into <see cref="SoftBodyMeshVertex"/> and <c>RenderBounds</c> (bodies that have not stepped since
    /// the last write, e.g. sleeping ones, are skipped); then, on the main thread, each changed mesh gets
    /// its position/normal stream through <c>Mesh.SetVertexBufferData</c> and its bounds. Runs before
    /// Entities Graphics updates world bounds and draws.
    /// </summary>
    [UpdateInGroup(typeof(PresentationSystemGroup))]
    [UpdateAfter(typeof(StructuralChangePresentationSystemGroup))]
    [UpdateBefore(typeof(UpdatePresentationSystemGroup))]
    public partial struct SoftBodyMeshWriteSystem : ISystem
    {
        /// <summary>Indices never change and the bounds come from the deformation, so neither is recomputed.</summary>
        const MeshUpdateFlags k_UploadFlags = MeshUpdateFlags.DontValidateIndices | MeshUpdateFlags.DontRecalculateBounds;

        EntityQuery m_Instances;

        public void OnCreate(ref SystemState state)
        {
            m_Instances = SystemAPI.QueryBuilder().WithAll<SoftBodyMeshInstance, SoftBodyMeshVertex, RenderBounds>().Build();
            state.RequireForUpdate(m_Instances);
        }

        public void OnUpdate(ref SystemState state)
        {
            new DeformJob().ScheduleParallel();
            new EmbeddedDeformJob().ScheduleParallel();
            state.CompleteDependency();

            EntityManager entityManager = state.EntityManager;
            NativeArray<Entity> entities = m_Instances.ToEntityArray(Allocator.Temp);
            foreach (Entity entity in entities)
            {
                SoftBodyMeshInstance instance = entityManager.GetComponentData<SoftBodyMeshInstance>(entity);
                if (!instance.PendingUpload)
                    continue;
                instance.PendingUpload = false;
                entityManager.SetComponentData(entity, instance);
                Mesh mesh = instance.Mesh.Value;
                if (mesh == null)
                    continue;
                NativeArray<SoftBodyMeshVertex> vertices = entityManager.GetBuffer<SoftBodyMeshVertex>(entity, true).AsNativeArray();
                mesh.SetVertexBufferData(vertices, 0, 0, vertices.Length, SoftBodyMeshInstancing.DeformedStream, k_UploadFlags);
                AABB bounds = entityManager.GetComponentData<RenderBounds>(entity).Value;
                mesh.bounds = new Bounds(ToVector3(bounds.Center), ToVector3(bounds.Size));
            }
            entities.Dispose();
        }

        static Vector3 ToVector3(float3 v) => new Vector3(v.x, v.y, v.z);

        [BurstCompile]
        [WithNone(typeof(SoftBodyUninitialized))]
        partial struct DeformJob : IJobEntity
        {
            void Execute(in ShapeMatchingShape shape, in ParticleBodyState body, in DynamicBuffer<SoftBodyPosition> positions,
                DynamicBuffer<SoftBodyMeshVertex> vertices, ref SoftBodyMeshInstance instance, ref RenderBounds renderBounds)
            {
                if (instance.Deformed && instance.DeformedStep == body.Status.StepCount)
                    return;
                ref ShapeMatchingShapeBlob blob = ref shape.Blob.Value;
                int n = blob.ParticleCount;
                if (positions.Length != n || vertices.Length != blob.VertexCount || vertices.Length == 0)
                    return;
                instance.Deformed = true;
                instance.DeformedStep = body.Status.StepCount;

                var scratch = new NativeArray<float3>(2 * n, Allocator.Temp, NativeArrayOptions.UninitializedMemory);
                System.Span<float3> s = scratch.AsSpan();
                AxisAlignedBox box = MeshDeformation.Deform(positions.Reinterpret<float3>().AsNativeArray().AsReadOnlySpan(),
                    blob.VertexToParticleSpan, blob.TrianglesSpan, body.Status.LocalCenter, body.Status.Rotation,
                    blob.BodyRest.RestCenter, s.Slice(0, n), s.Slice(n, n),
                    vertices.Reinterpret<DeformedVertex>().AsNativeArray().AsSpan());
                scratch.Dispose();

                // A body the NaN guard is about to reset keeps its last good mesh.
                if (!math.all(math.isfinite(box.Min)) || !math.all(math.isfinite(box.Max)))
                    return;
                renderBounds.Value = new AABB { Center = box.Center, Extents = 0.5f * box.Extent };
                instance.PendingUpload = true;
            }
        }

        /// <summary>The write-back of a tetrahedral body: render vertices from the nodes through the embedding.</summary>
        [BurstCompile]
        [WithNone(typeof(SoftBodyUninitialized))]
        partial struct EmbeddedDeformJob : IJobEntity
        {
            void Execute(in SoftBodyEmbedding embedding, in ParticleBodyState body, in DynamicBuffer<SoftBodyPosition> positions,
                DynamicBuffer<SoftBodyMeshVertex> vertices, ref SoftBodyMeshInstance instance, ref RenderBounds renderBounds)
            {
                if (instance.Deformed && instance.DeformedStep == body.Status.StepCount)
                    return;
                ref SoftBodyEmbeddingBlob blob = ref embedding.Blob.Value;
                if (vertices.Length != blob.VertexCount || vertices.Length == 0 || positions.Length != blob.NodeCount)
                    return;
                instance.Deformed = true;
                instance.DeformedStep = body.Status.StepCount;

                // Nodes into mesh space with the body's placement, Rᵀ(xᵢ − c) + x⁰_cm (as MeshDeformation places shape
                // matching), then the shared embedded deformation (positions and Nanson normals).
                int n = positions.Length;
                var local = new NativeArray<float3>(n, Allocator.Temp, NativeArrayOptions.UninitializedMemory);
                NativeArray<float3> x = positions.Reinterpret<float3>().AsNativeArray();
                quaternion inverse = math.conjugate(math.normalizesafe(body.Status.Rotation));
                for (int i = 0; i < n; i++)
                    local[i] = math.rotate(inverse, x[i] - body.Status.LocalCenter) + blob.RestCenter;
                AxisAlignedBox box = EmbeddedMeshDeformation.Deform(blob.VerticesSpan, blob.EdgeNodesSpan, blob.RestNodePositionsSpan,
                    blob.RestNormalsSpan, local.AsReadOnlySpan(), vertices.Reinterpret<DeformedVertex>().AsNativeArray().AsSpan(), 0,
                    blob.VertexCount);
                local.Dispose();

                if (!math.all(math.isfinite(box.Min)) || !math.all(math.isfinite(box.Max)))
                    return;
                renderBounds.Value = new AABB { Center = box.Center, Extents = 0.5f * box.Extent };
                instance.PendingUpload = true;
            }
        }
    }
}
