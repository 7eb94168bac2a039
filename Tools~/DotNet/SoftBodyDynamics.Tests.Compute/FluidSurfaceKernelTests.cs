using System;
using System.Linq;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Lavapipe;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using static SoftBodyDynamics.Tests.Compute.SurfaceScenes;

namespace SoftBodyDynamics.Tests.Compute
{
    /// <summary>
    /// The fluid surface kernels on lavapipe against their C# reference (FluidSurfacePasses, FluidSurfaceComposite) and
    /// against float64 ray casts of the same particles. Each stage is compared from the same input: the C# filter runs on
    /// the kernels' raw depth, the C# normals on their smoothed depth, the C# composite on their targets.
    /// </summary>
    public class FluidSurfaceKernelTests
    {
        /// <summary>
        /// Share of pixels allowed outside a round-off bound: where a threshold (a sample exactly μ behind, two equal
        /// one-sided steps, a floor() at a pixel edge) falls within round-off of its boundary, float32 evaluations may
        /// take different branches. Such pixels are a set of measure zero; one in a thousand is far above what occurs.
        /// </summary>
        const double BranchShare = 1e-3;

        static FluidSurfaceSettings Settings(FluidSurfaceScene scene, FluidSurfaceFilter filter, int iterations, int divisor = 1)
        {
            FluidSurfaceSettings s = divisor == 1 ? FluidSurfaceSettings.Desktop(scene.Radius) : FluidSurfaceSettings.Mobile(scene.Radius);
            s.Filter = filter;
            s.Iterations = iterations;
            return s;
        }

        /// <summary>Angle between two unit vectors in float64, atan2(|a × b|, a · b): no acos round-off near 0°.</summary>
        static double AngleDegrees(float3 a, float3 b)
        {
            double cx = (double)a.y * b.z - (double)a.z * b.y, cy = (double)a.z * b.x - (double)a.x * b.z, cz = (double)a.x * b.y - (double)a.y * b.x;
            double dot = (double)a.x * b.x + (double)a.y * b.y + (double)a.z * b.z;
            return Math.Atan2(Math.Sqrt(cx * cx + cy * cy + cz * cz), dot) * 180 / Math.PI;
        }

        [Test]
        public void SurfacePragmas_AreTheKernelEnumInOrder()
        {
            var pragmas = KernelCompiler.Kernels(LavapipeFluidSurface.ComputePath()).Select(k => k.Name).ToArray();
            Assert.That(pragmas, Is.EqualTo(Enum.GetNames(typeof(FluidSurfaceKernel))));
        }

        [Test]
        public void SurfaceKernels_ReadTheirConstantsFromTheConstantBufferOnly()
        {
            LavapipeComputeShader shader = Lavapipe.Surface.Shader;
            for (int k = 0; k < shader.KernelCount; k++)
            {
                CompiledKernel kernel = shader.Compiled(k);
                Assert.That(kernel.GlobalOffsets.Keys, Is.Empty, $"{kernel.Name}: loose globals");
                Assert.That(kernel.ConstantBlocks.Keys, Is.EquivalentTo(new[] { FluidSurfaceConstants.BufferName }), $"{kernel.Name}: constant buffers");
            }
        }

        [Test]
        public void SurfaceBufferNames_AreTheKernelsBindings()
        {
            LavapipeComputeShader shader = Lavapipe.Surface.Shader;
            var bound = Enumerable.Range(0, shader.KernelCount).SelectMany(k => shader.Compiled(k).Bindings).Where(b => !b.Uniform)
                .Select(b => b.Name).Distinct().OrderBy(n => n).ToArray();
            // The buffer build's screen I/O (SBD_SCREEN_BUFFERS) adds the scene and fluid colour buffers.
            var named = FluidSurfaceLayout.BufferNames.Where(n => n != null).Concat(FluidSurfaceLayout.DepthSlotNames)
                .Concat(new[] { "_SceneColor", "_SceneEyeDepth", "_FluidColor" }).OrderBy(n => n).ToArray();
            Assert.That(bound, Is.EqualTo(named));
        }

