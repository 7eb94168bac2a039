using NUnit.Framework;
using SoftBodyDynamics.Rendering;
using SoftBodyDynamics.Solvers;
using UnityEngine;

namespace SoftBodyDynamics.Tests.Editor.Rendering
{
    /// <summary>
    /// The renderer settings asset: its defaults are the desktop tier, the mobile tier applies the mobile defaults,
    /// lengths in particle radii become metres, and unusable values come back replaced and named.
    /// </summary>
    public class FluidRendererSettingsTests
    {
        const float k_Tolerance = 1e-6f;
        FluidRendererSettings m_Settings;

        [SetUp]
        public void SetUp() => m_Settings = ScriptableObject.CreateInstance<FluidRendererSettings>();

        [TearDown]
        public void TearDown() => Object.DestroyImmediate(m_Settings);

        static void AssertQualityEqual(FluidSurfaceSettings expected, FluidSurfaceSettings actual)
        {
            Assert.That(actual.ParticleRadius, Is.EqualTo(expected.ParticleRadius).Within(k_Tolerance), "particle radius");
            Assert.That(actual.DepthDivisor, Is.EqualTo(expected.DepthDivisor), "depth divisor");
            Assert.That(actual.CompositeDivisor, Is.EqualTo(expected.CompositeDivisor), "composite divisor");
            Assert.That(actual.Filter, Is.EqualTo(expected.Filter), "filter");
            Assert.That(actual.Iterations, Is.EqualTo(expected.Iterations), "iterations");
            Assert.That(actual.FilterRadius, Is.EqualTo(expected.FilterRadius).Within(k_Tolerance), "filter radius");
            Assert.That(actual.MaxFilterPixels, Is.EqualTo(expected.MaxFilterPixels), "largest filter radius");
            Assert.That(actual.DepthRange, Is.EqualTo(expected.DepthRange).Within(k_Tolerance), "depth range");
            Assert.That(actual.CurvatureStep, Is.EqualTo(expected.CurvatureStep).Within(k_Tolerance), "curvature step");
            Assert.That(actual.MaxRefractionPixels, Is.EqualTo(expected.MaxRefractionPixels).Within(k_Tolerance), "largest refraction offset");
        }

        [Test]
        public void NewAsset_IsTheDesktopTier()
        {
            FluidSurfaceSettings s = m_Settings.ToSettings(0.02f, out string problems);

            Assert.That(problems, Is.Empty);
            Assert.That(m_Settings.tier, Is.EqualTo(FluidRendererTier.Desktop));
            Assert.That(m_Settings.filterRadius, Is.EqualTo(2.5f), "filter radius in particle radii");
            Assert.That(m_Settings.depthRange, Is.EqualTo(2f), "depth range in particle radii");
            Assert.That(m_Settings.initialTileCapacity, Is.EqualTo(FluidRendererSettings.DefaultTileCapacity));
            AssertQualityEqual(FluidSurfaceSettings.Desktop(0.02f), s);
        }

        [Test]
        public void MobileTier_AppliesTheMobileDefaults_AndDesktopRestoresThem()
        {
            m_Settings.tier = FluidRendererTier.Mobile;
            m_Settings.Validate();
            FluidSurfaceSettings mobile = m_Settings.ToSettings(0.01f, out string problems);

            Assert.That(problems, Is.Empty);
            Assert.That(m_Settings.depthResolution, Is.EqualTo(FluidDepthResolution.Half));
            Assert.That(m_Settings.compositeResolution, Is.EqualTo(FluidDepthResolution.Half));
            AssertQualityEqual(FluidSurfaceSettings.Mobile(0.01f), mobile);

            m_Settings.tier = FluidRendererTier.Desktop;
            m_Settings.Validate();
            AssertQualityEqual(FluidSurfaceSettings.Desktop(0.01f), m_Settings.ToSettings(0.01f, out _));
        }

        [Test]
        public void Validate_KeepsHandEditedValues_WhileTheTierIsUnchanged()
        {
            m_Settings.iterations = 5;
            m_Settings.maxFilterPixels = 20;
            m_Settings.Validate();

            Assert.That(m_Settings.iterations, Is.EqualTo(5));
            Assert.That(m_Settings.maxFilterPixels, Is.EqualTo(20));
        }

