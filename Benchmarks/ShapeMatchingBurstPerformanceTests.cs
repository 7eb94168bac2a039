#if SBD_PERFORMANCE_TESTING
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Jobs;
using Unity.Mathematics;
using Unity.PerformanceTesting;

namespace SoftBodyDynamics.Benchmarks
{
    /// <summary>
    /// What users get: <see cref="ShapeMatchingSolver.Step"/> as Burst code, timed through
    /// <see cref="ShapeMatchingStepJob"/>'s <c>Run()</c> (the job on the main thread, no scheduling latency), on the
    /// body of <see cref="ShapeMatchingThroughputScenario"/>: a 1 m cube of 10³ particles resting on a floor plane,
    /// one 1/60 s step of <see cref="ShapeMatchingThroughputScenario.Substeps"/> substeps per sample, the same
    /// parameters (<see cref="ShapeMatchingBenchmarkBody.Parameters"/>). Compare with
    /// <see cref="ShapeMatchingPerformanceTests"/>, the managed build of the same step. The body is placed back at
    /// rest every <see cref="ShapeMatchingThroughputScenario.CycleSteps"/> steps, outside the timed region. In the
    /// Editor, Burst's safety checks are on unless they are switched off in the Jobs ▸ Burst menu, so players run
    /// somewhat faster.
    /// </summary>
    public class ShapeMatchingBurstPerformanceTests
    {
        const int k_Edge = 10;
        const int k_WarmupCount = 5;
        const int k_MeasurementCount = 20;

        [Test, Performance]
        public void ShapeMatching_Throughput_1000Particles_BurstJob(
            [Values] ShapeMatchingMode mode,
            [Values] ShapeMatchingClusterLayout layout)
        {
            float size = ShapeMatchingThroughputScenario.BodySize;
            float radius = ShapeMatchingBenchmarkBody.ParticleRadius(k_Edge, size);
            ShapeMatchingParameters parameters = ShapeMatchingBenchmarkBody.Parameters(mode, ShapeMatchingThroughputScenario.Substeps,
                new float3(0f, -9.81f, 0f), radius);
            // As the throughput scenario: the bottom layer touches the floor from the first step.
            var start = new float3(0f, 0.5f * size + radius, 0f);
            var placed = new ShapeMatchingInstance(ShapeMatchingBenchmarkBody.Lattice(k_Edge, size, layout, mode), parameters,
                start, quaternion.identity);
            var floor = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };

            using (var body = new ShapeMatchingJobBody(placed, floor, ShapeMatchingBenchmarkBody.TimeStep))
            {
                ShapeMatchingStepJob job = body.Job;
                string label = $"ShapeMatchingThroughput {ShapeMatchingBenchmarkBody.Label(mode, layout)} x{placed.Model.ParticleCount} Burst job step";
                StepCycleMeasure.Steps(() => job.Run(), () =>
                    {
                        placed.Reset(start, quaternion.identity);
                        body.Reset(placed);
                    },
                    ShapeMatchingThroughputScenario.CycleSteps, label, k_WarmupCount, k_MeasurementCount);

                ShapeMatchingStepReport report = body.LastReport;
                Assert.That(report.Stepped, Is.True, "the job stepped the body");
                Assert.That(report.Reset, Is.False, "no NaN-guard reset");
            }
        }
    }
}
#endif
