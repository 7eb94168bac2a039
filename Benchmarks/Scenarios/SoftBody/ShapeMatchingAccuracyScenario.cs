using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// What a shape-matching mode, cluster layout and substep count buy, on a cube of <see cref="Edge"/>³
    /// particles with the default jelly parameters: the timed step is one step of the squash-recovery test
    /// (<see cref="SquashRecovery"/>, squashed again every 2 s), and <see cref="Evaluate"/> runs the
    /// squash-recovery and the spinning-blob (<see cref="SpinningBlob"/>) tests on fresh bodies. One item is
    /// one particle-step (a particle advanced by one 1/60 s step, all substeps included), so time per item
    /// grows with the substep count: the cost axis of the sweep.
    /// </summary>
    public sealed class ShapeMatchingAccuracyScenario : IScenario
    {
        /// <summary>Particles per edge of the test body.</summary>
        public const int Edge = 8;
        /// <summary>Side of the test body (m).</summary>
        public const float BodySize = 0.7f;
        /// <summary>Seed of the spinning blob's jitter, axis and noise.</summary>
        public const uint Seed = 2024u;

        readonly ShapeMatchingMode m_Mode;
        readonly ShapeMatchingClusterLayout m_Layout;
        readonly int m_Substeps;
        ShapeMatchingModelData m_Model;
        ShapeMatchingParameters m_Parameters;
        ShapeMatchingInstance m_Body;
        int m_StepsSinceSquash;

        public ShapeMatchingAccuracyScenario(ShapeMatchingMode mode, ShapeMatchingClusterLayout layout, int substeps)
        {
            m_Mode = mode;
            m_Layout = layout;
            m_Substeps = substeps;
        }

        public string Name => "ShapeMatchingAccuracy";
        public string Method => $"{ShapeMatchingBenchmarkBody.Label(m_Mode, m_Layout)}, {m_Substeps} substeps";
        public int Size => Edge * Edge * Edge;
        public string SizeUnit => "particles";
        /// <summary>Particle-steps per step: the particle count (substeps are part of the cost of one item).</summary>
        public long ItemsPerStep => Size;

        float Spacing => ShapeMatchingBenchmarkBody.Spacing(Edge, BodySize);

        public void Setup()
        {
            m_Model = ShapeMatchingBenchmarkBody.Lattice(Edge, BodySize, m_Layout, m_Mode);
            m_Parameters = ShapeMatchingBenchmarkBody.Parameters(m_Mode, m_Substeps, float3.zero,
                ShapeMatchingBenchmarkBody.ParticleRadius(Edge, BodySize));
            m_Body = new ShapeMatchingInstance(m_Model, m_Parameters, float3.zero, quaternion.identity);
            m_StepsSinceSquash = SquashRecovery.StepsTo2s; // the first Step squashes the body
        }

        public void Step()
        {
            if (m_StepsSinceSquash == SquashRecovery.StepsTo2s)
            {
                SquashRecovery.Squash(m_Body);
                m_StepsSinceSquash = 0;
            }
            m_Body.Step(ShapeMatchingBenchmarkBody.TimeStep);
            m_StepsSinceSquash++;
        }

        /// <summary>Runs both tests from scratch (deterministic: same numbers on every call).</summary>
        public IReadOnlyList<Metric> Evaluate()
        {
            SquashRecoveryResult squash = SquashRecovery.Run(m_Model, m_Parameters);
            SpinningBlobResult spin = SpinningBlob.Run(m_Model, m_Parameters, Spacing, Seed);
            return new[]
            {
                new Metric(ShapeMatchingAccuracySuite.MaxVolumeError, squash.MaxVolumeError),
                new Metric(ShapeMatchingAccuracySuite.ShapeErrorAt1s, squash.ShapeErrorAt1s),
                new Metric(ShapeMatchingAccuracySuite.ShapeErrorAt2s, squash.ShapeErrorAt2s),
                new Metric(ShapeMatchingAccuracySuite.MaxShapeErrorFrom1sTo2s, squash.MaxShapeErrorFrom1sTo2s),
                new Metric(ShapeMatchingAccuracySuite.MomentumDrift, spin.MaxMomentumDrift),
                new Metric(ShapeMatchingAccuracySuite.AngularMomentumDrift, spin.MaxAngularMomentumDrift),
                new Metric(ShapeMatchingAccuracySuite.Resets, squash.Resets + spin.Resets),
            };
        }
    }
}
