using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Standing gravity wave: water <see cref="Depth"/> deep in a tank <see cref="Length"/> long between free-slip walls
    /// (x), periodic along z over <see cref="PeriodicLayers"/> spacings, started flat with the velocity of the first
    /// sloshing mode of linear theory, φ = B·cosh(ky)·cos(kx)·cos(ωt), k = π/L, so the surface rises as
    /// η = A·cos(kx)·sin(ωt) with amplitude <see cref="Amplitude"/>. Its analytic angular frequency is the dispersion
    /// relation ω² = g·k·tanh(kd) (Lamb 1932, §228). The water's centre of mass along x moves as sin(ωt); Setup records it
    /// every 1/60 s frame (at the time each frame simulated) for <see cref="Periods"/> analytic periods and fits e^(−γt)(a·sin ωt + b·cos ωt) + c
    /// (<see cref="DampedSineFit"/>). Error = |ω_fit/ω − 1|. Each timed Step is one more 1/60 s frame; an item is one
    /// particle-substep.
    /// </summary>
    public sealed class StandingWaveScenario : IScenario
    {
        /// <summary>Tank length L between the walls (m): half the mode's wavelength.</summary>
        public const float Length = 0.2f;
        /// <summary>Still-water depth d (m).</summary>
        public const float Depth = 0.1f;
        /// <summary>Surface amplitude A (m): kA = 0.047, so the frequency's amplitude correction, of order (kA)², is about 0.2 %.</summary>
        public const float Amplitude = 0.003f;
        /// <summary>Analytic periods recorded.</summary>
        public const int Periods = 3;
        /// <summary>Periodic length along z in spacings: four kernel radii at h = 2Δx (at least 3h).</summary>
        public const int PeriodicLayers = 8;
        const float k_Gravity = 9.81f;
        const float k_Frame = 1f / 60f;

        readonly int m_Layers;
        readonly FluidParameters m_Parameters;
        readonly string m_Setting;
        readonly int m_Members;
        StandingWaveScenario[] m_Ensemble;
        FluidConstants m_Constants;
        FluidBuffers m_Buffers;
        long m_Items;
        int m_Initial, m_Capped;
        /// <summary>ω_fit/ω − 1 of this member.</summary>
        double m_FrequencyBias;
        double m_Damping, m_FittedAmplitude, m_FitResidual;

        /// <param name="layers">Particle layers over the depth (Δx = d / layers).</param>
        /// <param name="parameters">The fluid; spacing, domain, gravity and periodic axes are set by the scene.</param>
        /// <param name="setting">The row's label.</param>
        /// <param name="members">
        /// Waves run in parallel whose ν is scaled by 1 + k/100 (k = 0 … members − 1: water's ν is 1/2500 of the artificial
        /// viscosity's, no physical change): one wave's fitted frequency moves by several per cent under such a change at
        /// coarse resolutions, so the metrics are the members' means, the frequency error with its spread.
        /// </param>
        public StandingWaveScenario(int layers, FluidParameters parameters, string setting, int members = 1)
        {
            m_Layers = layers;
            m_Members = Math.Max(1, members);
            m_Parameters = parameters;
            m_Setting = setting;
        }

        public string Name => "StandingWave";
        public string Method => $"{DamBreakScenario.SolverName(m_Parameters.Solver)} {m_Setting}, d/{m_Layers}";
        public int Size => (int)math.round(Length / Depth * m_Layers) * m_Layers * PeriodicLayers;
        public string SizeUnit => "particles";
        public long ItemsPerStep => Math.Max(1, m_Items);

        /// <summary>Wavenumber k = π/L of the first sloshing mode (1/m).</summary>
        public static double Wavenumber => Math.PI / Length;

        /// <summary>Analytic angular frequency ω = √(g·k·tanh(kd)) (rad/s).</summary>
        public static double AngularFrequency => Math.Sqrt(k_Gravity * Wavenumber * Math.Tanh(Wavenumber * Depth));

        /// <summary>The scene's fluid: <paramref name="parameters"/> at Δx = d/<paramref name="layers"/> in the tank.</summary>
        public static FluidParameters Tank(FluidParameters parameters, int layers)
        {
            float dx = Depth / layers;
            parameters.ParticleSpacing = dx;
            parameters.DomainMin = float3.zero;
            parameters.DomainMax = new float3(Length, 3f * Depth, PeriodicLayers * dx);
            parameters.Periodic = new bool3(false, false, true);
            parameters.Gravity = new float3(0f, -k_Gravity, 0f);
            // Every frame runs all the substeps the CFL limit asks for (d/20 at c₀ = 10 m/s asks for 42), never slow motion.
            parameters.MaxSubsteps = FluidParameters.SubstepLimit;
            return parameters;
        }

        /// <summary>
        /// Velocity of the mode at t = 0 at <paramref name="x"/> (m/s): ∇φ with B = gA/(ω·cosh(kd)), y from the floor;
        /// then η_t = φ_y(d) = A·ω·cos(kx) and φ_t + gη = 0 hold at the surface.
        /// </summary>
        public static float3 ModeVelocity(float3 x)
        {
            double k = Wavenumber, w = AngularFrequency;
            double b = k_Gravity * Amplitude / (w * Math.Cosh(k * Depth));
            return new float3((float)(-b * k * Math.Cosh(k * x.y) * Math.Sin(k * x.x)), (float)(b * k * Math.Sinh(k * x.y) * Math.Cos(k * x.x)), 0f);
        }

        public void Setup()
        {
            m_Ensemble = FluidScene.Ensemble(this, m_Members, m_Parameters, p => new StandingWaveScenario(m_Layers, p, m_Setting), m => m.Run());
        }

        /// <summary>Runs this member's wave for <see cref="Periods"/> periods and fits it.</summary>
        void Run()
        {
            FluidParameters p = Tank(m_Parameters, m_Layers);
            m_Constants = new FluidConstants(p);
            m_Buffers = new FluidBuffers(Size, m_Constants.Grid);
            FluidScene.FillBlock(m_Buffers, float3.zero, new float3(Length, Depth, p.DomainMax.z), p.ParticleSpacing);
            m_Initial = m_Buffers.Status.Count;
            for (int i = 0; i < m_Initial; i++)
                m_Buffers.Velocities[i] = ModeVelocity(m_Buffers.Positions[i]);
            int frames = (int)Math.Ceiling(Periods * 2 * Math.PI / AngularFrequency / k_Frame);
            var t = new double[frames + 1];
            var centre = new double[frames + 1];
            centre[0] = CentreX();
            m_Capped = 0;
            for (int f = 1; f <= frames; f++)
            {
                FluidStepReport r = Frame();
                if (r.SubstepsWanted > r.Substeps)
                    m_Capped++;
                t[f] = t[f - 1] + r.SimulatedTime;
                centre[f] = CentreX();
            }
            var fit = DampedSineFit.Fit(t, centre, AngularFrequency);
            m_FrequencyBias = fit.omega / AngularFrequency - 1;
            m_Damping = fit.damping;
            m_FittedAmplitude = fit.amplitude;
            m_FitResidual = fit.residual;
        }

        FluidStepReport Frame()
        {
            FluidStepReport r = FluidScene.Step(m_Constants, m_Buffers, k_Frame);
            m_Items = (long)r.Substeps * r.Count;
            return r;
        }

        double CentreX()
        {
            double sum = 0;
            int n = m_Buffers.Status.Count;
            for (int i = 0; i < n; i++)
                sum += m_Buffers.Positions[i].x;
            return n > 0 ? sum / n : double.NaN;
        }

        /// <summary>Analytic amplitude of the centre of mass along x (m): (1/(Ld))·∫₀ᴸ (x − L/2)·A·cos(kx) dx = 2LA/(π²d).</summary>
        public static double CentreAmplitude => 2.0 * Length * Amplitude / (Math.PI * Math.PI * Depth);

        /// <summary>|mean of ω_fit/ω − 1| over the members (after Setup).</summary>
        public double FrequencyError => Math.Abs(Mean(m => m.m_FrequencyBias).Mean);

        /// <summary>Fitted amplitude of the centre of mass over the analytic <see cref="CentreAmplitude"/>, the members' mean (after Setup).</summary>
        public double AmplitudeRatio => Mean(m => m.m_FittedAmplitude).Mean / CentreAmplitude;

        public void Step() => Frame();

        public IReadOnlyList<Metric> Evaluate()
        {
            int lost = 0, capped = 0;
            foreach (StandingWaveScenario m in m_Ensemble)
            {
                lost += m.m_Initial - m.m_Buffers.Status.Count;
                capped += m.m_Capped;
            }
            return new[]
            {
                new Metric("frequency error", FrequencyError, MetricUnit.Fraction),
                new Metric("frequency error spread", Mean(m => m.m_FrequencyBias).Spread, MetricUnit.Fraction),
                new Metric("damping ratio", Mean(m => m.m_Damping).Mean / AngularFrequency, MetricUnit.Dimensionless),
                new Metric("amplitude ratio", AmplitudeRatio, MetricUnit.Dimensionless),
                new Metric("fit residual", Mean(m => m.m_FitResidual).Mean / CentreAmplitude, MetricUnit.Fraction),
                new Metric("spacing", 1000.0 * Depth / m_Layers, MetricUnit.Millimetre),
                new Metric("ensemble members", m_Members, MetricUnit.Count),
                new Metric("particles lost", lost, MetricUnit.Count),
                new Metric("frames at the substep cap", capped, MetricUnit.Count),
            };
        }

        (double Mean, double Spread) Mean(Func<StandingWaveScenario, double> metric) => FluidScene.MeanAndSpread(m_Ensemble, metric);
    }
}
