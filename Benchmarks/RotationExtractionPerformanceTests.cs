#if SBD_PERFORMANCE_TESTING
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.PerformanceTesting;

namespace SoftBodyDynamics.Benchmarks
{
    /// <summary>
    /// Cost of <see cref="RotationExtraction.Extract"/> in Unity, on the same scenario the headless runner times
    /// (<see cref="RotationExtractionScenario"/>: seeded clusters from every hard-case family), warm-started from
    /// the previous step's rotation and cold-started from identity. One measurement is one scenario step, so
    /// each sample is the time of <see cref="k_MatrixCount"/> extractions.
    /// This runs the managed build of the solver; the step that calls it is timed as a Burst job in
    /// <see cref="ShapeMatchingBurstPerformanceTests"/>.
    /// </summary>
    public class RotationExtractionPerformanceTests
    {
        const int k_MatrixCount = 1000;
        const int k_WarmupCount = 10;
        const int k_MeasurementCount = 30;

        [Test, Performance]
        public void RotationExtraction_WarmStart_1000Matrices() => MeasureScenario(RotationStart.Warm, "warm");

        [Test, Performance]
        public void RotationExtraction_ColdStart_1000Matrices() => MeasureScenario(RotationStart.Cold, "cold");

        static void MeasureScenario(RotationStart start, string label) =>
            ScenarioMeasure.Steps(
                new RotationExtractionScenario(k_MatrixCount, start, RotationExtraction.DefaultMaxIterations),
                new SampleGroup($"RotationExtraction.Extract {label} x{k_MatrixCount}", SampleUnit.Microsecond),
                k_WarmupCount, k_MeasurementCount);
    }
}
#endif
