#if SBD_PERFORMANCE_TESTING
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.PerformanceTesting;

namespace SoftBodyDynamics.Benchmarks
{
    /// <summary>
    /// Cost and accuracy of <see cref="ShapeMatchingSolver.Step"/> in Unity, on the same scenarios the headless
    /// runner times: <see cref="ShapeMatchingThroughputScenario"/> (a 1000-particle cube on a floor, one 1/60 s
    /// step of 4 substeps per measurement), <see cref="ShapeMatchingConvergenceScenario"/> (one 1/60 s step of the
    /// released 216-particle body per measurement, then the scenario's metrics recorded once each with
    /// <see cref="Measure.Custom(SampleGroup, double)"/>: trajectory error against the float64 reference, observed order,
    /// the reference's change at half its step, frequency and damping-ratio errors, resets) and
    /// <see cref="ShapeMatchingConservationScenario"/> (momentum and angular-momentum drift of the spinning blob). Each
    /// sample is the time of one step. This runs the managed build of the solver;
    /// <see cref="ShapeMatchingBurstPerformanceTests"/> times the same step as a Burst job.
    /// </summary>
    public class ShapeMatchingPerformanceTests
    {
        const int k_ThroughputEdge = 10;
        const int k_WarmupCount = 5;
        const int k_MeasurementCount = 20;

        [Test, Performance]
        public void ShapeMatching_Throughput_1000Particles(
            [Values] ShapeMatchingMode mode,
            [Values] ShapeMatchingClusterLayout layout)
        {
            MeasureScenario(new ShapeMatchingThroughputScenario(k_ThroughputEdge, mode, layout));
        }

        [Test, Performance]
        public void ShapeMatching_Convergence_216Particles(
            [Values] ShapeMatchingMode mode,
            [Values] ShapeMatchingClusterLayout layout,
            [ValueSource(typeof(ShapeMatchingConvergenceSuite), nameof(ShapeMatchingConvergenceSuite.SubstepCounts))] int substeps)
        {
            int index = System.Array.IndexOf(ShapeMatchingConvergenceSuite.SubstepCounts, substeps);
            int previous = index > 0 ? ShapeMatchingConvergenceSuite.SubstepCounts[index - 1] : 0;
            MeasureScenario(new ShapeMatchingConvergenceScenario(mode, layout, substeps, previous));
        }

        [Test, Performance]
        public void ShapeMatching_Conservation_216Particles(
            [Values] ShapeMatchingMode mode,
            [Values] ShapeMatchingClusterLayout layout)
        {
            MeasureScenario(new ShapeMatchingConservationScenario(mode, layout));
        }

        /// <summary>Times <see cref="IScenario.Step"/>, then records every metric of <see cref="IScenario.Evaluate"/>.</summary>
        static void MeasureScenario(IScenario scenario)
        {
            string label = $"{scenario.Name} {scenario.Method} x{scenario.Size}";
            ScenarioMeasure.Steps(scenario, new SampleGroup($"{label} step", SampleUnit.Millisecond), k_WarmupCount, k_MeasurementCount);
            ScenarioMeasure.Metrics(scenario, label);
        }
    }
}
#endif
