using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Rendering;
using Unity.Entities;
using UnityEngine;

namespace SoftBodyDynamics.Tests.Editor.Rendering
{
    /// <summary>
    /// Which fluids are drawn for a camera at the origin looking down +z (60° field of view, near plane 0.3 m):
    /// none without particles, a float4 buffer that holds them, or a radius; none behind the camera; one in front is.
    /// </summary>
    public class FluidRenderVisibilityTests
    {
        GameObject m_CameraObject;
        Plane[] m_Frustum;

        static readonly Bounds k_InFront = new Bounds(new Vector3(0f, 0f, 5f), Vector3.one);
        static readonly Bounds k_Behind = new Bounds(new Vector3(0f, 0f, -5f), Vector3.one);

        [SetUp]
        public void SetUp()
        {
            m_CameraObject = new GameObject("Fluid visibility test camera");
            Camera camera = m_CameraObject.AddComponent<Camera>();
            camera.fieldOfView = 60f;
            camera.nearClipPlane = 0.3f;
            camera.farClipPlane = 100f;
            m_Frustum = GeometryUtility.CalculateFrustumPlanes(camera);
        }

        [TearDown]
        public void TearDown()
        {
            Object.DestroyImmediate(m_CameraObject);
        }

        [Test]
        public void FluidInFront_IsDrawn() =>
            Assert.That(FluidRenderVisibility.IsDrawn(100, 100, 0.01f, k_InFront, m_Frustum), Is.True);

        [Test]
        public void FluidBehindTheCamera_IsNotDrawn() =>
            Assert.That(FluidRenderVisibility.IsDrawn(100, 100, 0.01f, k_Behind, m_Frustum), Is.False);

        [Test]
        public void NoParticles_IsNotDrawn() =>
            Assert.That(FluidRenderVisibility.IsDrawn(0, 100, 0.01f, k_InFront, m_Frustum), Is.False);

        [Test]
        public void MoreParticlesThanTheBufferHolds_IsNotDrawn() =>
            Assert.That(FluidRenderVisibility.IsDrawn(101, 100, 0.01f, k_InFront, m_Frustum), Is.False);

        [Test]
        public void ZeroOrNonFiniteRadius_IsNotDrawn()
        {
            Assert.That(FluidRenderVisibility.IsDrawn(100, 100, 0f, k_InFront, m_Frustum), Is.False);
            Assert.That(FluidRenderVisibility.IsDrawn(100, 100, -0.01f, k_InFront, m_Frustum), Is.False);
            Assert.That(FluidRenderVisibility.IsDrawn(100, 100, float.NaN, k_InFront, m_Frustum), Is.False);
        }

        [Test]
        public void FluidAcrossTheNearPlane_IsDrawn_AndOneWhollyBeforeIt_IsNot()
        {
            // Spheres from 0 to 0.4 m ahead reach past the 0.3 m near plane; spheres from 0 to 0.2 m do not.
            var across = new Bounds(new Vector3(0f, 0f, 0.2f), new Vector3(0.1f, 0.1f, 0.4f));
            var before = new Bounds(new Vector3(0f, 0f, 0.1f), new Vector3(0.1f, 0.1f, 0.2f));

            Assert.That(FluidRenderVisibility.IsDrawn(100, 100, 0.01f, across, m_Frustum), Is.True);
            Assert.That(FluidRenderVisibility.IsDrawn(100, 100, 0.01f, before, m_Frustum), Is.False);
        }

        [Test]
        public void MissingSourceOrBuffer_IsNotDrawn()
        {
            var withoutBuffer = new FluidRenderSource { Count = 100, ParticleRadius = 0.01f, WorldBounds = k_InFront };

            Assert.That(FluidRenderVisibility.IsDrawn(null, m_Frustum), Is.False);
            Assert.That(FluidRenderVisibility.IsDrawn(withoutBuffer, m_Frustum), Is.False);
        }

        [Test]
        public void SourceWithAFloat4Buffer_IsDrawnInFront_AndNotWithAnotherStride()
        {
            if (!SystemInfo.supportsComputeShaders)
                Assert.Ignore("This device has no compute shaders, so no structured buffers to draw from.");
            var particles = new GraphicsBuffer(GraphicsBuffer.Target.Structured, 4, 16);
            var scalars = new GraphicsBuffer(GraphicsBuffer.Target.Structured, 4, 4);
            try
            {
                var source = new FluidRenderSource { Particles = particles, Count = 4, ParticleRadius = 0.01f, WorldBounds = k_InFront };
                Assert.That(FluidRenderVisibility.IsDrawn(source, m_Frustum), Is.True);

                source.WorldBounds = k_Behind;
                Assert.That(FluidRenderVisibility.IsDrawn(source, m_Frustum), Is.False, "behind the camera");

                source.WorldBounds = k_InFront;
                source.Particles = scalars;
                Assert.That(FluidRenderVisibility.IsDrawn(source, m_Frustum), Is.False, "stride 4 is not float4");
            }
            finally
            {
                particles.Release();
                scalars.Release();
            }
        }

        [Test]
        public void AnyDrawn_IsFalse_ForAFluidWithoutBuffer_OrWithoutCamera()
        {
            Camera camera = m_CameraObject.GetComponent<Camera>();
            var planes = new Plane[FluidRenderVisibility.PlaneCount];

            var sources = new List<FluidRenderSource> { new FluidRenderSource { Count = 100, ParticleRadius = 0.01f, WorldBounds = k_InFront } };
            Assert.That(FluidRenderVisibility.AnyDrawn(camera, planes, sources), Is.False, "a fluid without a buffer");
            Assert.That(FluidRenderVisibility.AnyDrawn(null, planes, sources), Is.False, "no camera");
        }
    }
}
