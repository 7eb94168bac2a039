#if SBD_PERFORMANCE_TESTING
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;
using Unity.PerformanceTesting;
using Unity.Rendering;
using Unity.Transforms;
using UnityEngine;
using UnityEngine.Rendering;

namespace SoftBodyDynamics.Benchmarks
{
    /// <summary>
    /// Cost of the per-body mesh write-back at 1, 100 and 1000 bodies of the benchmark sphere
    /// (<see cref="MeshWriteBackBody"/>: 425 render vertices, 389 particles), in three parts:
    /// <list type="bullet">
    /// <item><b>frame</b>: one update of <see cref="SoftBodyMeshWriteSystem"/> with every body changed since the last
    /// write: the Burst deform job over all bodies, then on the main thread one <c>Mesh.SetVertexBufferData</c> of
    /// 24 bytes per vertex and one bounds write per body. Runs anywhere; under <c>-nographics</c> (the CI workflow)
    /// there is no graphics device, so the GPU side of the upload is not included.</item>
    /// <item><b>mesh copies</b>: <see cref="SoftBodyMeshInstancing.CreateDeformableCopy"/> per body, paid once when
    /// bodies appear.</item>
    /// <item><b>registration</b>: <see cref="SoftBodyRenderMeshSystem"/> giving every new body its mesh copy and
    /// registering it with <c>EntitiesGraphicsSystem.RegisterMesh</c>. Needs a renderer (category GPU); skipped
    /// (inconclusive) where Entities Graphics is disabled.</item>
    /// </list>
    /// See Documentation~/mesh-write-back.md for the headless figures of the CPU part and the scalable path.
    /// </summary>
    public class MeshWriteBackPerformanceTests
    {
        World m_World;
        Mesh m_Source;
        int m_VertexCount;
        BlobAssetReference<ShapeMatchingShapeBlob> m_Shape;
        readonly List<Mesh> m_Copies = new List<Mesh>();
        readonly List<Entity> m_Bodies = new List<Entity>();

        [SetUp]
        public void SetUp()
        {
            m_World = new World("Mesh write-back benchmark");
            SoftBodyBuildResult build = MeshWriteBackBody.Build(out float3[] vertices, out float3[] normals, out int[] triangles);
            m_VertexCount = vertices.Length;
            m_Source = new Mesh { name = "Write-back sphere" };
            m_Source.vertices = ToVector3(vertices);
            m_Source.normals = ToVector3(normals);
            m_Source.triangles = triangles;
            m_Shape = ShapeMatchingShapeBlobFactory.Create(build.Model, build.VertexToParticle, triangles, Allocator.Persistent);
        }

        [TearDown]
        public void TearDown()
        {
            m_World.EntityManager.CompleteAllTrackedJobs();
            m_World.Dispose();
            DestroyCopies();
            Object.DestroyImmediate(m_Source);
            if (m_Shape.IsCreated)
                m_Shape.Dispose();
            m_Bodies.Clear();
        }

        [Test, Performance]
        public void MeshWriteBack_Frame([ValueSource(typeof(MeshWriteBackBody), nameof(MeshWriteBackBody.BodyCounts))] int bodies)
        {
            EntityManager manager = m_World.EntityManager;
            SystemHandle initialization = m_World.CreateSystem<ShapeMatchingInitializationSystem>();
            SystemHandle write = m_World.CreateSystem<SoftBodyMeshWriteSystem>();
            for (int b = 0; b < bodies; b++)
            {
                Entity body = CreateBody(b);
                Mesh copy = SoftBodyMeshInstancing.CreateDeformableCopy(m_Source, m_VertexCount, out string error);
                Assert.That(copy != null, Is.True, error);
                m_Copies.Add(copy);
                manager.AddComponentData(body, new SoftBodyMeshInstance { Mesh = copy, MeshId = BatchMeshID.Null });
                manager.AddBuffer<SoftBodyMeshVertex>(body).ResizeUninitialized(m_VertexCount);
            }
            initialization.Update(m_World.Unmanaged);
            manager.CompleteAllTrackedJobs();

            Measure.Method(() => write.Update(m_World.Unmanaged))
                .SetUp(MarkAllStepped)
                .WarmupCount(3)
                .MeasurementCount(15)
                .IterationsPerMeasurement(1)
                .SampleGroup(new SampleGroup($"MeshWriteBack frame x{bodies} bodies", SampleUnit.Millisecond))
                .Run();

            foreach (Entity body in m_Bodies)
            {
                SoftBodyMeshInstance instance = manager.GetComponentData<SoftBodyMeshInstance>(body);
                Assert.That(instance.Deformed && !instance.PendingUpload, Is.True, "every body deformed and uploaded");
            }
        }