        [Test]
        public void SurfaceThreadGroups_AreTheLayoutSizes()
        {
            LavapipeComputeShader shader = Lavapipe.Surface.Shader;
            for (int k = 0; k < shader.KernelCount; k++)
            {
                var size = shader.ThreadGroupSize(k);
                var kernel = (FluidSurfaceKernel)k;
                int3 expected = kernel switch
                {
                    FluidSurfaceKernel.CountTiles or FluidSurfaceKernel.BinParticles => new int3(FluidSurfaceLayout.ParticleGroup, 1, 1),
                    FluidSurfaceKernel.ClearTiles or FluidSurfaceKernel.ScanTiles => new int3(FluidSurfaceLayout.ScanGroup, 1, 1),
                    _ => new int3(FluidSurfaceLayout.TileGroup, FluidSurfaceLayout.TileGroup, 1),
                };
                Assert.That(new[] { size.x, size.y, size.z }, Is.EqualTo(new[] { expected.x, expected.y, expected.z }), kernel.ToString());
            }
        }

        [Test]
        public void SurfaceBuffers_PerKernelAreAtMostTheLayoutBound()
        {
            LavapipeComputeShader shader = Lavapipe.Surface.Shader;
            int most = 0;
            for (int k = 0; k < shader.KernelCount; k++)
                most = Math.Max(most, shader.Compiled(k).Bindings.Count(b => !b.Uniform));
            Assert.That(most, Is.EqualTo(FluidSurfaceLayout.MaxBuffersPerKernel), "FluidSurfaceDevice checks the device against this bound");
        }

        [Test]
        public void RawDepth_IsTheUnionOfSpheresToRoundOff([Values("sphere", "two-blobs", "dam-break")] string name)
        {
            FluidSurfaceScene scene = Get(name);
            FluidSurfaceSettings s = Settings(scene, FluidSurfaceFilter.None, 0);
            LavapipeFluidSurface.Frame f = Render(scene, s, FluidLook.Water);
            FluidSurfaceReference.Surface exact = FluidSurfaceReference.UnionOfSpheres(scene, 1);
            var cpu = new float[f.RawDepth.Length];
            FluidSurfacePasses.SplatDepth(f.Constants, scene.Particles, cpu);
            int covered = 0, mismatched = 0, beyond = 0;
            double worst = 0;
            for (int y = 0; y < f.Targets.Depth.y; y++)
                for (int x = 0; x < f.Targets.Depth.x; x++)
                {
                    int i = y * f.Targets.Depth.x + x;
                    bool g = f.RawDepth[i] > 0f, e = exact.Depth[i] > 0;
                    if (g || e) covered++;
                    if (g != e || g != cpu[i] > 0f) { mismatched++; continue; }
                    if (!g) continue;
                    double h = FluidSurfaceReference.PixelHits(scene, scene.Camera.Pinhole(s.DepthDivisor), x, y).NearestHalfChord;
                    double bound = HitTolerance(exact.Depth[i], scene.Radius, h);
                    double d = Math.Max(Math.Abs(f.RawDepth[i] - exact.Depth[i]), Math.Abs(f.RawDepth[i] - cpu[i]) / 2);
                    worst = Math.Max(worst, d / bound);
                    if (d > bound) beyond++;
                }
            TestContext.Progress.WriteLine($"{name}: {covered} covered pixels, {mismatched} with a grazing hit on one side only, worst |Δz| {worst:P1} of its bound, {beyond} beyond");
            Assert.That(covered, Is.GreaterThan(100), "the scene must put fluid on screen");
            Assert.That(beyond, Is.Zero, "depth outside the float32 bound of the ray-sphere hit");
            Assert.That(mismatched, Is.LessThanOrEqualTo(Math.Max(1, (int)(BranchShare * covered))), "coverage differs beyond grazing hits");
            Lavapipe.AssertValid();
        }

