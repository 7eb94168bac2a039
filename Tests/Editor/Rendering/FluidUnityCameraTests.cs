using NUnit.Framework;
using SoftBodyDynamics.Rendering;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Tests.Editor.Rendering
{
    /// <summary>
    /// The fluid passes' camera from a Unity camera (view space looks down −z) and their lighting from the scene's sun.
    /// </summary>
    public class FluidUnityCameraTests
    {
        const float k_Tolerance = 1e-4f;
        GameObject m_Object;

        [TearDown]
        public void TearDown()
        {
            if (m_Object != null)
                Object.DestroyImmediate(m_Object);
        }

        static void AssertNear(float3 expected, float3 actual, string what)
        {
            Assert.That(actual.x, Is.EqualTo(expected.x).Within(k_Tolerance), what + " x");
            Assert.That(actual.y, Is.EqualTo(expected.y).Within(k_Tolerance), what + " y");
            Assert.That(actual.z, Is.EqualTo(expected.z).Within(k_Tolerance), what + " z");
        }

        FluidSurfaceCamera CameraAt(Vector3 position, Quaternion rotation)
        {
            m_Object = new GameObject("Fluid camera test");
            m_Object.transform.position = position;
            m_Object.transform.rotation = rotation;
            Camera camera = m_Object.AddComponent<Camera>();
            camera.fieldOfView = 50f;
            camera.nearClipPlane = 0.2f;
            return FluidUnityCamera.From(camera.worldToCameraMatrix, 640, 360, camera.fieldOfView, camera.nearClipPlane);
        }

        [Test]
        public void From_PutsPointsAheadOfTheCameraAtNegativeViewZ()
        {
            FluidSurfaceCamera c = CameraAt(new Vector3(0f, 0f, -10f), Quaternion.identity);

            AssertNear(new float3(0f, 0f, -10f), c.ToView(float3.zero), "the origin, 10 m ahead");
            AssertNear(new float3(1f, 2f, -4f), c.ToView(new float3(1f, 2f, -6f)), "a point right, up and ahead");
            Assert.That(c.Width, Is.EqualTo(640));
            Assert.That(c.Height, Is.EqualTo(360));
            Assert.That(c.FieldOfView, Is.EqualTo(50f));
            Assert.That(c.Near, Is.EqualTo(0.2f));
        }

        [Test]
        public void From_FollowsTheCameraRotation()
        {
            // Turned 90° about y: the camera looks down world +x, and world −z is to its right.
            FluidSurfaceCamera c = CameraAt(Vector3.zero, Quaternion.Euler(0f, 90f, 0f));

            AssertNear(new float3(0f, 0f, -5f), c.ToView(new float3(5f, 0f, 0f)), "a point 5 m along +x");
            AssertNear(new float3(1f, 0f, 0f), c.ToView(new float3(0f, 0f, -1f)), "a point 1 m along −z");
        }

        [Test]
        public void Lighting_PointsTowardTheSun_WithItsColourTimesIntensity()
        {
            m_Object = new GameObject("Fluid sun test");
            m_Object.transform.rotation = Quaternion.Euler(90f, 0f, 0f); // shining straight down
            Light sun = m_Object.AddComponent<Light>();
            sun.color = new Color(1f, 1f, 1f);
            sun.intensity = 2f;

            FluidSurfaceLighting l = FluidUnityCamera.Lighting(sun, new Color(0f, 0f, 0f), new Color(1f, 1f, 1f));

            AssertNear(new float3(0f, 1f, 0f), l.LightDirection, "direction toward the light");
            AssertNear(new float3(2f, 2f, 2f), l.LightColour, "colour × intensity");
            AssertNear(float3.zero, l.SkyZenith, "black zenith");
            AssertNear(new float3(1f, 1f, 1f), l.SkyHorizon, "white horizon");
        }

        [Test]
        public void Lighting_WithoutASun_KeepsTheDefaultLight_AndLinearisesTheSky()
        {
            FluidSurfaceLighting l = FluidUnityCamera.Lighting(null, new Color(0.5f, 0.5f, 0.5f), new Color(1f, 1f, 1f));
            FluidSurfaceLighting d = FluidSurfaceLighting.Default;

            AssertNear(d.LightDirection, l.LightDirection, "default direction");
            AssertNear(d.LightColour, l.LightColour, "default colour");
            // sRGB 0.5 is linear ((0.5 + 0.055) / 1.055)^2.4 ≈ 0.2140.
            Assert.That(l.SkyZenith.x, Is.EqualTo(0.2140f).Within(1e-3f));
        }
    }
}
