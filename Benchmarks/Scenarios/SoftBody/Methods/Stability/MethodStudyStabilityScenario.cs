using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// One method of the stability study. Setup runs the study on fresh bodies of the method: the largest stable step of
    /// the pinned cube at one substep (<see cref="StableStepSearch"/>) and the hard cases on the free cube at the method's
    /// first knob value of <see cref="MethodCatalog"/> (<see cref="HardCaseRun"/>); then Step (timed) advances the pinned
    /// cube by one step of the step found, started again every <see cref="FramesPerCycle"/> steps, and Evaluate reports.
    /// </summary>
    public sealed class MethodStudyStabilityScenario : IScenario, IScenarioRepeatCap
    {
        /// <summary>Knob of the stable-step runs: one substep (or the least the method allows), so that the row measures the integrator.</summary>
        public const int StepKnob = 1;
        /// <summary>Frame of the hard cases (s).</summary>
        public const float Frame = 1f / 60f;
        /// <summary>Simulated time of a hard case (s).</summary>
        public const float HardCaseTime = 3f;
        /// <summary>Timed steps between restarts from the compressed cube.</summary>
        public const int FramesPerCycle = 120;

        /// <summary>Metric: the largest stable step (ms).</summary>
        public const string MaxStep = "dt_max";
        /// <summary>Metric: 1 when the largest step searched (1 s) was bounded.</summary>
        public const string Capped = "capped";
        /// <summary>Metric: the method's explicit stable step (ms): mass-spring or FEM, NaN for the others.</summary>
        public const string Bound = "bound";
        /// <summary>Metric: dt_max over <see cref="Bound"/>.</summary>
        public const string Ratio = "dt_max/bound";
        /// <summary>Metric: 1 when runs at dt_max/2 and dt_max/4 were bounded too and none of dt_max · 2ᵏ (&lt; 1 s) was.</summary>
        public const string Monotone = "monotone";
        /// <summary>Metric: 1 when runs at dt_max/2 and dt_max/4 were bounded.</summary>
        public const string BoundedBelow = "bounded below";
        /// <summary>Metric: the largest dt_max · 2ᵏ (&lt; 1 s) that was bounded (ms); 0 when none was.</summary>
        public const string BoundedAbove = "bounded above";
        /// <summary>Metric: why the smallest failing step failed (<see cref="UnboundedReason"/> as a number).</summary>
        public const string FailureReason = "fail reason";
        /// <summary>Metric: runs of the search.</summary>
        public const string Runs = "runs";
        /// <summary>Metric: steps over all runs of the search.</summary>
        public const string Steps = "steps";
        /// <summary>Metric suffix: the shape deviation of a hard case at its end over the cube size.</summary>
        public const string DeviationSuffix = " dev";
        /// <summary>Metric suffix: guard resets of a hard case.</summary>
        public const string ResetsSuffix = " resets";

        readonly Func<StabilityCube> m_Cube;
        readonly MethodVariant m_Variant;
        StabilityCube m_CubeInUse;
        IMethodBody m_Body;
        StableStepResult m_Step;
        HardCaseResult[] m_Cases;
        int m_Frame;

        readonly bool m_CheckBelow;

        /// <param name="checkBelow">Also run dt_max/2 and dt_max/4 to see that stability is monotone (the full run).</param>
        public MethodStudyStabilityScenario(Func<StabilityCube> cube, MethodVariant variant, bool checkBelow = true)
        {
            m_CheckBelow = checkBelow;
            m_Cube = cube;
            m_Variant = variant;
        }

        public string Name => MethodStudyStabilitySuite.SuiteName;
        public string Method => $"{m_Variant.Family}; {StepKnob} substep";
        public int Size => m_Cube().Pinned.Mesh.NodeCount;
        public string SizeUnit => "particles";
        public long ItemsPerStep => Size;
        public int MaxRepeats => 15;

        /// <summary>The explicit stable step (s) that bounds a family: mass-spring for "MS …", FEM for "FEM …", NaN otherwise.</summary>
        public static double ExplicitBound(StabilityCube cube, string family) =>
            family.StartsWith("MS ", StringComparison.Ordinal) ? cube.MassSpringExplicitStep
            : family.StartsWith("FEM ", StringComparison.Ordinal) ? cube.FemExplicitStep
            : double.NaN;

        public void Setup()
        {
            StabilityCube cube = m_CubeInUse = m_Cube();
            m_Body = m_Variant.Create(cube.Pinned, StepKnob, cube.CellSize);
            m_Step = StableStepSearch.Find(cube, m_Body, m_CheckBelow);
            m_Cases = new HardCaseResult[HardCases.All.Length];
            IMethodBody free = m_Variant.Create(cube.Free, m_Variant.Knobs[0], cube.CellSize);
            for (int c = 0; c < m_Cases.Length; c++)
                m_Cases[c] = HardCaseRun.Run(free, HardCases.All[c], Frame, HardCaseTime, Unity.Mathematics.float3.zero);
            m_Frame = 0;
        }

        public void Step()
        {
            if (m_Frame++ % FramesPerCycle == 0)
                m_CubeInUse.Start(m_Body);
            m_Body.Step((float)m_Step.MaxStep, StabilityCube.Gravity, ReadOnlySpan<ColliderShape>.Empty);
        }

        public IReadOnlyList<Metric> Evaluate()
        {
            double bound = ExplicitBound(m_CubeInUse, m_Variant.Family);
            var metrics = new List<Metric>
            {
                new Metric(MaxStep, 1e3 * m_Step.MaxStep, MetricUnit.Millisecond),
                new Metric(Capped, m_Step.Capped ? 1 : 0, MetricUnit.Flag),
                new Metric(Bound, 1e3 * bound, MetricUnit.Millisecond),
                new Metric(Ratio, m_Step.MaxStep / bound, MetricUnit.Dimensionless),
                new Metric(Monotone, !m_Step.BelowChecked ? double.NaN : m_Step.Monotone ? 1 : 0, MetricUnit.Flag),
                new Metric(BoundedBelow, !m_Step.BelowChecked ? double.NaN : m_Step.BoundedBelow ? 1 : 0, MetricUnit.Flag),
                new Metric(BoundedAbove, 1e3 * m_Step.BoundedAbove, MetricUnit.Millisecond),
                new Metric(FailureReason, (int)m_Step.FailureAbove, MetricUnit.Code),
                new Metric(Runs, m_Step.Runs, MetricUnit.Count),
                new Metric(Steps, m_Step.Steps, MetricUnit.Count),
            };
            for (int c = 0; c < m_Cases.Length; c++)
            {
                string label = HardCases.Label(HardCases.All[c]);
                metrics.Add(new Metric(label, (int)m_Cases[c].Outcome, MetricUnit.Code));
                metrics.Add(new Metric(label + DeviationSuffix, m_Cases[c].Deviation, MetricUnit.Fraction));
                metrics.Add(new Metric(label + ResetsSuffix, m_Cases[c].Resets, MetricUnit.Count));
            }
            metrics.Add(new Metric(StudyScene.Particles, Size, MetricUnit.Count));
            return metrics;
        }
    }
}
