using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// One mode and cluster layout of the conservation suite: the timed step is one step of the spinning blob
    /// (<see cref="SpinningBlob"/>, spun again every <see cref="SpinningBlob.Steps"/> steps); <see cref="Evaluate"/> runs
    /// the whole test on a fresh body. One item is one particle-step.
    /// </summary>
    public sealed class ShapeMatchingConservationScenario : IScenario
    {
        /// <summary>Particles per edge of the test body.</summary>
        public const int Edge = 6;
        /// <summary>Side of the test body (m).</summary>
        public const float BodySize = 0.5f;
        /// <summary>Substeps per 1/60 s step.</summary>
        public const int Substeps = 4;
        /// <summary>Seed of the jitter, axis and noise.</summary>
        public const uint Seed = 2024u;

        readonly ShapeMatchingMode m_Mode;
        readonly ShapeMatchingClusterLayout m_Layout;
        ShapeMatchingModelData m_Model;
        ShapeMatchingParameters m_Parameters;
        ShapeMatchingInstance m_Body;
        int m_Steps;

        public ShapeMatchingConservationScenario(ShapeMatchingMode mode, ShapeMatchingClusterLayout layout)
        {
            m_Mode = mode;
            m_Layout = layout;
        }

        public string Name => "ShapeMatchingConservation";
        public string Method => ShapeMatchingBenchmarkBody.Label(m_Mode, m_Layout);
        public int Size => Edge * Edge * Edge;
        public string SizeUnit => "particles";
        public long ItemsPerStep => Size;

        float Spacing => ShapeMatchingBenchmarkBody.Spacing(Edge, BodySize);

        public void Setup()
        {
            m_Model = ShapeMatchingBenchmarkBody.Lattice(Edge, BodySize, m_Layout, m_Mode);
            m_Parameters = ShapeMatchingBenchmarkBody.Parameters(m_Mode, Substeps, float3.zero,
                ShapeMatchingBenchmarkBody.ParticleRadius(Edge, BodySize));
            m_Parameters.Body.SleepSpeed = 0f;
            m_Body = new ShapeMatchingInstance(m_Model, m_Parameters, float3.zero, quaternion.identity);
            m_Steps = SpinningBlob.Steps;
        }

        public void Step()
        {
            if (m_Steps == SpinningBlob.Steps)
            {
                m_Body.Reset(float3.zero, quaternion.identity);
                SpinningBlob.Spin(m_Body, Spacing, Seed);
                m_Steps = 0;
            }
            m_Body.Step(ShapeMatchingBenchmarkBody.TimeStep);
            m_Steps++;
        }

        public IReadOnlyList<Metric> Evaluate()
        {
            SpinningBlobResult spin = SpinningBlob.Run(m_Model, m_Parameters, Spacing, Seed);
            return new[]
            {
                new Metric(ShapeMatchingConservationSuite.MomentumDrift, spin.MaxMomentumDrift, MetricUnit.Fraction),
                new Metric(ShapeMatchingConservationSuite.AngularMomentumDrift, spin.MaxAngularMomentumDrift, MetricUnit.Fraction),
                new Metric(ShapeMatchingConservationSuite.Resets, spin.Resets, MetricUnit.Count),
            };
        }
    }
}
