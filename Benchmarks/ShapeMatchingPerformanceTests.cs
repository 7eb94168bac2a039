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
    /// step of 4 substeps per measurement) and <see cref="ShapeMatchingAccuracyScenario"/> (the 512-particle
    /// squash-recovery step per measurement, then the scenario's error metrics recorded once each with
    /// <see cref="Measure.Custom(SampleGroup, double)"/>: volume error, shape error at 1 s and 2 s, momentum drifts,
    /// resets; all dimensionless). Each sample is the time of one step. This runs the managed build of the
    /// solver; <see cref="ShapeMatchingBurstPerformanceTests"/> times the same step as a Burst job.
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
        public void ShapeMatching_Accuracy_512Particles(
            [Values] ShapeMatchingMode mode,
            [Values] ShapeMatchingClusterLayout layout,
            [ValueSource(typeof(ShapeMatchingAccuracySuite), nameof(ShapeMatchingAccuracySuite.SubstepCounts))] int substeps)
        {
            MeasureScenario(new ShapeMatchingAccuracyScenario(mode, layout, substeps));
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
