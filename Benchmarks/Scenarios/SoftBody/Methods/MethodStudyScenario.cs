using System.Collections.Generic;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// One point of the method study: a scene at a resolution, a method and a knob value. Step advances the body by one frame of the
    /// scene (timed: one item = one particle through a 1/60 s step, all substeps and iterations included); Evaluate
    /// runs the scene's measurement on fresh bodies of the same method and knob.
    /// </summary>
    public sealed class MethodStudyScenario : IScenario
    {
        readonly StudyScene m_Scene;
        readonly MethodVariant m_Variant;
        readonly int m_Knob, m_Resolution;
        IMethodBody m_Body;
        int m_Frame;

        public MethodStudyScenario(StudyScene scene, MethodVariant variant, int knob, int resolution = 0)
        {
            m_Scene = scene;
            m_Variant = variant;
            m_Knob = knob;
            m_Resolution = resolution;
        }

        public string Name => m_Scene.Name;
        public string Method => m_Variant.Label(m_Knob, m_Resolution);
        public int Size => m_Variant.ParticleCount(m_Scene.SetupAt(m_Resolution));
        public string SizeUnit => "particles";
        public long ItemsPerStep => Size;

        public void Setup()
        {
            m_Body = m_Variant.Create(m_Scene.SetupAt(m_Resolution), m_Knob, m_Scene.CellSizeAt(m_Resolution));
            m_Frame = 0;
        }

        public void Step() => m_Scene.TimedFrame(m_Body, m_Frame++);

        /// <summary>Metric: conjugate-gradient iterations per implicit substep, the mean over the evaluation's runs (iterative methods only).</summary>
        public const string CgIterations = "CG its";
        /// <summary>Metric: the largest relative residual ‖b − A x‖/‖b‖ a solve of the evaluation ended at (iterative methods only).</summary>
        public const string CgResidual = "CG res";

        /// <summary>The scene's metrics; for a method that solves iteratively, also <see cref="CgIterations"/> and <see cref="CgResidual"/>.</summary>
        public IReadOnlyList<Metric> Evaluate()
        {
            var bodies = new List<IMethodBody>();
            IReadOnlyList<Metric> metrics = m_Scene.Measure(m_Scene.SetupAt(m_Resolution), s =>
            {
                IMethodBody body = m_Variant.Create(s, m_Knob, m_Scene.CellSizeAt(m_Resolution));
                bodies.Add(body);
                return body;
            });
            long iterations = 0, substeps = 0;
            double residual = 0;
            foreach (IMethodBody body in bodies)
                if (body is IIterativeMethodBody solved)
                {
                    iterations += solved.CgIterations;
                    substeps += solved.ImplicitSubsteps;
                    residual = System.Math.Max(residual, solved.MaxCgResidual);
                }
            if (substeps == 0)
                return metrics;
            var all = new List<Metric>(metrics)
            {
                new Metric(CgIterations, (double)iterations / substeps, MetricUnit.Count),
                new Metric(CgResidual, residual, MetricUnit.Fraction),
            };
            return all;
        }
    }
}