        [Test]
        public void Thickness_IsTheSummedChordsToTheQuantum([Values("sphere", "dam-break")] string name, [Values(1, 2)] int divisor)
        {
            FluidSurfaceScene scene = Get(name);
            FluidSurfaceSettings s = Settings(scene, FluidSurfaceFilter.None, 0, divisor);
            LavapipeFluidSurface.Frame f = Render(scene, s, FluidLook.Water);
            double[] exact = FluidSurfaceReference.Thickness(scene, FluidSurfaceSettings.ThicknessDivisor);
            var cpu = new float2[f.Thickness.Length];
            FluidSurfacePasses.SplatThickness(f.Constants, scene.Particles, cpu);
            double quantum = f.Constants.ThicknessQuantum;
            int covered = 0;
            for (int y = 0; y < f.Targets.Thickness.y; y++)
                for (int x = 0; x < f.Targets.Thickness.x; x++)
                {
                    int i = y * f.Targets.Thickness.x + x;
                    int hits = FluidSurfaceReference.PixelHits(scene, scene.Camera.Pinhole(FluidSurfaceSettings.ThicknessDivisor), x, y).Hits;
                    if (hits > 0) covered++;
                    // Per chord: half a quantum of rounding, and at most 4√ε·r of float32 error (2·min(h, 4ε r²/h)).
                    double bound = hits * (quantum / 2 + 4 * Math.Sqrt(Epsilon) * scene.Radius) + 1e-9;
                    Assert.That(Math.Abs(f.Thickness[i].x - exact[i]), Is.LessThanOrEqualTo(bound), $"thickness at ({x}, {y}), {hits} chords");
                    Assert.That(Math.Abs(f.Thickness[i].x - cpu[i].x), Is.LessThanOrEqualTo(2 * bound), $"thickness vs C# at ({x}, {y})");
                    Assert.That(f.Thickness[i].y, Is.InRange(0f, 1f));
                }
            Assert.That(covered, Is.GreaterThan(50));
            Lavapipe.AssertValid();
        }

        [Test]
        public void TileLists_GrowAndGiveTheSamePicture()
        {
            FluidSurfaceScene scene = Get("dam-break");
            FluidSurfaceSettings s = Settings(scene, FluidSurfaceFilter.NarrowRange, 2);
            LavapipeFluidSurface.Frame big = Render(scene, s, FluidLook.Water);
            using var small = new LavapipeFluidSurface(Lavapipe.Device, initialTileCapacity: 8);
            LavapipeFluidSurface.Frame grown = small.Render(scene.Camera, s, FluidLook.Water, scene.Lighting, scene.Particles, scene.SceneColour, scene.SceneEyeDepth);
            int needed = FluidSurfacePasses.TileEntries(big.Constants, scene.Particles);
            Assert.That(big.Stats[FluidSurfaceLayout.StatEntries], Is.EqualTo(needed), "tile entries vs the C# count");
            Assert.That(big.Stats[FluidSurfaceLayout.StatDrawn], Is.EqualTo(scene.Particles.Length));
            Assert.That(small.Regrowths, Is.EqualTo(1));
            Assert.That(small.TileCapacity, Is.GreaterThanOrEqualTo(needed));
            Assert.That(grown.Stats[FluidSurfaceLayout.StatDropped], Is.Zero);
            // The lists are filled in a different order (atomics), the pixels do not depend on it.
            Assert.That(grown.Depth, Is.EqualTo(big.Depth));
            Assert.That(grown.Thickness, Is.EqualTo(big.Thickness));
            Assert.That(grown.Colour, Is.EqualTo(big.Colour));
            Lavapipe.AssertValid();
        }

