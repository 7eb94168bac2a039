using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// The renderer's one pass list (FluidSurfacePassList): each optional pass is absent when its effect is off, the frame
    /// driver dispatches exactly the list, the cost table counts exactly the list, and the composite reads no target whose
    /// pass did not run.
    /// </summary>
    public class FluidSurfacePassListTests
    {
        static readonly FluidSurfaceFilter[] s_Filters =
            { FluidSurfaceFilter.None, FluidSurfaceFilter.NarrowRange, FluidSurfaceFilter.Bilateral, FluidSurfaceFilter.CurvatureFlow };

        /// <summary>Water with nothing that depends on thickness: no refraction, no absorption, no emission.</summary>
        internal static FluidLook ClearWater
        {
            get
            {
                FluidLook l = FluidLook.Water;
                l.Refraction = 0f;
                l.Absorption = float3.zero;
                l.Emission = float3.zero;
                return l;
            }
        }

        static FluidSurfaceSettings Settings(FluidSurfaceFilter filter, int iterations, bool mobile = false)
        {
            FluidSurfaceSettings s = mobile ? FluidSurfaceSettings.Mobile(0.02f) : FluidSurfaceSettings.Desktop(0.02f);
            s.Filter = filter;
            s.Iterations = iterations;
            return s;
        }

        /// <summary>Every look of interest: the presets and clear water.</summary>
        static IEnumerable<(string Name, FluidLook Look)> Looks()
        {
            foreach (var p in FluidLook.Presets)
                yield return p;
            yield return ("clear water", ClearWater);
        }

        [Test]
        public void Smoothing_IsAbsentWithTheFilterOffOrNoIterations()
        {
            FluidSurfacePassList off = FluidSurfacePassList.Of(Settings(FluidSurfaceFilter.None, 3), FluidLook.Water);
            FluidSurfacePassList none = FluidSurfacePassList.Of(Settings(FluidSurfaceFilter.NarrowRange, 0), FluidLook.Water);
            FluidSurfacePassList on = FluidSurfacePassList.Of(Settings(FluidSurfaceFilter.NarrowRange, 1), FluidLook.Water);
            Assert.That(off.Has(FluidSurfaceStage.Smoothing), Is.False);
            Assert.That(off.Iterations, Is.Zero, "a filter that is off has no iterations to record");
            Assert.That(none.Has(FluidSurfaceStage.Smoothing), Is.False);
            Assert.That(on.Has(FluidSurfaceStage.Smoothing), Is.True);
            Assert.That(on.SmoothingPasses, Is.EqualTo(2));
            Assert.That(FluidSurfacePassList.Of(Settings(FluidSurfaceFilter.CurvatureFlow, 5), FluidLook.Water).SmoothingPasses, Is.EqualTo(5));
        }

        [Test]
        public void Thickness_IsAbsentForLooksThatDoNotReadIt()
        {
            Assert.That(FluidSurfacePassList.ReadsThickness(FluidLook.FlatColour), Is.False);
            Assert.That(FluidSurfacePassList.ReadsThickness(FluidLook.Toon), Is.False);
            Assert.That(FluidSurfacePassList.ReadsThickness(ClearWater), Is.False, "lit without refraction, absorption or emission");
            Assert.That(FluidSurfacePassList.ReadsThickness(FluidLook.ThicknessTint), Is.True);
            Assert.That(FluidSurfacePassList.ReadsThickness(FluidLook.Water), Is.True);
            Assert.That(FluidSurfacePassList.ReadsThickness(FluidLook.Lava), Is.True, "no refraction, but absorption and emission (the attribute rides on thickness)");
            FluidLook refracting = ClearWater, absorbing = ClearWater, glowing = ClearWater;
            refracting.Refraction = 0.1f;
            absorbing.Absorption = new float3(0f, 0f, 1f);
            glowing.Emission = new float3(1f, 0f, 0f);
            Assert.That(FluidSurfacePassList.ReadsThickness(refracting), Is.True);
            Assert.That(FluidSurfacePassList.ReadsThickness(absorbing), Is.True);
            Assert.That(FluidSurfacePassList.ReadsThickness(glowing), Is.True);
        }

        [Test]
        public void Normals_AreAbsentForLooksThatDoNotShadeWithThem()
        {
            Assert.That(FluidSurfacePassList.ReadsNormals(FluidLook.FlatColour), Is.False);
            Assert.That(FluidSurfacePassList.ReadsNormals(FluidLook.ThicknessTint), Is.False);
            Assert.That(FluidSurfacePassList.ReadsNormals(FluidLook.Toon), Is.True);
            Assert.That(FluidSurfacePassList.ReadsNormals(FluidLook.Water), Is.True);
        }

        [Test]
        public void FrameDriver_DispatchesExactlyTheList()
        {
            var camera = FluidSurfaceCamera.LookAt(new float3(0f, 0.3f, 0.5f), float3.zero, 100, 50, 40f);
            foreach (bool mobile in new[] { false, true })
            foreach (FluidSurfaceFilter filter in s_Filters)
            foreach (int iterations in new[] { 0, 1, 3 })
            foreach (var (name, look) in Looks())
            {
                FluidSurfaceSettings s = Settings(filter, iterations, mobile);
                FluidSurfacePassList list = FluidSurfacePassList.Of(s, look);
                var rec = new CountingRecorder();
                FluidSurfaceFrame.Record(ref rec, FluidSurfaceTargets.Of(camera, s), list, 10);
                string where = $"{(mobile ? "mobile" : "desktop")}, {filter} × {iterations}, {name}";
                Assert.That(rec.Total, Is.EqualTo(list.TotalDispatches), where);
                Assert.That(rec.Count(FluidSurfaceKernel.ClearTiles) + rec.Count(FluidSurfaceKernel.CountTiles) + rec.Count(FluidSurfaceKernel.ScanTiles)
                    + rec.Count(FluidSurfaceKernel.BinParticles), Is.EqualTo(list.Dispatches(FluidSurfaceStage.TileLists)), where);
                Assert.That(rec.Count(FluidSurfaceKernel.SplatDepth), Is.EqualTo(1), where);
                Assert.That(rec.Count(FluidSurfaceKernel.SplatThickness), Is.EqualTo(list.Dispatches(FluidSurfaceStage.ThicknessSplat)), where);
                Assert.That(rec.Count(FluidSurfaceKernel.NarrowRangeX) + rec.Count(FluidSurfaceKernel.NarrowRangeY) + rec.Count(FluidSurfaceKernel.BilateralX)
                    + rec.Count(FluidSurfaceKernel.BilateralY) + rec.Count(FluidSurfaceKernel.CurvatureFlow), Is.EqualTo(list.Dispatches(FluidSurfaceStage.Smoothing)), where);
                Assert.That(rec.Count(FluidSurfaceKernel.Normals), Is.EqualTo(list.Dispatches(FluidSurfaceStage.Normals)), where);
                Assert.That(rec.Count(FluidSurfaceKernel.Composite), Is.EqualTo(1), where);
                // The optional passes follow the settings and the look, not the other way round.
                Assert.That(list.Has(FluidSurfaceStage.ThicknessSplat), Is.EqualTo(FluidSurfacePassList.ReadsThickness(look)), where);
                Assert.That(list.Has(FluidSurfaceStage.Normals), Is.EqualTo(FluidSurfacePassList.ReadsNormals(look)), where);
                Assert.That(list.Has(FluidSurfaceStage.Smoothing), Is.EqualTo(filter != FluidSurfaceFilter.None && iterations > 0), where);
            }
        }

        [Test]
        public void Cost_CountsExactlyThePassesOfTheList()
        {
            foreach (FluidSurfaceFilter filter in s_Filters)
            foreach (int iterations in new[] { 0, 2 })
            foreach (var (name, look) in Looks())
            {
                FluidSurfacePassList list = FluidSurfacePassList.Of(Settings(filter, iterations), look);
                var stages = new List<FluidSurfaceStage>();
                foreach (FluidSurfacePassCost p in FluidSurfaceCost.Passes(list))
                {
                    stages.Add(p.Stage);
                    Assert.That(p.BytesPerPixel, Is.GreaterThan(0), $"{name}: {p.Pass}");
                }
                var expected = new List<FluidSurfaceStage>();
                // Tile binning is counted per particle (BinningBytesPerParticle), not per pixel.
                for (var s = FluidSurfaceStage.DepthSplat; s <= FluidSurfaceStage.Overlay; s++)
                    if (list.Has(s))
                        expected.Add(s);
                Assert.That(stages, Is.EqualTo(expected), $"{filter} × {iterations}, {name}");
            }
        }

        [Test]
        public void Cost_OfALookWithoutThicknessOrNormalsDropsTheirPassesAndTheCompositeReads()
        {
            FluidSurfaceSettings s = FluidSurfaceSettings.Desktop(0.02f);
            double water = FluidSurfaceCost.BytesPerPixel(s, FluidLook.Water), clear = FluidSurfaceCost.BytesPerPixel(s, ClearWater);
            // The half-resolution thickness target: written by its splat (8 B / 4) and read once by the composite (8 B / 4).
            Assert.That(water - clear, Is.EqualTo(2.0 * FluidSurfaceCost.ThicknessBytes / 4).Within(1e-12));
            double toon = FluidSurfaceCost.BytesPerPixel(s, FluidLook.Toon), flat = FluidSurfaceCost.BytesPerPixel(s, FluidLook.FlatColour);
            // Normals read the depth and write a normal (4 + 4 B), the composite reads the normal (4 B).
            Assert.That(toon - flat, Is.EqualTo(FluidSurfaceCost.DepthBytes + 2.0 * FluidSurfaceCost.NormalBytes).Within(1e-12));
        }

        [Test]
        public void Constants_TellTheCompositeWhichTargetsTheListHas()
        {
            var camera = FluidSurfaceCamera.LookAt(new float3(0f, 0.3f, 0.5f), float3.zero, 64, 32, 40f);
            FluidSurfaceSettings s = FluidSurfaceSettings.Desktop(0.02f);
            foreach (var (name, look) in Looks())
            {
                FluidSurfaceConstants k = FluidSurfaceConstants.Of(camera, s, look, FluidSurfaceLighting.Default, 1, 1);
                FluidSurfacePassList list = FluidSurfacePassList.Of(s, look);
                Assert.That(k.PassFlags, Is.EqualTo(list.Flags), name);
                Assert.That((k.PassFlags & FluidSurfacePassList.ThicknessFlag) != 0, Is.EqualTo(list.Thickness), name);
                Assert.That((k.PassFlags & FluidSurfacePassList.NormalsFlag) != 0, Is.EqualTo(list.Normals), name);
            }
        }

        /// <summary>Counts each kernel's dispatches.</summary>
        struct CountingRecorder : IFluidSurfaceCommands
        {
            int[] m_Counts;
            public int Total;

            public int Count(FluidSurfaceKernel k) => m_Counts == null ? 0 : m_Counts[(int)k];

            public void SetConstants(in FluidSurfaceConstants constants) { }

            public void BindDepth(FluidSurfaceKernel kernel, FluidSurfaceDepthSlot slot, FluidSurfaceBuffer buffer) { }

            public void Dispatch(FluidSurfaceKernel kernel, int groupsX, int groupsY)
            {
                m_Counts ??= new int[Enum.GetValues(typeof(FluidSurfaceKernel)).Length];
                m_Counts[(int)kernel]++;
                Total++;
            }
        }
    }
}
