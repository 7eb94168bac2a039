using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The measures of the fluid study (FluidAccuracy, FluidThroughput): what they report on inputs with a known answer.</summary>
    public class FluidStudyMeasureTests
    {
        static FluidBuffers Points(IReadOnlyList<float3> points)
        {
            var b = new FluidBuffers(points.Count, new FluidGrid(new float3(-1f), new float3(1f), 0.1f));
            for (int i = 0; i < points.Count; i++)
                b.Positions[i] = points[i];
            b.Status.Count = points.Count;
            return b;
        }

        [Test]
        public void Sphericity_IsOneForASphereAndOneOverRootThreeForACube()
        {
            // 4000 points of a Fibonacci sphere of radius 0.1: neighbouring points are ≈ √(4π/4000) = 0.056 rad apart, so
            // the extreme point along any direction lies within that angle of it and every width is at least
            // 2R·cos(0.056) = 0.9984·2R: sphericity ≥ 0.998.
            var sphere = new List<float3>();
            double golden = Math.PI * (3 - Math.Sqrt(5));
            for (int k = 0; k < 4000; k++)
            {
                double z = 1 - (k + 0.5) * 2 / 4000, r = Math.Sqrt(1 - z * z);
                sphere.Add(0.1f * new float3((float)(r * Math.Cos(k * golden)), (float)(r * Math.Sin(k * golden)), (float)z));
            }
            Assert.That(DropletScenario.Sphericity(Points(sphere), 0f), Is.GreaterThan(0.998));

            // The corners of a cube: width along a face normal = edge, largest along a body diagonal = √3·edge, so 1/√3 = 0.577
            // for exact directions. The 100-direction set has one 0.3° off a face normal (width ≤ 1.005·edge) and one within 3°
            // of a body diagonal (width ≥ √3·cos 3°·edge): the ratio lies in [1/√3, 1.005/(√3·cos 3°)] = [0.5774, 0.5810].
            var cube = new List<float3>();
            for (int i = 0; i < 8; i++)
                cube.Add(new float3(i & 1, (i >> 1) & 1, (i >> 2) & 1) * 0.1f);
            Assert.That(DropletScenario.Sphericity(Points(cube), 0f), Is.InRange(1 / Math.Sqrt(3), 1.005 / (Math.Sqrt(3) * Math.Cos(3 * Math.PI / 180))));
        }

        [Test]
        public void HeightAtWall_IsTheTopOfTheBulkNearTheWallPlusHalfASpacing()
        {
            // A column x ∈ {0.01, 0.03}, y up to 0.19 (tops at 0.19) and a taller particle farther out (x = 0.2, y = 0.5): only
            // the band x < 0.05 counts, and only particles with enough neighbours.
            var points = new List<float3>();
            for (int x = 0; x < 2; x++)
            for (int y = 0; y < 10; y++)
                points.Add(new float3(0.01f + 0.02f * x, 0.01f + 0.02f * y, 0f));
            points.Add(new float3(0.2f, 0.5f, 0f));
            points.Add(new float3(0.01f, 0.6f, 0f));
            FluidBuffers b = Points(points);
            for (int i = 0; i < b.Status.Count; i++)
                b.NeighbourCounts[i] = i < 21 ? 8 : 0;
            Assert.That(FluidScene.BulkHeightAtWall(b, 0.02f, 4, 0.05f), Is.EqualTo(0.19 + 0.01).Within(1e-6));
            // The table's first 14 points (τ ≤ 3.44, T = τ√2 ≤ 4.87) fall inside a run to T = 4.9; τ = 4.2 does not.
            Assert.AreEqual(14, DamBreakScenario.HeightPoints);
        }

        [Test]
        public void FrontSpeed_OfTheTableIsItsLateSlope()
        {
            // The stability plan quotes a late slope of 1.38 for Table 2; the least-squares fit over 2 ≤ T ≤ 3.33
            // (8 points) must give it to the table's two decimals.
            double slope = DamBreakScenario.FrontSpeed(MartinMoyce1952.T, MartinMoyce1952.Z, MartinMoyce1952.T.Length, DamBreakScenario.LateT, DamBreakScenario.LastTableT);
            Assert.That(slope, Is.EqualTo(1.38).Within(0.005));
            // A line Z = 1 + 2T sampled anywhere has slope 2 exactly (up to double round-off).
            double[] t = { 0.5, 1.9, 2.0, 2.5, 3.0, 3.33, 3.4 };
            var z = new double[t.Length];
            for (int k = 0; k < t.Length; k++)
                z[k] = 1 + 2 * t[k];
            Assert.That(DamBreakScenario.FrontSpeed(t, z, t.Length, 2.0, 3.33), Is.EqualTo(2.0).Within(1e-12));
        }

        [Test]
        public void StagedSubstep_HasTheBitsOfFluidSolverStep()
        {
            // The throughput suite's per-stage split is only meaningful if the staged step is the solver's step: its setup
            // runs one of each from the same state and compares positions, velocities and ids bit for bit.
            var scenario = new FluidThroughputScenario(8, FluidThroughputRow.Staged);
            scenario.Setup();
            scenario.Step();
            double same = double.NaN;
            foreach (Metric m in scenario.Evaluate())
                if (m.Name == "same bits as FluidSolver.Step")
                    same = m.Value;
            Assert.AreEqual(1.0, same);
        }

        [Test]
        public void StageOf_CountsEveryPassOfAWeaklyCompressibleSubstepInANamedStage()
        {
            // The throughput fluid (no cohesion, no colliders) must leave nothing in "other passes".
            FluidParameters p = FluidThroughputScenario.CubeParameters(8).Sanitized();
            Span<FluidPass> passes = stackalloc FluidPass[FluidSubstepPasses.MaxPasses];
            var c = new FluidConstants(p);
            int n = FluidSubstepPasses.Write(c, FluidSolver.CflSubstep(c, 0f, 1f), false, passes);
            FluidStage stage = FluidStage.Other;
            for (int q = 0; q < n; q++)
            {
                stage = FluidThroughputScenario.StageOf(passes[q], stage);
                Assert.AreNotEqual(FluidStage.Other, stage, passes[q].ToString());
            }
        }

        [Test]
        public void HardCase_NaNInjected_RemovesExactlyTheTwoNonFiniteParticles()
        {
            // NaN in one position and +∞ in one velocity are removed by the next sort; 1e20 m is finite and is put back in
            // the box. The 998 others stay finite and inside.
            var scenario = new FluidHardCaseScenario(FluidHardCase.NaNInjected, FluidSolverKind.WeaklyCompressible);
            scenario.Setup();
            scenario.Step();
            var values = new Dictionary<string, double>();
            foreach (Metric m in scenario.Evaluate())
                values[m.Name] = m.Value;
            Assert.AreEqual(2.0, values["invalid removed"]);
            Assert.AreEqual(998.0, values["alive"]);
            Assert.AreEqual(1.0, values["finite"]);
            Assert.AreEqual(1.0, values["in box"]);
        }

        /// <summary>
        /// The accuracy figure's x-axis is the whole scene's compute per 1/60 s of flow: a run at twice the resolution (8× the
        /// particles, 2× the substeps) at the same ns per particle-substep costs 16× on it (per particle-substep it cost the same).
        /// </summary>
        [Test]
        public void AccuracyFigure_ChargesTheWholeScene_SoResolutionShowsItsPrice()
        {
            var suite = new FluidAccuracySuite();
            var coarse = new ScenarioOutcome("WCSPH c0 = 10·v, a/10", 500, Array.Empty<Metric>(), 800, 800L * 3000);
            var fine = new ScenarioOutcome("WCSPH c0 = 10·v, a/20", 500, Array.Empty<Metric>(), 6400, 6400L * 6000);
            Assert.That(suite.Cost(fine) / suite.Cost(coarse), Is.EqualTo(16.0).Within(1e-12));
            double seconds = DamBreakScenario.EndT / Math.Sqrt(2 * 9.81 / MartinMoyce1952.ColumnWidth);
            Assert.That(suite.Cost(coarse), Is.EqualTo(500e-6 * 800 * 3000 / (60 * seconds)).Within(1e-9));
        }

        [Test]
        public void DropletRows_GiveViscosityAndCohesionTheirCostAgainstTheRightBaseline()
        {
            // Viscosity is priced against the inviscid drop, cohesion against the viscous drop without cohesion; a row order
            // that puts the inviscid drop after the plain one must not make it the cohesion baseline.
            static ScenarioOutcome Drop(string method, double ns) =>
                new ScenarioOutcome(method, ns, new[] { new Metric("sphericity", 0.9, MetricUnit.Dimensionless) }, 1000, 1000);
            var rows = new[]
            {
                Drop("WCSPH no cohesion", 1400),
                Drop("WCSPH " + FluidFindings.InviscidDroplet, 1200),
                Drop("WCSPH flocking (50/s², align 2/s)", 1900),
            };
            var costs = new Dictionary<string, string>();
            foreach (Finding f in FluidFindings.Findings(rows))
                if (f is EffectFinding e)
                    costs[e.Effect] = e.Cost;
            StringAssert.StartsWith("+200 ns per particle-substep", costs[EffectNames.FluidViscosity]);
            StringAssert.Contains("without the viscosity pass", costs[EffectNames.FluidViscosity]);
            StringAssert.StartsWith("+500 ns per particle-substep", costs[EffectNames.FlockingCohesion]);
            Assert.IsFalse(costs.ContainsKey(EffectNames.AkinciCohesion), "no Akinci row, no Akinci line");
        }
    }
}