        [Test]
        public void TileLists_CountWhatDoesNotFit()
        {
            FluidSurfaceScene scene = Get("sphere");
            FluidSurfaceSettings s = Settings(scene, FluidSurfaceFilter.None, 0);
            using var tiny = new LavapipeFluidSurface(Lavapipe.Device, initialTileCapacity: 8) { GrowTileLists = false };
            LavapipeFluidSurface.Frame f = tiny.Render(scene.Camera, s, FluidLook.Water, scene.Lighting, scene.Particles, scene.SceneColour, scene.SceneEyeDepth);
            Assert.That(f.Stats[FluidSurfaceLayout.StatDropped], Is.EqualTo(f.Stats[FluidSurfaceLayout.StatEntries] - 8));
            Assert.That(f.RawDepth.All(z => z >= 0f && float.IsFinite(z)));
            Lavapipe.AssertValid();
        }

        [Test]
        public void Render_IsTheSameBitsEveryTime()
        {
            FluidSurfaceScene scene = Get("two-blobs");
            FluidSurfaceSettings s = Settings(scene, FluidSurfaceFilter.CurvatureFlow, 5);
            LavapipeFluidSurface.Frame a = Render(scene, s, FluidLook.Honey), b = Render(scene, s, FluidLook.Honey);
            Assert.That(b.Colour, Is.EqualTo(a.Colour));
            Assert.That(b.Normals, Is.EqualTo(a.Normals));
        }

        [Test]
        public void Filter_MatchesTheCSharpReference([Values] FluidSurfaceFilter filter)
        {
            FluidSurfaceScene scene = Get("dam-break");
            int iterations = filter == FluidSurfaceFilter.CurvatureFlow ? 10 : 2;
            FluidSurfaceSettings s = Settings(scene, filter, iterations);
            LavapipeFluidSurface.Frame f = Render(scene, s, FluidLook.Water);
            float[] a = (float[])f.RawDepth.Clone(), b = new float[a.Length];
            FluidSurfacePasses.Smooth(f.Constants, s, a, b);
            float[] cpu = FluidSurfaceFrame.SmoothedDepth(FluidSurfacePassList.Of(s, FluidLook.Water)) == FluidSurfaceBuffer.DepthA ? a : b;
            if (filter == FluidSurfaceFilter.None)
                cpu = f.RawDepth;
            // Separable pass: a weighted mean of m ≤ 2·32 + 1 samples, m + 2 roundings plus the weights' exp (3 + 2|x| ulp,
            // |x| ≤ 2): (m + 10)·ε relative, times 4. Curvature flow: a stable explicit step adds about λ·8ε z of rounding
            // to the Laplacian and 8ε z elsewhere: 16ε z per step, times 2.
            int m = 2 * s.MaxFilterPixels + 1;
            double perPass = filter == FluidSurfaceFilter.CurvatureFlow ? 32 * Epsilon : 4 * (m + 10) * Epsilon;
            int passes = filter == FluidSurfaceFilter.CurvatureFlow ? iterations : 2 * iterations;
            int covered = 0, beyond = 0;
            for (int i = 0; i < cpu.Length; i++)
            {
                Assert.That(f.Depth[i] > 0f, Is.EqualTo(cpu[i] > 0f), "smoothing must not change coverage");
                if (cpu[i] <= 0f)
                    continue;
                covered++;
                if (Math.Abs(f.Depth[i] - cpu[i]) > passes * perPass * cpu[i])
                    beyond++;
            }
            TestContext.Progress.WriteLine($"{filter}: {covered} pixels, {beyond} beyond {passes} × {perPass:E1} relative");
            Assert.That(beyond, Is.LessThanOrEqualTo((int)(BranchShare * covered)));
            Lavapipe.AssertValid();
        }

