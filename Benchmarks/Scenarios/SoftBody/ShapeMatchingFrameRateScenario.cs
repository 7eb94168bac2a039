using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// One preset, frame rate and requested substep count of the frame-rate suite. The timed step is one step of the
    /// body resting on the floor (put back in its rest shape every second); <see cref="Evaluate"/> settles it
    /// (<see cref="RestingSag"/>) and compares its rest with the preset's dt → 0 rest, and fits the free oscillation of
    /// its fully resisted mode (<see cref="FreeOscillation"/>, no gravity). One item is one particle-step.
    /// </summary>
    public sealed class ShapeMatchingFrameRateScenario : IScenario
    {
        readonly string m_Preset;
        readonly float m_Rate;
        readonly int m_Substeps;
        FrameRateStudy m_Study;
        ShapeMatchingInstance m_Body;
        ColliderShape[] m_Floor;
        int m_Steps;

        public ShapeMatchingFrameRateScenario(string preset, float rate, int requestedSubsteps)
        {
            m_Preset = preset;
            m_Rate = rate;
            m_Substeps = requestedSubsteps;
        }

        public string Name => "ShapeMatchingFrameRate";
        public string Method => $"{m_Preset}, {m_Rate:0} Hz, {m_Substeps} requested";
        public int Size => FrameRateStudy.Edge * FrameRateStudy.Edge * FrameRateStudy.Edge;
        public string SizeUnit => "particles";
        public long ItemsPerStep => Size;

        float TimeStep => 1f / m_Rate;

        public void Setup()
        {
            m_Study = FrameRateStudy.For(m_Preset);
            ShapeMatchingParameters p = m_Study.WithSubsteps(m_Substeps);
            p.Body.Acceleration = new float3(0f, -RestingSag.Gravity, 0f);
            p.Body.SleepSpeed = 0f;
            m_Body = new ShapeMatchingInstance(m_Study.Model, p, float3.zero, quaternion.identity);
            m_Floor = new[] { RestingSag.Floor(m_Study.Model, p.Body.ParticleRadius) };
            m_Steps = 0;
        }

        public void Step()
        {
            if (m_Steps == (int)m_Rate)
            {
                m_Body.Reset(float3.zero, quaternion.identity);
                m_Steps = 0;
            }
            m_Body.Step(TimeStep, m_Floor);
            m_Steps++;
        }

        public IReadOnlyList<Metric> Evaluate()
        {
            ShapeMatchingParameters p = m_Study.WithSubsteps(m_Substeps);
            RestingSagReference reference = m_Study.Reference;
            RestingSagResult rest = RestingSag.Run(m_Study.Model, p, TimeStep);
            double omega = 2 * Math.PI * m_Study.Material.Frequency;
            double h = TimeStep / (double)rest.Substeps;
            double sagRatio = rest.Deflection / reference.Deflection;
            double predicted = RestingSag.PredictedSagRatio(omega, m_Study.Material.DampingRatio, h);
            var metrics = new List<Metric>
            {
                new Metric(ShapeMatchingFrameRateSuite.Substeps, rest.Substeps, MetricUnit.Count),
                new Metric(ShapeMatchingFrameRateSuite.Phase, omega * h, MetricUnit.Radian),
                new Metric(ShapeMatchingFrameRateSuite.HeightRatio, rest.Height / reference.Height, MetricUnit.Dimensionless),
                new Metric(ShapeMatchingFrameRateSuite.SagRatio, sagRatio, MetricUnit.Dimensionless),
                new Metric(ShapeMatchingFrameRateSuite.SagError, Math.Abs(sagRatio - 1), MetricUnit.Fraction),
                new Metric(ShapeMatchingFrameRateSuite.PredictedSag, predicted, MetricUnit.Fraction),
                new Metric(ShapeMatchingFrameRateSuite.SagVersusPrediction, sagRatio / predicted - 1, MetricUnit.Fraction),
                new Metric(ShapeMatchingFrameRateSuite.Volume, rest.VolumeRatio, MetricUnit.Dimensionless),
                new Metric(ShapeMatchingFrameRateSuite.VolumeDeviation, rest.VolumeRatio / reference.VolumeRatio - 1, MetricUnit.Fraction),
            };
            int resets = rest.Resets;
            if (m_Study.ResistedMode != null)
            {
                FreeOscillationResult wobble = FreeOscillation.Run(m_Study.Model, m_Study.ResistedMode, p, TimeStep, float3.zero);
                resets += wobble.Resets;
                if (wobble.Fit.Valid)
                {
                    metrics.Add(new Metric(ShapeMatchingFrameRateSuite.FrequencyError, wobble.FrequencyDeviation(m_Study.Material.Frequency), MetricUnit.Fraction));
                    metrics.Add(new Metric(ShapeMatchingFrameRateSuite.FrequencyTolerance, wobble.FrequencyTolerance, MetricUnit.Fraction));
                    metrics.Add(new Metric(ShapeMatchingFrameRateSuite.DampingError, wobble.DampingRatioDeviation(m_Study.Material.DampingRatio), MetricUnit.Fraction));
                    metrics.Add(new Metric(ShapeMatchingFrameRateSuite.DampingTolerance, wobble.DampingRatioTolerance, MetricUnit.Fraction));
                }
            }
            metrics.Add(new Metric(ShapeMatchingFrameRateSuite.PlasticUpdates, rest.PlasticUpdates, MetricUnit.Count));
            metrics.Add(new Metric(ShapeMatchingFrameRateSuite.Resets, resets, MetricUnit.Count));
            return metrics;
        }
    }
}
