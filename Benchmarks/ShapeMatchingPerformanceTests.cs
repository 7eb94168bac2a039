#if SBD_PERFORMANCE_TESTING
using System.Collections.Generic;
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
    /// resets; all dimensionless). With a fixed MeasurementCount each sample is the total time of
    /// IterationsPerMeasurement steps. This runs the managed build of the solver; Burst-compiled timings belong
    /// to the job benchmarks.
    /// </summary>
    public class ShapeMatchingPerformanceTests
    {
        const int k_ThroughputEdge = 10;
        const int k_WarmupCount = 5;
        const int k_MeasurementCount = 20;
        const int k_IterationsPerMeasurement = 1;

        [Test, Performance]
        public void ShapeMatching_Throughput_1000Particles(
            [Values] ShapeMatchingMode mode,
            [Values] ShapeMatchingClusterLayout layout)
        {
            var scenario = new ShapeMatchingThroughputScenario(k_ThroughputEdge, mode, layout);
            Measure(scenario);
        }

        [Test, Performance]
        public void ShapeMatching_Accuracy_512Particles(
            [Values] ShapeMatchingMode mode,
            [Values] ShapeMatchingClusterLayout layout,
            [Values(1, 2, 4, 8)] int substeps)
        {
            var scenario = new ShapeMatchingAccuracyScenario(mode, layout, substeps);
            Measure(scenario);
        }

        /// <summary>Times <see cref="IScenario.Step"/>, then records every metric of <see cref="IScenario.Evaluate"/>.</summary>
        static void Measure(IScenario scenario)
        {
            scenario.Setup();
            string label = $"{scenario.Name} {scenario.Method} x{scenario.Size}";
            Unity.PerformanceTesting.Measure.Method(scenario.Step)
                .WarmupCount(k_WarmupCount)
                .MeasurementCount(k_MeasurementCount)
                .IterationsPerMeasurement(k_IterationsPerMeasurement)
                .SampleGroup(new SampleGroup($"{label} step", SampleUnit.Millisecond))
                .Run();
            IReadOnlyList<Metric> metrics = scenario.Evaluate();
            foreach (Metric metric in metrics)
            {
                // Measure.Custom rejects NaN; a non-finite metric is a failed simulation, reported as such.
                Assert.That(double.IsNaN(metric.Value) || double.IsInfinity(metric.Value), Is.False, $"{label}: {metric.Name}");
                Unity.PerformanceTesting.Measure.Custom(new SampleGroup($"{label} {metric.Name}", SampleUnit.Undefined), metric.Value);
            }
        }
    }
}
#endif