        [Test]
        public void Normals_MatchTheCSharpReference()
        {
            FluidSurfaceScene scene = Get("two-blobs");
            FluidSurfaceSettings s = Settings(scene, FluidSurfaceFilter.NarrowRange, 2);
            LavapipeFluidSurface.Frame f = Render(scene, s, FluidLook.Water);
            var cpu = new uint[f.Normals.Length];
            FluidSurfacePasses.Normals(f.Constants, f.Depth, cpu);
            // Packing: 16-bit octahedral, under 0.004°; the tangents are differences of positions a pixel apart, whose
            // relative round-off is about ε·f (f the focal length in pixels): together under 0.01°.
            int covered = 0, beyond = 0;
            for (int i = 0; i < cpu.Length; i++)
            {
                if (f.Depth[i] <= 0f)
                    continue;
                covered++;
                float3 a = FluidSurfacePasses.UnpackNormal(f.Normals[i]), b = FluidSurfacePasses.UnpackNormal(cpu[i]);
                double angle = AngleDegrees(a, b);
                if (angle > 0.01) beyond++;
            }
            Assert.That(covered, Is.GreaterThan(100));
            Assert.That(beyond, Is.LessThanOrEqualTo((int)(BranchShare * covered)));
            Lavapipe.AssertValid();
        }

        [Test]
        public void Composite_MatchesTheCSharpReference([Values(0, 1, 2, 3, 4, 5, 6, 7)] int preset, [Values(1, 2)] int divisor)
        {
            FluidSurfaceScene scene = Get("two-blobs");
            var (name, look) = FluidLook.Presets[preset];
            FluidSurfaceSettings s = Settings(scene, FluidSurfaceFilter.NarrowRange, 1, divisor);
            LavapipeFluidSurface.Frame f = Render(scene, s, look);
            var cpu = new float4[f.Colour.Length];
            FluidSurfaceComposite.Composite(f.Constants, new FluidSurfaceComposite.Inputs(f.Depth, f.Normals, f.Thickness, scene.SceneColour, scene.SceneEyeDepth), cpu);
            // Each channel: a handful of products and sums of values up to the emission (≤ 6), pow(x, ≤ 1200) whose
            // relative error is the exponent times x's (1200 · 4ε ≈ 3e-4), and exp: 1e-3 · (1 + |c|) covers them.
            int covered = 0, beyond = 0;
            for (int i = 0; i < cpu.Length; i++)
            {
                Assert.That(f.Colour[i].w, Is.EqualTo(cpu[i].w), "coverage is decided by the same depths");
                if (cpu[i].w == 0f)
                    continue;
                covered++;
                float4 d = f.Colour[i] - cpu[i];
                double worst = Math.Max(Math.Abs(d.x) / (1 + Math.Abs(cpu[i].x)), Math.Max(Math.Abs(d.y) / (1 + Math.Abs(cpu[i].y)), Math.Abs(d.z) / (1 + Math.Abs(cpu[i].z))));
                if (worst > 1e-3 || !float.IsFinite(f.Colour[i].x + f.Colour[i].y + f.Colour[i].z)) beyond++;
            }
            TestContext.Progress.WriteLine($"{name}, divisor {divisor}: {covered} fluid pixels, {beyond} beyond the bound");
            Assert.That(f.Colour.Length, Is.EqualTo(f.Targets.Composite.x * f.Targets.Composite.y));
            Assert.That(covered, Is.GreaterThan(100 / (divisor * divisor)));
            Assert.That(beyond, Is.LessThanOrEqualTo((int)(BranchShare * covered)));
            Lavapipe.AssertValid();
        }

        [Test]
        public void Frame_DispatchesThePassListOfItsLook([Values(0, 5, 6, 7)] int preset)
        {
            FluidSurfaceScene scene = Get("two-blobs");
            var (name, look) = FluidLook.Presets[preset];
            FluidSurfaceSettings s = Settings(scene, FluidSurfaceFilter.NarrowRange, 1);
            LavapipeFluidSurface.Frame f = Render(scene, s, look);
            FluidSurfacePassList list = FluidSurfacePassList.Of(s, look);
            Assert.That(f.Passes, Is.EqualTo(list), name);
            Assert.That(f.Dispatches, Is.EqualTo(list.TotalDispatches), name);
        }

