using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;
using Unity.Rendering;
using UnityEngine;

namespace SoftBodyDynamics.Tests.Editor
{
    /// <summary>
    /// <see cref="SoftBodyRenderMeshSystem"/> in worlds where Entities Graphics cannot draw: no
    /// <c>EntitiesGraphicsSystem</c> at all (server and custom worlds), or one that is disabled. Entities Graphics
    /// disables itself in <c>OnCreate</c> when it has no renderer (no render pipeline asset, -nographics as in the
    /// CI workflow, no compute support) and then has no BatchRendererGroup, so registering a mesh with it throws.
    /// The system must then do nothing, throw nothing, and warn once per world, however many frames pass.
    /// </summary>
    public class SoftBodyRenderMeshSystemTests
    {
        const int k_Frames = 10;
        const string k_WarningText = "simulated but not drawn";

        World m_World;
        Mesh m_Mesh;
        BlobAssetReference<ShapeMatchingShapeBlob> m_Shape;
        int m_Warnings;
        List<string> m_Errors;

        /// <summary>A readable tetrahedron mesh, one particle per vertex, one cluster.</summary>
        [SetUp]
        public void SetUp()
        {
            m_World = new World("Soft body render mesh tests");
            var rest = new[] { new float3(0f, 0f, 0f), new float3(1f, 0f, 0f), new float3(0f, 1f, 0f), new float3(0f, 0f, 1f) };
            int[] triangles = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };
            m_Mesh = new Mesh { name = "Tetrahedron" };
            m_Mesh.vertices = new[] { new Vector3(0f, 0f, 0f), new Vector3(1f, 0f, 0f), new Vector3(0f, 1f, 0f), new Vector3(0f, 0f, 1f) };
            m_Mesh.triangles = triangles;
            ShapeMatchingModelData model = ShapeMatchingModelData.Create(rest, new[] { 0.25f, 0.25f, 0.25f, 0.25f },
                new[] { 0, 4 }, new[] { 0, 1, 2, 3 }, false);
            m_Shape = ShapeMatchingShapeBlobFactory.Create(model, new[] { 0, 1, 2, 3 }, triangles, Allocator.Persistent);

            m_Warnings = 0;
            m_Errors = new List<string>();
            Application.logMessageReceived += OnLog;
        }

        [TearDown]
        public void TearDown()
        {
            Application.logMessageReceived -= OnLog;
            m_World.Dispose();
            Object.DestroyImmediate(m_Mesh);
            if (m_Shape.IsCreated)
                m_Shape.Dispose();
        }

        void OnLog(string condition, string stackTrace, LogType type)
        {
            if (type == LogType.Warning && condition.Contains(k_WarningText))
                m_Warnings++;
            else if (type == LogType.Error || type == LogType.Exception || type == LogType.Assert)
                m_Errors.Add(condition);
        }

        /// <summary>A body as the baker makes it for Entities Graphics: render mesh, shape, MaterialMeshInfo, RenderBounds.</summary>
        Entity CreateRenderedBody()
        {
            EntityManager manager = m_World.EntityManager;
            Entity entity = manager.CreateEntity();
            manager.AddComponentData(entity, new SoftBodyRenderMesh { Mesh = m_Mesh });
            manager.AddComponentData(entity, new ShapeMatchingShape { Blob = m_Shape });
            manager.AddComponentData(entity, new MaterialMeshInfo());
            manager.AddComponentData(entity, new RenderBounds());
            return entity;
        }

        void UpdateFrames(SystemHandle system)
        {
            for (int f = 0; f < k_Frames; f++)
                system.Update(m_World.Unmanaged);
        }

        void AssertNothingDone(Entity body)
        {
            EntityManager manager = m_World.EntityManager;
            Assert.That(m_Errors, Is.Empty, "no exception or error on any frame");
            Assert.That(manager.HasComponent<SoftBodyMeshInstance>(body), Is.False, "no mesh instance without a renderer");
            Assert.That(manager.HasBuffer<SoftBodyMeshVertex>(body), Is.False, "no vertex buffer either");
        }

        [Test]
        public void WithoutEntitiesGraphicsSystem_DoesNothing_AndWarnsOnce()
        {
            SystemHandle system = m_World.CreateSystem<SoftBodyRenderMeshSystem>();
            Entity body = CreateRenderedBody();

            UpdateFrames(system);

            AssertNothingDone(body);
            Assert.That(m_Warnings, Is.EqualTo(1), $"one warning over {k_Frames} frames");
        }

        [Test]
        public void WithEntitiesGraphicsSystemDisabled_DoesNothing_AndWarnsOnce()
        {
            // Under -nographics or without a render pipeline asset the system disables itself in OnCreate and never
            // creates its BatchRendererGroup (the per-frame NullReferenceException this pins); elsewhere it is
            // disabled here by hand, which must be honoured the same way.
            var graphics = m_World.GetOrCreateSystemManaged<EntitiesGraphicsSystem>();
            graphics.Enabled = false;
            SystemHandle system = m_World.CreateSystem<SoftBodyRenderMeshSystem>();
            Entity body = CreateRenderedBody();

            UpdateFrames(system);

            AssertNothingDone(body);
            Assert.That(m_Warnings, Is.EqualTo(1), $"one warning over {k_Frames} frames");
        }

        [Test]
        public void WithoutARenderedBody_DoesNotWarn()
        {
            SystemHandle system = m_World.CreateSystem<SoftBodyRenderMeshSystem>();
            Entity unrendered = m_World.EntityManager.CreateEntity();
            m_World.EntityManager.AddComponentData(unrendered, new ShapeMatchingShape { Blob = m_Shape });

            UpdateFrames(system);

            Assert.That(m_Errors, Is.Empty);
            Assert.That(m_Warnings, Is.EqualTo(0), "nothing to draw, nothing to say");
        }
    }
}
