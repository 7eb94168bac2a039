using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>What <see cref="FreeOscillation.Run"/> measured.</summary>
    public struct FreeOscillationResult
    {
        public OscillationEstimate Fit;
        /// <summary>Substeps the solver took per step.</summary>
        public int Substeps;
        /// <summary>Frames fitted.</summary>
        public int Frames;
        /// <summary>NaN-guard resets (0 expected).</summary>
        public int Resets;
        /// <summary>Largest |x| of a particle relative to the body's origin (m): what float32 positions round against.</summary>
        public double LocalExtent;
        /// <summary>Initial amplitude of the mode's largest displacement (m).</summary>
        public double Amplitude;
        /// <summary>σₐ: the per-frame noise float32 positions can add to the samples (m, <see cref="AccuracyTolerances.PositionRoundingNoise"/>).</summary>
        public double RoundingNoise;
        /// <summary>Allowed |f/f₀ − 1|: coefficient rounding + <see cref="AccuracyTolerances.FitSigmas"/> standard errors at σₐ.</summary>
        public double FrequencyTolerance;
        /// <summary>Allowed |ζ/ζ₀ − 1|, the same way.</summary>
        public double DampingRatioTolerance;

        /// <summary>f/f₀ − 1 of the fit.</summary>
        public double FrequencyDeviation(double frequency) => Fit.Frequency / frequency - 1;
        /// <summary>ζ/ζ₀ − 1 of the fit.</summary>
        public double DampingRatioDeviation(double dampingRatio) => Fit.DampingRatio / dampingRatio - 1;

        /// <summary>
        /// True when the fit is valid, its residual is at most <see cref="AccuracyTolerances.NoiseFactor"/> × σₐ (the data
        /// are a damped oscillation up to float32 noise) and f and ζ equal <paramref name="frequency"/> and
        /// <paramref name="dampingRatio"/> within <see cref="FrequencyTolerance"/> and <see cref="DampingRatioTolerance"/>.
        /// </summary>
        public bool Matches(double frequency, double dampingRatio) =>
            Fit.Valid && Resets == 0 && Fit.Noise <= AccuracyTolerances.NoiseFactor * RoundingNoise
            && Math.Abs(FrequencyDeviation(frequency)) <= FrequencyTolerance
            && Math.Abs(DampingRatioDeviation(dampingRatio)) <= DampingRatioTolerance;
    }

    /// <summary>
    /// The frequency-and-decay test: a body at rest (no gravity, no colliders, no sleeping) displaced along its
    /// <see cref="FullyResistedMode"/> by <see cref="AmplitudeFraction"/> of its size and released; its mode amplitude
    /// yₙ = Σ mᵢ sᵢ (xᵢ − xᵢ⁰)·e_x / Σ mᵢ sᵢ² (float64, world positions) is sampled after every step and fitted by
    /// <see cref="OscillationFit"/>. Continuous model: ÿ = −ω² y − 2ζω ẏ, so the fit must return the parameters' f and ζ.
    /// The record lasts until the amplitude has decayed to 10⁻³ (ln 10³ / ζω), at most <see cref="MaxDuration"/>.
    /// </summary>
    public static class FreeOscillation
    {
        /// <summary>Initial amplitude of the largest displacement over the largest rest extent.</summary>
        public const double AmplitudeFraction = 0.02;
        /// <summary>Longest record (s).</summary>
        public const double MaxDuration = 1.0;

        /// <summary>Length (s) of the record for ζω: until e^{−ζωt} = 10⁻³, at most <see cref="MaxDuration"/>.</summary>
        public static double Duration(in ShapeMatchingParameters parameters)
        {
            ShapeMatchingParameters p = parameters.Sanitized();
            double decay = p.DampingRatio * p.AngularFrequency;
            return decay > 0 ? Math.Min(MaxDuration, Math.Log(1e3) / decay) : MaxDuration;
        }

        /// <param name="mode">Pattern from <see cref="FullyResistedMode.Find"/> for this model and mode.</param>
        /// <param name="position">Where the body's centre is placed (world, m).</param>
        public static FreeOscillationResult Run(ShapeMatchingModelData model, double[] mode, ShapeMatchingParameters parameters,
            float dt, float3 position)
        {
            parameters.Body.Acceleration = float3.zero;
            parameters.Body.SleepSpeed = 0f;
            var body = new ShapeMatchingInstance(model, parameters, position, quaternion.identity);
            Vector3d[] rest = ConvergenceRelease.World(body);
            double size = BodyMeasures.RestSize(model.AsModel());
            double amplitude = AmplitudeFraction * size;
            double norm = 0;
            for (int i = 0; i < mode.Length; i++)
            {
                body.Positions[i].x += (float)(amplitude * mode[i]);
                norm += model.Masses[i] * mode[i] * mode[i];
            }
            int frames = Math.Max(8, (int)Math.Round(Duration(parameters) / dt)) + 1;
            var samples = new double[frames];
            var result = new FreeOscillationResult { Frames = frames, Amplitude = amplitude };
            for (int f = 0; f < frames; f++)
            {
                if (f > 0)
                {
                    ShapeMatchingStepReport report = body.Step(dt);
                    result.Substeps = report.Substeps;
                    result.Resets += report.Reset ? 1 : 0;
                }
                double y = 0;
                var o = (Vector3d)body.Status.Origin;
                for (int i = 0; i < mode.Length; i++)
                {
                    y += model.Masses[i] * mode[i] * ((o + (Vector3d)body.Positions[i]).X - rest[i].X);
                    result.LocalExtent = Math.Max(result.LocalExtent, ((Vector3d)body.Positions[i]).Length);
                }
                samples[f] = y / norm;
            }
            ShapeMatchingParameters p = parameters.Sanitized();
            result.Fit = OscillationFit.Fit(samples, dt, p.Frequency);
            // Tolerances for the parameters' f and ζ (what the fit must return).
            double omega = 2 * Math.PI * p.Frequency, h = dt / (double)Math.Max(1, result.Substeps);
            double weighted = 0;
            for (int i = 0; i < mode.Length; i++)
                weighted += model.Masses[i] * model.Masses[i] * mode[i] * mode[i];
            result.RoundingNoise = AccuracyTolerances.PositionRoundingNoise(result.LocalExtent, Math.Max(1, result.Substeps),
                AccuracyTolerances.Pull(omega, p.DampingRatio, h), Math.Sqrt(weighted) / norm);
            AccuracyTolerances.CoefficientRounding(omega, p.DampingRatio, h, out double frequencyRounding, out double dampingRounding);
            result.FrequencyTolerance = frequencyRounding
                + AccuracyTolerances.FitSigmas * result.RoundingNoise * result.Fit.FrequencySensitivity / p.Frequency;
            result.DampingRatioTolerance = dampingRounding
                + AccuracyTolerances.FitSigmas * result.RoundingNoise * result.Fit.DampingRatioSensitivity / Math.Max(1e-6, p.DampingRatio);
            return result;
        }
    }
}
