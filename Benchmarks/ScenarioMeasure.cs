#if SBD_PERFORMANCE_TESTING
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using Unity.PerformanceTesting;

namespace SoftBodyDynamics.Benchmarks
{
    /// <summary>
    /// Runs an <see cref="IScenario"/> under the Performance Testing package the way the headless runner does:
    /// <see cref="IScenario.Setup"/>, untimed warm-up steps, timed steps, then the error metrics.
    /// </summary>
    static class ScenarioMeasure
    {
        /// <summary>
        /// Sets the scenario up, then records <paramref name="measurementCount"/> samples of one
        /// <see cref="IScenario.Step"/> each in <paramref name="sampleGroup"/>, after <paramref name="warmupCount"/>
        /// untimed steps. (With a fixed MeasurementCount the package records the total time of
        /// IterationsPerMeasurement calls per sample, not their mean; here that is one step.)
        /// </summary>
        public static void Steps(IScenario scenario, SampleGroup sampleGroup, int warmupCount, int measurementCount)
        {
            scenario.Setup();
            Measure.Method(scenario.Step)
                .WarmupCount(warmupCount)
                .MeasurementCount(measurementCount)
                .IterationsPerMeasurement(1)
                .SampleGroup(sampleGroup)
                .Run();
        }

        /// <summary>Records every metric of <see cref="IScenario.Evaluate"/> once, as "<paramref name="label"/> name".</summary>
        public static void Metrics(IScenario scenario, string label)
        {
            foreach (Metric metric in scenario.Evaluate())
            {
                // Measure.Custom rejects NaN; a non-finite metric is a failed simulation, reported as such.
                Assert.That(double.IsNaN(metric.Value) || double.IsInfinity(metric.Value), Is.False, $"{label}: {metric.Name}");
                Measure.Custom(new SampleGroup($"{label} {metric.Name}", SampleUnit.Undefined), metric.Value);
            }
        }
    }
}
#endif
