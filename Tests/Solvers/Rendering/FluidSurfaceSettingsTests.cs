using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    public class FluidSurfaceSettingsTests
    {
        [Test]
        public void Tiers_AreValidAsTheyCome()
        {
            FluidSurfaceSettings.Desktop(0.01f).Sanitized(out string desktop);
            FluidSurfaceSettings.Mobile(0.01f).Sanitized(out string mobile);
            Assert.That(desktop, Is.Empty);
            Assert.That(mobile, Is.Empty);
            Assert.That(FluidSurfaceSettings.Mobile(0.01f).DepthDivisor, Is.EqualTo(2));
            Assert.That(FluidSurfaceSettings.Desktop(0.01f).DepthDivisor, Is.EqualTo(1));
            Assert.That(FluidSurfaceSettings.Mobile(0.01f).CompositeDivisor, Is.EqualTo(2));
            Assert.That(FluidSurfaceSettings.Desktop(0.01f).CompositeDivisor, Is.EqualTo(1));
        }

        [Test]
        public void Sanitized_ReplacesEveryUnusableValueAndSaysWhich()
        {
            FluidSurfaceSettings s = FluidSurfaceSettings.Desktop(0.01f);
            s.ParticleRadius = float.NaN;
            s.DepthDivisor = 3;
            s.CompositeDivisor = 0;
            s.Filter = (FluidSurfaceFilter)9;
            s.Iterations = 1000;
            s.FilterRadius = -1f;
            s.MaxFilterPixels = 0;
            s.DepthRange = float.PositiveInfinity;
            s.CurvatureStep = 0.5f;
            s.MaxRefractionPixels = float.NaN;
            FluidSurfaceSettings t = s.Sanitized(out string problems);
            foreach (string word in new[] { "particle radius", "depth divisor", "composite divisor", "filter", "iterations", "filter radius", "largest filter radius", "depth range", "curvature step", "refraction" })
                Assert.That(problems, Does.Contain(word));
            Assert.That(t.ParticleRadius, Is.GreaterThan(0f));
            Assert.That(t.DepthDivisor, Is.EqualTo(1));
            Assert.That(t.CompositeDivisor, Is.EqualTo(1));
            Assert.That(t.Filter, Is.EqualTo(FluidSurfaceFilter.NarrowRange));
            Assert.That(t.Iterations, Is.EqualTo(FluidSurfaceSettings.MaxIterations));
            Assert.That(t.FilterRadius, Is.GreaterThan(0f));
            Assert.That(t.MaxFilterPixels, Is.EqualTo(1));
            Assert.That(math.isfinite(t.DepthRange) && t.DepthRange > 0f);
            Assert.That(t.CurvatureStep, Is.InRange(1e-6f, 0.25f));
            Assert.That(t.MaxRefractionPixels, Is.GreaterThanOrEqualTo(0f));
            t.Sanitized(out string again);
            Assert.That(again, Is.Empty, "a sanitized copy is valid");
        }

        [Test]
        public void Looks_AreValidPresets()
        {
            foreach (var (name, look) in FluidLook.Presets)
            {
                look.Sanitized(out string problems);
                Assert.That(problems, Is.Empty, name);
            }
            // Schlick's F0 of water, ((1.33 − 1)/(1.33 + 1))² ≈ 0.02.
            Assert.That(FluidLook.Water.F0, Is.EqualTo(0.0201f).Within(2e-4f));
        }

        [Test]
        public void LookSanitized_ReplacesBadValues()
        {
            FluidLook l = FluidLook.Water;
            l.Absorption = new float3(float.NaN, 1f, 1f);
            l.IndexOfRefraction = 0.5f;
            l.Bands = 0;
            l.HotAttribute = l.ColdAttribute;
            l.Emission = new float3(1f);
            FluidLook t = l.Sanitized(out string problems);
            Assert.That(problems, Does.Contain("absorption").And.Contain("index of refraction").And.Contain("toon bands").And.Contain("hot attribute"));
            Assert.That(math.all(math.isfinite(t.Absorption)));
            Assert.That(t.IndexOfRefraction, Is.InRange(1f, 3f));
            Assert.That(t.Bands, Is.InRange(1, 8));
            Assert.That(t.HotAttribute, Is.GreaterThan(t.ColdAttribute));
            Assert.That(t.Emission.x + t.Emission.y + t.Emission.z, Is.Zero, "emission is off when the attribute range is unusable");
        }

        [Test]
        public void Cost_FallsWithResolutionAndGrowsWithIterations()
        {
            FluidSurfaceSettings full = FluidSurfaceSettings.Desktop(0.01f), half = FluidSurfaceSettings.Mobile(0.01f);
            full.Iterations = half.Iterations = 1;
            FluidSurfacePassCost[] f = FluidSurfaceCost.Passes(full, FluidLook.Water), h = FluidSurfaceCost.Passes(half, FluidLook.Water);
            // Depth-resolution passes cost a quarter at half resolution; thickness is at half resolution in both.
            Assert.That(h[0].BytesPerPixel, Is.EqualTo(f[0].BytesPerPixel / 4).Within(1e-12));
            Assert.That(h[1].BytesPerPixel, Is.EqualTo(f[1].BytesPerPixel).Within(1e-12));
            Assert.That(h[2].BytesPerPixel, Is.EqualTo(f[2].BytesPerPixel / 4).Within(1e-12));
            Assert.That(FluidSurfaceCost.BytesPerPixel(half, FluidLook.Water), Is.LessThan(FluidSurfaceCost.BytesPerPixel(full, FluidLook.Water)));
            // A half-resolution composite writes a quarter of the colour and the overlay reads a quarter of it; the
            // camera colour the overlay blends onto stays at full resolution (4 + 4 bytes).
            Assert.That(h[5].BytesPerPixel, Is.EqualTo(FluidSurfaceCost.FluidColourBytes / 4.0 + 2 * FluidSurfaceCost.CameraColourBytes).Within(1e-12));
            Assert.That(f[5].BytesPerPixel, Is.EqualTo(FluidSurfaceCost.FluidColourBytes + 2 * FluidSurfaceCost.CameraColourBytes).Within(1e-12));
            // Each separable iteration reads and writes the depth twice: 2 × (4 + 4) bytes per depth pixel.
            FluidSurfaceSettings more = full;
            more.Iterations = 3;
            Assert.That(FluidSurfaceCost.BytesPerPixel(more, FluidLook.Water) - FluidSurfaceCost.BytesPerPixel(full, FluidLook.Water), Is.EqualTo(2 * 16.0).Within(1e-9));
        }
    }
}
