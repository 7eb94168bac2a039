using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Cost of <see cref="ShapeMatchingSolver.Step"/> for one cubic body of edge³ particles settling on a floor
    /// plane under gravity: one step of <see cref="ShapeMatchingBenchmarkBody.TimeStep"/> with
    /// <see cref="Substeps"/> substeps. The body starts at its rest shape touching the floor and is placed there
    /// again every <see cref="CycleSteps"/> steps, so every timed step belongs to the same first second of
    /// settling whatever the number of steps the harness runs. One item is one particle-iteration (a particle
    /// advanced by one substep), so ns per item is the cost of one particle through predict, solve, collide and update.
    /// </summary>
    public sealed class ShapeMatchingThroughputScenario : IScenario
    {
        /// <summary>Substeps per step.</summary>
        public const int Substeps = 4;
        /// <summary>Side of the body (m).</summary>
        public const float BodySize = 1f;
        /// <summary>Steps between two placements of the body at rest on the floor (60 = 1 s).</summary>
        public const int CycleSteps = 60;

        readonly int m_Edge;
        readonly ShapeMatchingMode m_Mode;
        readonly ShapeMatchingClusterLayout m_Layout;
        ShapeMatchingInstance m_Body;
        ColliderShape[] m_Colliders;
        float3 m_Start;
        int m_CycleStep;
        int m_Steps;
        int m_Resets;
        long m_Contacts;

        public ShapeMatchingThroughputScenario(int edge, ShapeMatchingMode mode, ShapeMatchingClusterLayout layout)
        {
            m_Edge = edge;
            m_Mode = mode;
            m_Layout = layout;
        }

        public string Name => "ShapeMatchingThroughput";
        public string Method => ShapeMatchingBenchmarkBody.Label(m_Mode, m_Layout);
        public int Size => m_Edge * m_Edge * m_Edge;
        public string SizeUnit => "particles";
        /// <summary>Particle-iterations per step: particles × substeps.</summary>
        public long ItemsPerStep => (long)Size * Substeps;

        public void Setup()
        {
            ShapeMatchingModelData model = ShapeMatchingBenchmarkBody.Lattice(m_Edge, BodySize, m_Layout, m_Mode);
            float radius = ShapeMatchingBenchmarkBody.ParticleRadius(m_Edge, BodySize);
            var p = ShapeMatchingBenchmarkBody.Parameters(m_Mode, Substeps, new float3(0f, -9.81f, 0f), radius);
            // The bottom layer touches the floor from the first step: contacts every substep.
            m_Start = new float3(0f, 0.5f * BodySize + radius, 0f);
            m_Body = new ShapeMatchingInstance(model, p, m_Start, quaternion.identity);
            m_Colliders = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            m_CycleStep = m_Steps = m_Resets = 0;
            m_Contacts = 0;
        }

        public void Step()
        {
            if (m_CycleStep == CycleSteps)
            {
                m_Body.Reset(m_Start, quaternion.identity);
                m_CycleStep = 0;
            }
            ShapeMatchingStepReport report = m_Body.Step(ShapeMatchingBenchmarkBody.TimeStep, m_Colliders);
            m_CycleStep++;
            m_Steps++;
            m_Resets += report.Reset ? 1 : 0;
            m_Contacts += report.Contacts;
        }

        /// <summary>
        /// Sanity of the timed run, not accuracy: NaN-guard resets over all steps (0 expected) and the mean
        /// number of particles in floor contact in the last substep of a step (at least edge², the bottom layer;
        /// more as the body sags and spreads).
        /// </summary>
        public IReadOnlyList<Metric> Evaluate() => new[]
        {
            new Metric("resets", m_Resets, MetricUnit.Count),
            new Metric("contacts", m_Steps > 0 ? (double)m_Contacts / m_Steps : 0.0, MetricUnit.Dimensionless),
        };
    }
}
