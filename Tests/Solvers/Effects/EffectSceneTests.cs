using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// The effect study (EffectCost): an effect a scene lacks runs nothing, every timed frame is the same frame, colliders far
    /// from the water change none of its bits, and the summary prices each effect as with − without.
    /// </summary>
    public class EffectSceneTests
    {
        static EffectCostSuite.Case CaseOf(string effect)
        {
            foreach (EffectCostSuite.Case c in EffectCostSuite.Cases)
                if (c.Effect == effect)
                    return c;
            throw new ArgumentException(effect);
        }

        [TestCase(EffectNames.ShapeMatchingBody)]
        [TestCase(EffectNames.MassSpringBody)]
        [TestCase(EffectNames.FemBody)]
        [TestCase(EffectNames.Fluid)]
        public void AbsentMethodOrFluid_RunsNoStep(string effect)
        {
            EffectCostSuite.Case c = CaseOf(effect);
            EffectScene without = c.Build(false), with = c.Build(true);
            without.Start(3);
            with.Start(3);
            without.Step();
            with.Step();
            Assert.That(without.BodySteps + without.FluidSubsteps, Is.Zero, "nothing of the effect runs without it");
            Assert.That(without.ParticleCount, Is.Zero);
            Assert.That(with.BodySteps + with.FluidSubsteps, Is.GreaterThanOrEqualTo(4), "one step per frame with it (fluid: ≥ 1 substep)");
        }

        [Test]
        public void FluidPassList_HasTheCollidePassOnlyWithColliders()
        {
            var c = new FluidConstants(FluidParameters.Default);
            var passes = new FluidPass[FluidSubstepPasses.MaxPasses];
            int without = FluidSubstepPasses.Write(c, 1f / 600f, false, passes);
            Assert.That(Array.IndexOf(passes, FluidPass.Collide, 0, without), Is.EqualTo(-1));
            int with = FluidSubstepPasses.Write(c, 1f / 600f, true, passes);
            Assert.That(with, Is.EqualTo(without + 1));
            Assert.That(passes[with - 1], Is.EqualTo(FluidPass.Collide));
        }

        [TestCase(EffectNames.ShapeMatchingBody)]
        [TestCase(EffectNames.Plasticity)]
        [TestCase(EffectNames.Fluid)]
        public void EveryTimedFrame_StartsFromTheSameState(string effect)
        {
            EffectScene scene = CaseOf(effect).Build(true);
            scene.Start(5);
            scene.Step();
            float3[] first = Snapshot(scene);
            scene.Step();
            scene.Step();
            Assert.That(Snapshot(scene), Is.EqualTo(first), "the third timed frame ends where the first did, bit for bit");
        }

        static float3[] Snapshot(EffectScene scene)
        {
            var all = new List<float3>();
            foreach (IMethodBody b in scene.Bodies)
                all.AddRange(b.Positions);
            if (scene.Fluid != null)
                all.AddRange(new ReadOnlySpan<float3>(scene.Fluid.Positions, 0, scene.Fluid.Status.Count).ToArray());
            return all.ToArray();
        }

        [Test]
        public void CollidersOutOfTheWatersReach_ChangeNoneOfItsBits()
        {
            // The fluid-collider scene hangs its colliders more than 16 cm (four kernel radii) above the resting water: no
            // particle comes within a kernel radius of them, so the boundary terms and the contact pass must leave every bit
            // as the scene without them, through the settling and the timed frame.
            EffectCostSuite.Case c = CaseOf(EffectNames.FluidCollidersOutOfReach);
            EffectScene with = c.Build(true), without = c.Build(false);
            for (int f = 0; f < c.StartFrames + 10; f++)
            {
                with.Step();
                without.Step();
            }
            Assert.That(with.Colliders.Length, Is.EqualTo(3));
            Assert.That(without.Colliders.Length, Is.Zero);
            Assert.That(Snapshot(with), Is.EqualTo(Snapshot(without)));
        }

        [Test]
        public void SubmergedColliders_AreTimedOnTheSameParticlesWithAndWithoutThem()
        {
            EffectCostSuite.Case c = CaseOf(EffectNames.FluidColliders);
            EffectScene with = c.Build(true), without = c.Build(false);
            Assert.That(with.Colliders.Length, Is.EqualTo(3));
            Assert.That(without.Colliders.Length, Is.Zero);
            Assert.That(with.ParticleCount, Is.EqualTo(without.ParticleCount));
            Assert.That(Snapshot(with), Is.EqualTo(Snapshot(without)), "the same particles");
            // The colliders' volume is left empty: 12³ = 1728 lattice points less the few hundred inside the three solids
            // (and within the wall distance around them).
            Assert.That(with.ParticleCount, Is.InRange(1000, 1628));
            foreach (float3 x in Snapshot(with))
            foreach (ColliderShape shape in with.Colliders)
                Assert.That(ParticleCollision.Penetration(shape, x, with.FluidConstants.WallDistance, out _, out _), Is.False);
        }

        [Test]
        public void Findings_PriceEachEffectAsWithMinusWithout()
        {
            var rows = new List<ScenarioOutcome>();
            foreach (EffectCostSuite.Case c in EffectCostSuite.Cases)
                rows.Add(new ScenarioOutcome(c.Effect, 4.75e6, new[]
                {
                    new Metric(EffectScenario.WithMs, 3.5, MetricUnit.Millisecond),
                    new Metric(EffectScenario.WithoutMs, 1.25, MetricUnit.Millisecond),
                }, 512, 1));
            var effects = new List<string>();
            foreach (Finding f in new EffectCostSuite().Findings(rows, RunScope.Standard))
            {
                var e = (EffectFinding)f;
                effects.Add(e.Effect);
                StringAssert.StartsWith("+2.25 ms per frame (with 3.5 ms, without 1.25 ms; 512 particles", e.Cost);
            }
            var expected = new List<string>();
            foreach (EffectCostSuite.Case c in EffectCostSuite.Cases)
                expected.Add(c.Effect);
            Assert.That(effects, Is.EqualTo(expected), "one line per effect, in order");
            Assert.That(EffectCostSuite.CostText(1.0, 1.2, 100, "x"), Does.StartWith("no cost above the timing noise (-0.2 ms per frame)"));
        }

        [Test]
        public void Fastest_LeavesOutTheWarmupPairs()
        {
            Assert.That(EffectScenario.Fastest(new List<double> { 0.5, 0.7, 3, 1, 2 }), Is.EqualTo(1));
            Assert.That(EffectScenario.Fastest(new List<double> { 7, 9 }), Is.EqualTo(7), "too few pairs: all of them");
            Assert.That(EffectScenario.Fastest(new List<double>()), Is.NaN);
        }
    }
}
