using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    public class FluidSurfacePassesTests
    {
        static FluidSurfaceConstants Constants(FluidSurfaceCamera camera, FluidSurfaceSettings settings, int particles = 1) =>
            FluidSurfaceConstants.Of(camera, settings, FluidLook.Water, FluidSurfaceLighting.Default, particles, 1 << 16);

        static FluidSurfaceCamera Camera(int w = 64, int h = 48) => FluidSurfaceCamera.LookAt(new float3(0f, 0f, 2f), float3.zero, w, h, 60f);

        [Test]
        public void RaySphere_OnAxisHitsAtDepthMinusRadiusWithAChordOfTheDiameter()
        {
            float2 hit = FluidSurfacePasses.RaySphere(new float3(0f, 0f, -1f), new float3(0f, 0f, -2f), 0.25f);
            Assert.That(hit.x, Is.EqualTo(1.5f).Within(1e-6f));
            Assert.That(hit.y, Is.EqualTo(1f).Within(1e-6f));
        }

        [Test]
        public void RaySphere_MissesBesideAndBehind()
        {
            Assert.That(FluidSurfacePasses.RaySphere(new float3(0f, 0f, -1f), new float3(0.6f, 0f, -2f), 0.25f).y, Is.Zero);
            Assert.That(FluidSurfacePasses.RaySphere(new float3(0f, 0f, -1f), new float3(0f, 0f, 2f), 0.25f).y, Is.Zero);
        }

        [Test]
        public void Pinhole_ProjectsAViewPointOntoThePixelWhoseRayPassesThroughIt()
        {
            FluidSurfaceCamera cam = Camera(80, 60);
            foreach (int divisor in new[] { 1, 2 })
            {
                float4 pin = cam.Pinhole(divisor);
                var p = new float3(0.3f, -0.2f, -1.7f);
                float px = pin.z + pin.x * p.x / -p.z, py = pin.w + pin.y * p.y / -p.z;
                float3 ray = FluidSurfacePasses.PixelRay(px, py, new float2(pin.x, pin.y), new float2(pin.z, pin.w)) * -p.z;
                Assert.That(math.length(ray - p), Is.LessThan(1e-5f));
            }
            // 60° vertical field: f = 30 / tan 30°.
            Assert.That(cam.Pinhole(1).y, Is.EqualTo(30.0 / Math.Tan(Math.PI / 6)).Within(1e-3));
            Assert.That(cam.Size(2).x, Is.EqualTo(40));
            Assert.That(FluidSurfaceCamera.LookAt(float3.zero, new float3(0f, 0f, -1f), 81, 61, 60f).Size(2).y, Is.EqualTo(31));
        }

        [Test]
        public void TileRect_CoversEveryPixelTheSphereHits()
        {
            FluidSurfaceCamera cam = Camera(96, 64);
            FluidSurfaceSettings s = FluidSurfaceSettings.Desktop(0.15f);
            FluidSurfaceConstants k = Constants(cam, s);
            var rng = new Unity.Mathematics.Random(7u);
            for (int trial = 0; trial < 50; trial++)
            {
                float3 world = (rng.NextFloat3() - 0.5f) * new float3(2.4f, 1.6f, 1.5f);
                int4 rect = FluidSurfacePasses.TileRect(k, world);
                float3 c = FluidSurfacePasses.ToView(k, world);
                for (int y = 0; y < cam.Height; y++)
                    for (int x = 0; x < cam.Width; x++)
                    {
                        if (FluidSurfacePasses.RaySphere(FluidSurfacePasses.PixelRay(x + 0.5f, y + 0.5f, k.DepthFocal, k.DepthCentre), c, s.ParticleRadius * s.ParticleRadius).y <= 0f)
                            continue;
                        int tx = x / FluidSurfaceLayout.TileSize, ty = y / FluidSurfaceLayout.TileSize;
                        Assert.That(tx >= rect.x && tx <= rect.z && ty >= rect.y && ty <= rect.w, $"pixel ({x}, {y}) of a sphere at {world} is outside its tiles {rect}");
                    }
            }
        }

        [Test]
        public void TileRect_CullsNonFiniteAndNearParticles()
        {
            FluidSurfaceConstants k = Constants(Camera(), FluidSurfaceSettings.Desktop(0.1f));
            foreach (float3 p in new[] { new float3(float.NaN, 0f, 0f), new float3(0f, float.PositiveInfinity, 0f), new float3(0f, 0f, 1.95f), new float3(0f, 0f, 3f), new float3(50f, 0f, 0f) })
            {
                int4 r = FluidSurfacePasses.TileRect(k, p);
                Assert.That(r.x, Is.GreaterThan(r.z), $"{p} must be culled");
            }
        }

        [Test]
        public void PackedNormal_RoundTripsWithin0Point005Degrees()
        {
            var rng = new Unity.Mathematics.Random(3u);
            double worst = 0;
            for (int i = 0; i < 20000; i++)
            {
                float3 n = math.normalize(rng.NextFloat3() * 2f - 1f);
                if (!math.all(math.isfinite(n)))
                    continue;
                float3 m = FluidSurfacePasses.UnpackNormal(FluidSurfacePasses.PackNormal(n));
                double cx = (double)n.y * m.z - (double)n.z * m.y, cy = (double)n.z * m.x - (double)n.x * m.z, cz = (double)n.x * m.y - (double)n.y * m.x;
                worst = Math.Max(worst, Math.Atan2(Math.Sqrt(cx * cx + cy * cy + cz * cz), (double)n.x * m.x + (double)n.y * m.y + (double)n.z * m.z) * 180 / Math.PI);
            }
            // A 16-bit octahedral cell is 2/65535 wide: at most about 0.0035° of arc.
            Assert.That(worst, Is.LessThan(0.005));
        }

        static float[] Plane(FluidSurfaceConstants k, float z, int w, int h, int holeX = -1)
        {
            var d = new float[w * h];
            for (int i = 0; i < d.Length; i++)
                d[i] = i % w == holeX ? 0f : z;
            return d;
        }

        [TestCase(FluidSurfaceFilter.NarrowRange)]
        [TestCase(FluidSurfaceFilter.Bilateral)]
        [TestCase(FluidSurfaceFilter.CurvatureFlow)]
        public void Filters_KeepAFlatSurfaceFlatAndEmptyPixelsEmpty(FluidSurfaceFilter filter)
        {
            FluidSurfaceCamera cam = Camera(32, 24);
            FluidSurfaceSettings s = FluidSurfaceSettings.Desktop(0.05f);
            s.Filter = filter;
            s.Iterations = 3;
            FluidSurfaceConstants k = Constants(cam, s);
            float[] a = Plane(k, 1.5f, 32, 24, holeX: 10), b = new float[a.Length];
            FluidSurfacePasses.Smooth(k, s, a, b);
            float[] result = FluidSurfaceFrame.SmoothedDepth(FluidSurfacePassList.Of(s, FluidLook.Water)) == FluidSurfaceBuffer.DepthA ? a : b;
            for (int i = 0; i < result.Length; i++)
            {
                if (i % 32 == 10)
                    Assert.That(result[i], Is.Zero, "an empty pixel stays empty");
                else
                    Assert.That(result[i], Is.EqualTo(1.5f).Within(1.5f * 1e-6f), $"pixel {i}");
            }
        }

        [TestCase(FluidSurfaceFilter.NarrowRange)]
        [TestCase(FluidSurfaceFilter.Bilateral)]
        [TestCase(FluidSurfaceFilter.CurvatureFlow)]
        public void Filters_FlattenASpike(FluidSurfaceFilter filter)
        {
            FluidSurfaceCamera cam = Camera(32, 24);
            FluidSurfaceSettings s = FluidSurfaceSettings.Desktop(0.05f);
            s.Filter = filter;
            s.Iterations = filter == FluidSurfaceFilter.CurvatureFlow ? 10 : 1;
            FluidSurfaceConstants k = Constants(cam, s);
            float[] a = Plane(k, 1.5f, 32, 24), b = new float[a.Length];
            int spike = 12 * 32 + 16;
            a[spike] = 1.5f - 0.02f;   // a bump 2 cm towards the camera, inside the depth range
            FluidSurfacePasses.Smooth(k, s, a, b);
            float[] result = FluidSurfaceFrame.SmoothedDepth(FluidSurfacePassList.Of(s, FluidLook.Water)) == FluidSurfaceBuffer.DepthA ? a : b;
            Assert.That(1.5f - result[spike], Is.LessThan(0.5f * 0.02f), "the spike must lose at least half its height");
        }

        [Test]
        public void Normals_OfATiltedPlaneAreItsNormal()
        {
            FluidSurfaceCamera cam = Camera(40, 30);
            FluidSurfaceSettings s = FluidSurfaceSettings.Desktop(0.05f);
            FluidSurfaceConstants k = Constants(cam, s);
            // The plane z_view = −1.5 − 0.3 x_view: depth along each pixel ray where it meets the plane.
            float3 normal = math.normalize(new float3(-0.3f, 0f, 1f));
            var depth = new float[40 * 30];
            for (int y = 0; y < 30; y++)
                for (int x = 0; x < 40; x++)
                {
                    float3 ray = FluidSurfacePasses.PixelRay(x + 0.5f, y + 0.5f, k.DepthFocal, k.DepthCentre);
                    depth[y * 40 + x] = 1.5f / (1f + 0.3f * ray.x);
                }
            var packed = new uint[depth.Length];
            FluidSurfacePasses.Normals(k, depth, packed);
            for (int i = 0; i < packed.Length; i++)
                Assert.That(math.dot(FluidSurfacePasses.UnpackNormal(packed[i]), normal), Is.GreaterThan(0.99999f), $"pixel {i}");
        }

        [Test]
        public void Frame_RecordsOnePassPairPerIterationAndEndsInTheRightBuffer()
        {
            FluidSurfaceCamera cam = Camera(100, 50);
            foreach (FluidSurfaceFilter filter in new[] { FluidSurfaceFilter.None, FluidSurfaceFilter.NarrowRange, FluidSurfaceFilter.Bilateral, FluidSurfaceFilter.CurvatureFlow })
                foreach (int iterations in new[] { 0, 1, 3 })
                {
                    FluidSurfaceSettings s = FluidSurfaceSettings.Desktop(0.05f);
                    s.Filter = filter;
                    s.Iterations = iterations;
                    var rec = new Recorder();
                    FluidSurfaceFrame.Record(ref rec, FluidSurfaceTargets.Of(cam, 1), FluidSurfacePassList.Of(s, FluidLook.Water), 0);
                    int filters = rec.Count(FluidSurfaceKernel.NarrowRangeX) + rec.Count(FluidSurfaceKernel.NarrowRangeY) + rec.Count(FluidSurfaceKernel.BilateralX)
                        + rec.Count(FluidSurfaceKernel.BilateralY) + rec.Count(FluidSurfaceKernel.CurvatureFlow);
                    int expected = filter == FluidSurfaceFilter.None ? 0 : filter == FluidSurfaceFilter.CurvatureFlow ? iterations : 2 * iterations;
                    Assert.That(filters, Is.EqualTo(expected), $"{filter} × {iterations}");
                    Assert.That(rec.Count(FluidSurfaceKernel.Composite), Is.EqualTo(1));
                    Assert.That(rec.CompositeDepth, Is.EqualTo(FluidSurfaceFrame.SmoothedDepth(FluidSurfacePassList.Of(s, FluidLook.Water))));
                    Assert.That(rec.MinGroups, Is.GreaterThanOrEqualTo(1), "no empty dispatch, even with no particles");
                }
        }

        struct Recorder : IFluidSurfaceCommands
        {
            int[] m_Counts;
            public FluidSurfaceBuffer CompositeDepth;
            public int MinGroups;

            public int Count(FluidSurfaceKernel k) => m_Counts == null ? 0 : m_Counts[(int)k];

            public void SetConstants(in FluidSurfaceConstants constants) { }

            public void BindDepth(FluidSurfaceKernel kernel, FluidSurfaceDepthSlot slot, FluidSurfaceBuffer buffer)
            {
                if (kernel == FluidSurfaceKernel.Composite)
                    CompositeDepth = buffer;
            }

            public void Dispatch(FluidSurfaceKernel kernel, int groupsX, int groupsY)
            {
                if (m_Counts == null)
                {
                    m_Counts = new int[Enum.GetValues(typeof(FluidSurfaceKernel)).Length];
                    MinGroups = int.MaxValue;
                }
                m_Counts[(int)kernel]++;
                MinGroups = Math.Min(MinGroups, Math.Min(groupsX, groupsY));
            }
        }
    }
}
