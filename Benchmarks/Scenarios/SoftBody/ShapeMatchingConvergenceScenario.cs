using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// One mode, cluster layout and substep count of the convergence suite: the timed step is one 1/60 s step of the
    /// released body (<see cref="ConvergenceRelease"/>, released again every second); <see cref="Evaluate"/> gives its
    /// trajectory error against the float64 reference, the observed order against the previous substep count of the
    /// sweep, the reference's own change under step halving, and the frequency and damping ratio of the body's fully
    /// resisted mode (<see cref="FreeOscillation"/>) against the parameters. One item is one particle-step (a particle
    /// through a whole step, all substeps included), so time per item grows with the substep count.
    /// </summary>
    public sealed class ShapeMatchingConvergenceScenario : IScenario
    {
        readonly ShapeMatchingMode m_Mode;
        readonly ShapeMatchingClusterLayout m_Layout;
        readonly int m_Substeps, m_PreviousSubsteps, m_ReferenceSteps;
        ConvergenceStudy m_Study;
        ShapeMatchingInstance m_Body;
        int m_Frame;

        /// <param name="previousSubsteps">The substep count before this one in the sweep (0 for the first): the observed order is measured against it.</param>
        public ShapeMatchingConvergenceScenario(ShapeMatchingMode mode, ShapeMatchingClusterLayout layout, int substeps, int previousSubsteps,
            int referenceStepsPerFrame = ConvergenceStudy.ReferenceStepsPerFrame)
        {
            m_Mode = mode;
            m_Layout = layout;
            m_Substeps = substeps;
            m_PreviousSubsteps = previousSubsteps;
            m_ReferenceSteps = referenceStepsPerFrame;
        }

        public string Name => "ShapeMatchingConvergence";
        public string Method => $"{ShapeMatchingBenchmarkBody.Label(m_Mode, m_Layout)}, {m_Substeps} substeps";
        public int Size => ConvergenceStudy.Edge * ConvergenceStudy.Edge * ConvergenceStudy.Edge;
        public string SizeUnit => "particles";
        public long ItemsPerStep => Size;

        public void Setup()
        {
            m_Study = ConvergenceStudy.For(m_Mode, m_Layout, m_ReferenceSteps);
            ShapeMatchingParameters p = m_Study.Release.Parameters;
            p.Body.Substeps = m_Substeps;
            m_Body = new ShapeMatchingInstance(m_Study.Release.Model, p, float3.zero, quaternion.identity);
            m_Frame = ConvergenceRelease.Frames;
        }

        public void Step()
        {
            if (m_Frame == ConvergenceRelease.Frames)
            {
                m_Study.Release.Start.CopyTo(m_Body.Positions, 0);
                Array.Clear(m_Body.Velocities, 0, m_Body.Velocities.Length);
                m_Frame = 0;
            }
            m_Body.Step(ConvergenceRelease.FrameTime);
            m_Frame++;
        }

        public IReadOnlyList<Metric> Evaluate()
        {
            double omega = m_Study.Release.Parameters.AngularFrequency;
            var metrics = new List<Metric>
            {
                new Metric(ShapeMatchingConvergenceSuite.TrajectoryError, m_Study.Error(m_Substeps), MetricUnit.Fraction),
            };
            if (m_PreviousSubsteps > 0)
                metrics.Add(new Metric(ShapeMatchingConvergenceSuite.Order, m_Study.ObservedOrder(m_PreviousSubsteps, m_Substeps), MetricUnit.Dimensionless));
            metrics.Add(new Metric(ShapeMatchingConvergenceSuite.ReferenceChange, m_Study.ReferenceChange, MetricUnit.Fraction));
            metrics.Add(new Metric(ShapeMatchingConvergenceSuite.Phase, omega * ConvergenceRelease.FrameTime / m_Substeps, MetricUnit.Radian));
            FreeOscillationResult oscillation = m_Study.Oscillation(m_Substeps);
            if (oscillation.Fit.Valid)
            {
                ShapeMatchingParameters p = m_Study.Release.Parameters;
                metrics.Add(new Metric(ShapeMatchingConvergenceSuite.FrequencyError, oscillation.Fit.Frequency / p.Frequency - 1, MetricUnit.Fraction));
                metrics.Add(new Metric(ShapeMatchingConvergenceSuite.DampingError, oscillation.Fit.DampingRatio / p.DampingRatio - 1, MetricUnit.Fraction));
            }
            metrics.Add(new Metric(ShapeMatchingConvergenceSuite.Resets, oscillation.Resets + m_Study.Resets(m_Substeps), MetricUnit.Count));
            return metrics;
        }
    }
}
