using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Cost of one method's step for a jelly cube of edge³ nodes (a box of (edge − 1)³ cells of 6 tetrahedra,
    /// <see cref="BoxTetrahedra"/>) settling on a floor plane under gravity: one step of <see cref="TimeStep"/> with the
    /// variant's fixed substeps. The body starts at its rest shape touching the floor and is placed there again every
    /// <see cref="CycleSteps"/> steps, so every timed step belongs to the same first second of settling. One item is one
    /// particle-substep, so ns per item is the cost of one particle through one substep of the method.
    /// </summary>
    public sealed class SoftBodyMethodsThroughputScenario : IScenario, IScenarioRepeatCap
    {
        /// <summary>Step (s).</summary>
        public const float TimeStep = 1f / 60f;
        /// <summary>Side of the cube (m).</summary>
        public const float BodySize = 1f;
        /// <summary>Steps between two placements of the body at rest on the floor (60 = 1 s).</summary>
        public const int CycleSteps = 60;
        /// <summary>Node count from which <see cref="MaxRepeats"/> drops to <see cref="LargeRepeats"/>.</summary>
        public const int LargeSize = 50000;
        /// <summary>Timed steps at most for bodies of <see cref="LargeSize"/> nodes or more.</summary>
        public const int LargeRepeats = 5;

        static readonly float3 s_Gravity = new float3(0f, -9.81f, 0f);

        readonly int m_Edge;
        readonly SoftBodyMethodsThroughputSuite.Variant m_Variant;
        IMethodBody m_Body;
        ColliderShape[] m_Colliders;
        int m_CycleStep;
        int m_Resets;

        /// <param name="edge">Nodes per axis (≥ 2).</param>
        /// <param name="variant">Method, integrator and substeps.</param>
        public SoftBodyMethodsThroughputScenario(int edge, SoftBodyMethodsThroughputSuite.Variant variant)
        {
            m_Edge = edge;
            m_Variant = variant;
        }

        public string Name => "SoftBodyMethodsThroughput";
        public string Method => m_Variant.Label;
        public int Size => m_Edge * m_Edge * m_Edge;
        public string SizeUnit => "particles";
        /// <summary>Particle-substeps per step: particles × substeps.</summary>
        public long ItemsPerStep => (long)Size * m_Variant.Substeps;
        /// <summary>At most <see cref="LargeRepeats"/> timed steps for the largest bodies (seconds each in managed code).</summary>
        public int MaxRepeats => Size >= LargeSize ? LargeRepeats : int.MaxValue;

        /// <summary>Cell size (m) of the cube.</summary>
        public float CellSize => BodySize / (m_Edge - 1);

        public void Setup()
        {
            // Rest shape with its bottom layer one particle radius above the floor: contacts from the first substep.
            m_Body = m_Variant.Create(MethodBodySetup.JellyCube(BodySize, m_Edge, 0f), CellSize);
            m_Colliders = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            m_CycleStep = m_Resets = 0;
        }

        public void Step()
        {
            if (m_CycleStep == CycleSteps)
            {
                m_Resets += m_Body.Resets;
                m_Body.Place();
                m_CycleStep = 0;
            }
            m_Body.Step(TimeStep, s_Gravity, m_Colliders);
            m_CycleStep++;
        }

        /// <summary>Sanity of the run, not accuracy: NaN-guard resets over all steps (0 expected).</summary>
        public IReadOnlyList<Metric> Evaluate() => new[] { new Metric("resets", m_Resets + m_Body.Resets, MetricUnit.Count) };
    }
}
