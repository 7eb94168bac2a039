#if SBD_PERFORMANCE_TESTING
using System;
using Unity.PerformanceTesting;

namespace SoftBodyDynamics.Benchmarks
{
    /// <summary>
    /// How the Burst step-job benchmarks time a body: one step per sample, the body placed back at rest every few steps
    /// outside the timed region, so every sample times a body in the same regime.
    /// </summary>
    static class StepCycleMeasure
    {
        /// <summary>
        /// Records <paramref name="measurementCount"/> samples of one <paramref name="step"/> each in the group
        /// <paramref name="label"/> (ms), after <paramref name="warmupCount"/> untimed ones. <paramref name="placeAtRest"/>
        /// runs untimed before the first step and then before every <paramref name="cycleSteps"/>-th.
        /// </summary>
        public static void Steps(Action step, Action placeAtRest, int cycleSteps, string label, int warmupCount, int measurementCount)
        {
            int stepsSincePlacement = cycleSteps;
            Measure.Method(step)
                .SetUp(() =>
                {
                    if (stepsSincePlacement == cycleSteps)
                    {
                        placeAtRest();
                        stepsSincePlacement = 0;
                    }
                    stepsSincePlacement++;
                })
                .WarmupCount(warmupCount)
                .MeasurementCount(measurementCount)
                .IterationsPerMeasurement(1)
                .SampleGroup(new SampleGroup(label, SampleUnit.Millisecond))
                .Run();
        }
    }
}
#endif