        [Test]
        public void Composite_ReadsNoThicknessWhenItsPassIsOff()
        {
            FluidSurfaceScene scene = Get("two-blobs");
            FluidLook clear = FluidLook.Water;
            clear.Refraction = 0f;
            clear.Absorption = float3.zero;
            FluidSurfaceSettings s = Settings(scene, FluidSurfaceFilter.NarrowRange, 1);
            Assert.That(FluidSurfacePassList.Of(s, clear).Thickness, Is.False);
            LavapipeFluidSurface.Frame f;
            Lavapipe.Surface.PoisonThickness = true;
            try
            {
                f = Render(scene, s, clear);
            }
            finally
            {
                Lavapipe.Surface.PoisonThickness = false;
            }
            // A read of the infinite thickness would make the colour NaN (e^(−0 · ∞)); NaN itself would not do: the
            // composite skips thickness texels that are not positive.
            Assert.That(float.IsPositiveInfinity(f.Thickness[0].x), Is.True, "no thickness splat ran over the poisoned target");
            int covered = 0;
            foreach (float4 c in f.Colour)
            {
                Assert.That(math.all(math.isfinite(c)), Is.True);
                covered += c.w > 0f ? 1 : 0;
            }
            Assert.That(covered, Is.GreaterThan(100));
            Lavapipe.AssertValid();
        }

        [Test]
        public void Composite_HidesFluidBehindOpaqueGeometry()
        {
            FluidSurfaceScene scene = Get("two-blobs");
            FluidSurfaceSettings s = Settings(scene, FluidSurfaceFilter.NarrowRange, 1);
            LavapipeFluidSurface.Frame f = Render(scene, s, FluidLook.Water);
            int hidden = 0, shown = 0;
            for (int i = 0; i < f.Colour.Length; i++)
            {
                float z = f.Depth[i];   // full-resolution depth: one depth pixel per screen pixel
                if (z <= 0f)
                    continue;
                if (scene.SceneEyeDepth[i] < z)
                {
                    hidden++;
                    Assert.That(f.Colour[i].w, Is.Zero, "fluid drawn over the post in front of it");
                }
                else
                {
                    shown++;
                    Assert.That(f.Colour[i].w, Is.EqualTo(1f));
                }
            }
            Assert.That(hidden, Is.GreaterThan(20), "the post must hide part of the fluid");
            Assert.That(shown, Is.GreaterThan(100));
        }

        [Test]
        public void Smoothing_BringsTheSurfaceTowardsTheMetaballReference([Values(FluidSurfaceFilter.NarrowRange, FluidSurfaceFilter.Bilateral, FluidSurfaceFilter.CurvatureFlow)] FluidSurfaceFilter filter)
        {
            FluidSurfaceScene scene = Get("sphere");
            FluidSurfaceReference.Surface metaball = FluidSurfaceReference.Metaball(scene, 1);
            LavapipeFluidSurface.Frame raw = Render(scene, Settings(scene, FluidSurfaceFilter.None, 0), FluidLook.Water);
            LavapipeFluidSurface.Frame smooth = Render(scene, Settings(scene, filter, filter == FluidSurfaceFilter.CurvatureFlow ? 20 : 2), FluidLook.Water);
            var e0 = FluidSurfaceReference.Compare(metaball, raw.Depth, raw.Normals, scene.Radius);
            var e1 = FluidSurfaceReference.Compare(metaball, smooth.Depth, smooth.Normals, scene.Radius);
            TestContext.Progress.WriteLine($"{filter}: normal error {e0.MeanAngle:F1}° → {e1.MeanAngle:F1}°, depth error {e0.MeanDepth:F3} → {e1.MeanDepth:F3} r");
            Assert.That(e1.MeanAngle, Is.LessThan(e0.MeanAngle), "smoothing must bring the normals closer to the smooth surface");
        }