        [Test, Performance]
        public void MeshWriteBack_MeshCopies([ValueSource(typeof(MeshWriteBackBody), nameof(MeshWriteBackBody.BodyCounts))] int bodies)
        {
            Measure.Method(() =>
                {
                    for (int b = 0; b < bodies; b++)
                        m_Copies.Add(SoftBodyMeshInstancing.CreateDeformableCopy(m_Source, m_VertexCount, out _));
                })
                .CleanUp(DestroyCopies)
                .WarmupCount(1)
                .MeasurementCount(5)
                .IterationsPerMeasurement(1)
                .SampleGroup(new SampleGroup($"MeshWriteBack mesh copies x{bodies} bodies", SampleUnit.Millisecond))
                .Run();
        }

        [Test, Performance, Category("GPU")]
        public void MeshWriteBack_Registration([ValueSource(typeof(MeshWriteBackBody), nameof(MeshWriteBackBody.BodyCounts))] int bodies)
        {
            Assume.That(EntitiesGraphicsSystem.EntitiesGraphicsEnabled, Is.True,
                "Entities Graphics has no renderer here (no render pipeline asset or -nographics): nothing to register with");
            m_World.GetOrCreateSystemManaged<EntitiesGraphicsSystem>();
            SystemHandle renderMesh = m_World.CreateSystem<SoftBodyRenderMeshSystem>();
            EntityManager manager = m_World.EntityManager;

            Measure.Method(() => renderMesh.Update(m_World.Unmanaged))
                .SetUp(() =>
                {
                    for (int b = 0; b < bodies; b++)
                    {
                        Entity body = manager.CreateEntity();
                        manager.AddComponentData(body, new ShapeMatchingShape { Blob = m_Shape });
                        manager.AddComponentData(body, new SoftBodyRenderMesh { Mesh = m_Source });
                        manager.AddComponentData(body, new MaterialMeshInfo());
                        manager.AddComponentData(body, new RenderBounds());
                        m_Bodies.Add(body);
                    }
                })
                .CleanUp(() =>
                {
                    // Destroyed bodies keep their cleanup component until the system unregisters and frees their meshes.
                    foreach (Entity body in m_Bodies)
                        manager.DestroyEntity(body);
                    m_Bodies.Clear();
                    renderMesh.Update(m_World.Unmanaged);
                })
                .WarmupCount(1)
                .MeasurementCount(5)
                .IterationsPerMeasurement(1)
                .SampleGroup(new SampleGroup($"MeshWriteBack registration x{bodies} bodies", SampleUnit.Millisecond))
                .Run();
        }

        /// <summary>A simulated body at <see cref="MeshWriteBackBody.Position"/>.</summary>
        Entity CreateBody(int index)
        {
            EntityManager manager = m_World.EntityManager;
            Entity body = manager.CreateEntity();
            manager.AddComponentData(body, LocalTransform.FromPositionRotation(MeshWriteBackBody.Position(index), quaternion.identity));
            SoftBodyArchetype.AddComponents(manager, body, m_Shape, ShapeMatchingParameters.Default);
            manager.AddComponentData(body, new RenderBounds());
            m_Bodies.Add(body);
            return body;
        }

        /// <summary>Counts one more step on every body, as the simulation would, so the next write deforms and uploads all of them.</summary>
        void MarkAllStepped()
        {
            EntityManager manager = m_World.EntityManager;
            foreach (Entity body in m_Bodies)
            {
                ParticleBodyState state = manager.GetComponentData<ParticleBodyState>(body);
                state.Status.StepCount++;
                manager.SetComponentData(body, state);
            }
        }

        void DestroyCopies()
        {
            foreach (Mesh copy in m_Copies)
                SoftBodyMeshInstancing.Destroy(copy);
            m_Copies.Clear();
        }

        static Vector3[] ToVector3(float3[] v)
        {
            var result = new Vector3[v.Length];
            for (int i = 0; i < v.Length; i++)
                result[i] = new Vector3(v[i].x, v[i].y, v[i].z);
            return result;
        }
    }
}
#endif
