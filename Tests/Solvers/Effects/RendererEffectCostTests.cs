using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// The renderer's effect rows (EffectCostRenderer): the frame without a pass dispatches exactly that pass's kernels
    /// fewer, a frame with no fluid dispatches nothing, and the summary prices each row as with − without next to its
    /// counted traffic at 1920 × 1080.
    /// </summary>
    public class RendererEffectCostTests
    {
        static RendererEffectCostSuite.Case CaseOf(string effect)
        {
            foreach (RendererEffectCostSuite.Case c in RendererEffectCostSuite.Cases)
                if (c.Effect == effect)
                    return c;
            throw new ArgumentException(effect);
        }

        [Test]
        public void AbsentRenderer_DispatchesNothing()
        {
            RendererEffectCostSuite.Case c = CaseOf(EffectNames.FluidRenderer);
            Assert.That(c.Build(false), Is.Null, "no fluid to draw: the URP pass records no compute pass for it");
            FluidSurfaceCpuFrame with = c.Build(true);
            with.Render();
            Assert.That(with.Dispatches, Is.EqualTo(with.Passes.TotalDispatches));
        }

        [TestCase(EffectNames.RendererSmoothing, FluidSurfaceStage.Smoothing)]
        [TestCase(EffectNames.RendererThickness, FluidSurfaceStage.ThicknessSplat)]
        [TestCase(EffectNames.RendererNormals, FluidSurfaceStage.Normals)]
        public void AbsentPass_IsNotDispatched(string effect, FluidSurfaceStage stage)
        {
            RendererEffectCostSuite.Case c = CaseOf(effect);
            FluidSurfaceCpuFrame with = c.Build(true), without = c.Build(false);
            with.Render();
            without.Render();
            Assert.That(with.Passes.Has(stage), Is.True);
            Assert.That(without.Passes.Has(stage), Is.False);
            Assert.That(without.Passes.Dispatches(stage), Is.Zero);
            Assert.That(with.Dispatches - without.Dispatches, Is.EqualTo(with.Passes.Dispatches(stage)), "exactly the pass's dispatches fewer");
            for (var s = FluidSurfaceStage.TileLists; s <= FluidSurfaceStage.Overlay; s++)
                if (s != stage)
                    Assert.That(without.Passes.Dispatches(s), Is.EqualTo(with.Passes.Dispatches(s)), $"{s} is in both frames");
        }

        [Test]
        public void HalfResolutionTier_RunsTheSamePassesOnFewerPixels()
        {
            RendererEffectCostSuite.Case c = CaseOf(EffectNames.RendererFullResolution);
            FluidSurfaceCpuFrame full = c.Build(true), half = c.Build(false);
            Assert.That(half.Passes.TotalDispatches, Is.EqualTo(full.Passes.TotalDispatches));
            Assert.That(half.DepthA.Length * 4, Is.InRange(full.DepthA.Length, full.DepthA.Length + 2 * (full.Targets.Depth.x + full.Targets.Depth.y) + 4));
            Assert.That(FluidSurfaceCost.BytesPerPixel(half.Passes), Is.LessThan(FluidSurfaceCost.BytesPerPixel(full.Passes)));
        }

        [Test]
        public void Scenario_ReportsThePassAloneOnlyWhenTheListsDiffer()
        {
            var smoothing = new RendererEffectScenario(CaseOf(EffectNames.RendererSmoothing), 3);
            var tier = new RendererEffectScenario(CaseOf(EffectNames.RendererFullResolution), 3);
            foreach (RendererEffectScenario scenario in new[] { smoothing, tier })
            {
                scenario.Setup();
                for (int i = 0; i < 3; i++)
                    scenario.Step();
            }
            var m = new ScenarioOutcome("s", 0, smoothing.Evaluate());
            Assert.That(m.Value(RendererEffectScenario.PassMs), Is.GreaterThan(0).And.LessThan(m.Value(EffectScenario.WithMs)));
            Assert.That(m.Value(RendererEffectScenario.DispatchesWith) - m.Value(RendererEffectScenario.DispatchesWithout), Is.EqualTo(2));
            Assert.That(m.Value(RendererEffectScenario.BytesWith) - m.Value(RendererEffectScenario.BytesWithout), Is.EqualTo(2 * 2 * FluidSurfaceCost.DepthBytes));
            Assert.That(new ScenarioOutcome("t", 0, tier.Evaluate()).Value(RendererEffectScenario.PassMs), Is.NaN, "the same kernels: no pass to time alone");
        }

        [Test]
        public void Findings_PriceEachRowAsWithMinusWithoutAndCountTheBytesOfAFullHdFrame()
        {
            var rows = new List<ScenarioOutcome>();
            foreach (RendererEffectCostSuite.Case c in RendererEffectCostSuite.Cases)
                rows.Add(new ScenarioOutcome(c.Effect, 4.75e6, new[]
                {
                    new Metric(EffectScenario.WithMs, 3.5, MetricUnit.Millisecond),
                    new Metric(EffectScenario.WithoutMs, 1.25, MetricUnit.Millisecond),
                    new Metric(RendererEffectScenario.PassMs, 2, MetricUnit.Millisecond),
                    new Metric(RendererEffectScenario.BytesWith, 72, MetricUnit.Dimensionless),
                    new Metric(RendererEffectScenario.BytesWithout, 56, MetricUnit.Dimensionless),
                }, 515, 1));
            var effects = new List<string>();
            foreach (Finding f in new RendererEffectCostSuite().Findings(rows, RunScope.Standard))
            {
                var e = (EffectFinding)f;
                effects.Add(e.Effect);
                StringAssert.StartsWith("+2.25 ms per frame (with 3.5 ms, without 1.25 ms; 515 particles: C# reference passes on the CPU", e.Cost);
                StringAssert.Contains("not a GPU time", e.Cost);
                StringAssert.Contains("its passes alone take 2 ms", e.Cost);
                // 16 B/px × 1920 × 1080 = 33.2 MB.
                StringAssert.EndsWith("counted traffic of a 1920 × 1080 frame: +33.2 MB (+16 B/px)", e.Cost);
            }
            var expected = new List<string>();
            foreach (RendererEffectCostSuite.Case c in RendererEffectCostSuite.Cases)
                expected.Add(c.Effect);
            Assert.That(effects, Is.EqualTo(expected), "one line per row, in order");
        }

        [Test]
        public void QuickRun_KeepsTheWholeRendererAndSmoothing()
        {
            var quick = new List<string>();
            foreach (IScenario s in new RendererEffectCostSuite().Scenarios(RunScope.Quick))
                quick.Add(s.Method);
            Assert.That(quick, Is.EqualTo(new[] { EffectNames.FluidRenderer, EffectNames.RendererSmoothing }));
            int standard = 0;
            foreach (IScenario _ in new RendererEffectCostSuite().Scenarios(RunScope.Standard))
                standard++;
            Assert.That(standard, Is.EqualTo(RendererEffectCostSuite.Cases.Count));
        }
    }
}