        [Test]
        public void HalfResolution_CoversTheSameSilhouetteWithinTwoPixels()
        {
            FluidSurfaceScene scene = Get("sphere");
            LavapipeFluidSurface.Frame full = Render(scene, Settings(scene, FluidSurfaceFilter.NarrowRange, 1, 1), FluidLook.Water);
            LavapipeFluidSurface.Frame half = Render(scene, Settings(scene, FluidSurfaceFilter.NarrowRange, 1, 2), FluidLook.Water);
            Assert.That(half.Targets.Depth.x, Is.EqualTo((Width + 1) / 2));
            Assert.That(half.Targets.Depth.y, Is.EqualTo((Height + 1) / 2));
            Assert.That(half.Targets.Composite.x, Is.EqualTo((Width + 1) / 2), "the mobile tier composites at half resolution");
            // A half-resolution composite pixel c stands for screen pixels 2c and 2c + 1 each way and samples the depth
            // under its centre, so its coverage may differ from the full-resolution one at 2c + 1 only within two
            // screen pixels of the full-resolution silhouette.
            int edge = 0, compared = 0;
            for (int cy = 0; cy < half.Targets.Composite.y; cy++)
                for (int cx = 0; cx < half.Targets.Composite.x; cx++)
                {
                    int x = Math.Min(2 * cx + 1, Width - 1), y = Math.Min(2 * cy + 1, Height - 1);
                    bool a = full.Colour[y * Width + x].w > 0f;
                    bool nearEdge = false;
                    for (int dy = -2; dy <= 2 && !nearEdge; dy++)
                        for (int dx = -2; dx <= 2; dx++)
                        {
                            int qx = x + dx, qy = y + dy;
                            if (qx >= 0 && qy >= 0 && qx < Width && qy < Height && (full.Colour[qy * Width + qx].w > 0f) != a)
                                nearEdge = true;
                        }
                    if (nearEdge) edge++;
                    compared++;
                    if (a != half.Colour[cy * half.Targets.Composite.x + cx].w > 0f)
                        Assert.That(nearEdge, $"coverage differs at composite pixel ({cx}, {cy}), away from the silhouette");
                }
            Assert.That(edge, Is.GreaterThan(0));
            Assert.That(compared, Is.EqualTo(half.Colour.Length));
        }

        [Test]
        public void NonFiniteAndNearParticles_AreNotDrawn()
        {
            FluidSurfaceScene scene = Get("sphere");
            float3 eye = -math.mul(math.transpose(scene.Camera.Rotation), scene.Camera.Translation);
            var particles = scene.Particles.Concat(new[]
            {
                new float4(float.NaN, 0.1f, 0f, 1000f),
                new float4(float.PositiveInfinity, 0.1f, 0f, 1000f),
                new float4(eye, 1000f),                         // around the eye: crosses the near plane
                new float4(eye + new float3(0f, 0f, 1f), 1000f), // behind the camera
            }).ToArray();
            FluidSurfaceSettings s = Settings(scene, FluidSurfaceFilter.NarrowRange, 2);
            LavapipeFluidSurface.Frame f = Lavapipe.Surface.Render(scene.Camera, s, FluidLook.Lava, scene.Lighting, particles, scene.SceneColour, scene.SceneEyeDepth);
            Assert.That(f.Stats[FluidSurfaceLayout.StatDrawn], Is.EqualTo(scene.Particles.Length));
            Assert.That(f.Depth.All(float.IsFinite) && f.Thickness.All(t => float.IsFinite(t.x) && float.IsFinite(t.y)));
            Assert.That(f.Colour.All(c => float.IsFinite(c.x) && float.IsFinite(c.y) && float.IsFinite(c.z) && float.IsFinite(c.w)));
            Lavapipe.AssertValid();
        }

        [Test]
        public void NoParticles_DrawNothing()
        {
            FluidSurfaceScene scene = Get("sphere");
            FluidSurfaceSettings s = Settings(scene, FluidSurfaceFilter.Bilateral, 1);
            LavapipeFluidSurface.Frame f = Lavapipe.Surface.Render(scene.Camera, s, FluidLook.Water, scene.Lighting, ReadOnlySpan<float4>.Empty, scene.SceneColour, scene.SceneEyeDepth);
            Assert.That(f.Stats[FluidSurfaceLayout.StatEntries], Is.Zero);
            Assert.That(f.Colour.All(c => c.w == 0f));
            Lavapipe.AssertValid();
        }
    }
}