        [Test]
        public void LengthsInParticleRadii_BecomeMetres()
        {
            m_Settings.filterRadius = 3f;
            m_Settings.depthRange = 1.5f;
            FluidSurfaceSettings s = m_Settings.ToSettings(0.04f, out string problems);

            Assert.That(problems, Is.Empty);
            Assert.That(s.FilterRadius, Is.EqualTo(0.12f).Within(k_Tolerance));
            Assert.That(s.DepthRange, Is.EqualTo(0.06f).Within(k_Tolerance));
        }

        [Test]
        public void BadValues_AreNamedInProblems_AndReplacedBySaneOnes()
        {
            m_Settings.iterations = -3;
            m_Settings.filterRadius = -1f;
            m_Settings.maxFilterPixels = 0;
            m_Settings.depthResolution = (FluidDepthResolution)3;
            m_Settings.curvatureStep = 0.9f;
            FluidSurfaceSettings s = m_Settings.ToSettings(0.02f, out string problems);

            Assert.That(problems, Does.Contain("iterations"));
            Assert.That(problems, Does.Contain("filter radius"));
            Assert.That(problems, Does.Contain("depth divisor"));
            Assert.That(problems, Does.Contain("curvature step"));
            Assert.That(s.Iterations, Is.EqualTo(0));
            Assert.That(s.FilterRadius, Is.GreaterThan(0f));
            Assert.That(s.MaxFilterPixels, Is.EqualTo(1));
            Assert.That(s.DepthDivisor, Is.EqualTo(1));
            Assert.That(s.CurvatureStep, Is.GreaterThan(0f).And.LessThanOrEqualTo(0.25f));
        }

        [Test]
        public void NonPositiveParticleRadius_IsNamedInProblems()
        {
            FluidSurfaceSettings s = m_Settings.ToSettings(0f, out string problems);

            Assert.That(problems, Does.Contain("particle radius"));
            Assert.That(s.ParticleRadius, Is.GreaterThan(0f));
            Assert.That(s.FilterRadius, Is.GreaterThan(0f));
            Assert.That(s.DepthRange, Is.GreaterThan(0f));
        }

        [Test]
        public void Validate_ClampsObviouslyBadValues()
        {
            m_Settings.iterations = 500;
            m_Settings.filterRadius = float.NaN;
            m_Settings.maxFilterPixels = 100;
            m_Settings.depthRange = -2f;
            m_Settings.curvatureStep = -1f;
            m_Settings.maxRefractionPixels = float.PositiveInfinity;
            m_Settings.initialTileCapacity = 0;
            m_Settings.Validate();

            Assert.That(m_Settings.iterations, Is.EqualTo(FluidSurfaceSettings.MaxIterations));
            Assert.That(m_Settings.filterRadius, Is.EqualTo(2.5f));
            Assert.That(m_Settings.maxFilterPixels, Is.EqualTo(FluidSurfaceSettings.MaxFilterPixelsLimit));
            Assert.That(m_Settings.depthRange, Is.EqualTo(FluidRendererSettings.MinRadii));
            Assert.That(m_Settings.curvatureStep, Is.EqualTo(0.2f));
            Assert.That(m_Settings.maxRefractionPixels, Is.EqualTo(48f));
            Assert.That(m_Settings.initialTileCapacity, Is.EqualTo(FluidRendererSettings.MinTileCapacity));
            m_Settings.ToSettings(0.02f, out string problems);
            Assert.That(problems, Is.Empty, "validated settings need no further replacement");
        }

        [Test]
        public void DefaultSky_IsTheDefaultLightingSkyInLinear()
        {
            Color zenith = m_Settings.skyZenith.linear, horizon = m_Settings.skyHorizon.linear;
            FluidSurfaceLighting d = FluidSurfaceLighting.Default;

            Assert.That(zenith.r, Is.EqualTo(d.SkyZenith.x).Within(2e-3f));
            Assert.That(zenith.g, Is.EqualTo(d.SkyZenith.y).Within(2e-3f));
            Assert.That(zenith.b, Is.EqualTo(d.SkyZenith.z).Within(2e-3f));
            Assert.That(horizon.r, Is.EqualTo(d.SkyHorizon.x).Within(2e-3f));
            Assert.That(horizon.g, Is.EqualTo(d.SkyHorizon.y).Within(2e-3f));
            Assert.That(horizon.b, Is.EqualTo(d.SkyHorizon.z).Within(2e-3f));
        }
    }
}
