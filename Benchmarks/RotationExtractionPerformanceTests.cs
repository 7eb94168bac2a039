#if SBD_PERFORMANCE_TESTING
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using Unity.PerformanceTesting;

namespace SoftBodyDynamics.Benchmarks
{
    /// <summary>
    /// Cost of <see cref="RotationExtraction.Extract"/> on a fixed batch of seeded cluster matrices, warm-started
    /// from the previous step's rotation (the shape-matching case) and cold-started from identity.
    /// Each matrix is A = R · S: R a random rotation, S = W · diag(s) · Wᵀ a symmetric stretch (s in [0.5, 2]) along
    /// random axes W, so R is the exact answer. The warm start is R turned by up to 0.2 rad about a random axis
    /// (12 rad/s at 60 Hz). One iteration = the whole batch, one measurement = one iteration (with a fixed
    /// MeasurementCount the package records the total time of IterationsPerMeasurement calls, not their mean),
    /// so each sample is microseconds per batch of 256 extractions.
    /// This runs the managed (Mono) build of the solver; Burst-compiled timings belong to the job benchmarks.
    /// </summary>
    public class RotationExtractionPerformanceTests
    {
        const int k_MatrixCount = 256;
        const uint k_Seed = 0x5B0D1E5u;
        const float k_WarmStartMaxAngle = 0.2f;

        const int k_WarmupCount = 10;
        const int k_MeasurementCount = 30;
        const int k_IterationsPerMeasurement = 1;

        float3x3[] m_Matrices;
        quaternion[] m_WarmStarts;
        int m_IterationSink;

        [OneTimeSetUp]
        public void CreateMatrices()
        {
            m_Matrices = new float3x3[k_MatrixCount];
            m_WarmStarts = new quaternion[k_MatrixCount];
            var rng = new Random(k_Seed);
            for (int i = 0; i < k_MatrixCount; i++)
            {
                quaternion r = rng.NextQuaternionRotation();
                var w = new float3x3(rng.NextQuaternionRotation());
                float3 s = rng.NextFloat3(new float3(0.5f), new float3(2f));
                var stretch = math.mul(w, math.mul(new float3x3(s.x, 0f, 0f, 0f, s.y, 0f, 0f, 0f, s.z), math.transpose(w)));
                m_Matrices[i] = math.mul(new float3x3(r), stretch);

                float3 axis = rng.NextFloat3Direction();
                float angle = rng.NextFloat(0f, k_WarmStartMaxAngle);
                m_WarmStarts[i] = math.normalize(math.mul(quaternion.AxisAngle(axis, angle), r));
            }
        }

        [Test, Performance]
        public void RotationExtraction_WarmStart_256Matrices()
        {
            Measure.Method(ExtractWarm)
                .WarmupCount(k_WarmupCount)
                .MeasurementCount(k_MeasurementCount)
                .IterationsPerMeasurement(k_IterationsPerMeasurement)
                .SampleGroup(new SampleGroup("RotationExtraction.Extract warm x256", SampleUnit.Microsecond))
                .Run();
        }

        [Test, Performance]
        public void RotationExtraction_ColdStart_256Matrices()
        {
            Measure.Method(ExtractCold)
                .WarmupCount(k_WarmupCount)
                .MeasurementCount(k_MeasurementCount)
                .IterationsPerMeasurement(k_IterationsPerMeasurement)
                .SampleGroup(new SampleGroup("RotationExtraction.Extract cold x256", SampleUnit.Microsecond))
                .Run();
        }

        void ExtractWarm()
        {
            int iterations = 0;
            for (int i = 0; i < k_MatrixCount; i++)
            {
                quaternion q = m_WarmStarts[i];
                iterations += RotationExtraction.Extract(m_Matrices[i], ref q);
            }
            m_IterationSink += iterations;
        }

        void ExtractCold()
        {
            int iterations = 0;
            for (int i = 0; i < k_MatrixCount; i++)
            {
                quaternion q = quaternion.identity;
                iterations += RotationExtraction.Extract(m_Matrices[i], ref q);
            }
            m_IterationSink += iterations;
        }
    }
}
#endif
