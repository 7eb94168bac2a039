using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Plane Poiseuille flow: a channel <see cref="Width"/> wide between two no-slip faces (y = 0 and y = W,
    /// <see cref="FluidParameters.DomainNoSlip"/>), periodic along x (the flow) and z, filled with a lattice of the fluid at rest
    /// and driven by a body force f along x. The steady profile is u(y) = f/(2ν)·y(W − y), peak u_max = fW²/(8ν) at the
    /// centre line; the slowest transient decays as e^(−π²νt/W²). Setup runs <see cref="SettleSeconds"/> in 1/60 s frames and
    /// measures the mean profile's error (the RMS over layers Δx thick of the layer's mean u_x against u at its mean y, as
    /// a fraction of u_max; the layer means optionally averaged over the last frames), the particles' scatter about u(y), the mean flow against 2/3·u_max and the cross flow. Each timed Step is one more 1/60 s frame; an item is one particle-substep.
    /// </summary>
    public sealed class PoiseuilleScenario : IScenario
    {
        /// <summary>Channel width W between the no-slip faces (m).</summary>
        public const float Width = 0.1f;
        /// <summary>Kinematic viscosity ν (m²/s): the honey preset's.</summary>
        public static float Viscosity => FluidPresets.Get(FluidPresetKind.Honey).Parameters.Viscosity;
        /// <summary>Peak speed u_max of the steady profile (m/s); the body force is f = 8νu_max/W².</summary>
        public const float PeakSpeed = 0.1f;
        /// <summary>
        /// Seconds before the measurement: eleven e-folding times W²/(π²ν) of the slowest transient (0.145 s), which then
        /// leaves 2·10⁻⁵ of u_max.
        /// </summary>
        public const float SettleSeconds = 1.6f;
        /// <summary>Periodic lengths along x and z in spacings: four kernel radii at h = 2Δx (at least 3h, <see cref="FluidParameters.MinPeriodicExtentRatio"/>).</summary>
        public const int PeriodicLayers = 8;
        const float k_Frame = 1f / 60f;

        readonly int m_Layers;
        readonly int m_Averaged;
        readonly float m_Settle;
        readonly FluidParameters m_Parameters;
        readonly string m_Setting;
        FluidConstants m_Constants;
        FluidBuffers m_Buffers;
        long m_Items;
        int m_Initial;
        double m_ProfileError, m_Scatter, m_FlowError, m_CrossFlow, m_DensityError;

        /// <param name="layers">Particle layers across the channel (Δx = W / layers).</param>
        /// <param name="parameters">The fluid; spacing, domain, gravity, faces and viscosity are set by the scene.</param>
        /// <param name="setting">The row's label.</param>
        /// <param name="settleSeconds">Seconds before the measurement (default <see cref="SettleSeconds"/>).</param>
        /// <param name="averagedFrames">Frames, the last of the settling, over which the profile error's layer means are averaged (default 1: the last frame's).</param>
        public PoiseuilleScenario(int layers, FluidParameters parameters, string setting, float settleSeconds = SettleSeconds, int averagedFrames = 1)
        {
            m_Settle = settleSeconds;
            m_Averaged = Math.Max(1, averagedFrames);
            m_Layers = layers;
            m_Parameters = parameters;
            m_Setting = setting;
        }

        public string Name => "Poiseuille";
        public string Method => $"{DamBreakScenario.SolverName(m_Parameters.Solver)} {m_Setting}, W/{m_Layers}";
        public int Size => PeriodicLayers * PeriodicLayers * m_Layers;
        public string SizeUnit => "particles";
        public long ItemsPerStep => Math.Max(1, m_Items);

        /// <summary>Body force f (m/s²) that drives the peak speed <see cref="PeakSpeed"/>.</summary>
        public static float BodyForce => 8f * Viscosity * PeakSpeed / (Width * Width);

        /// <summary>The analytic steady speed u(y) = f/(2ν)·y(W − y) (m/s).</summary>
        public static double Analytic(double y) => BodyForce / (2.0 * Viscosity) * y * (Width - y);

        /// <summary>The scene's fluid: <paramref name="parameters"/> at Δx = W/<paramref name="layers"/> in the periodic channel.</summary>
        public static FluidParameters Channel(FluidParameters parameters, int layers)
        {
            float dx = Width / layers;
            parameters.ParticleSpacing = dx;
            parameters.KernelRadiusRatio = 2f;
            parameters.DomainMin = float3.zero;
            parameters.DomainMax = new float3(PeriodicLayers * dx, Width, PeriodicLayers * dx);
            parameters.Periodic = new bool3(true, false, true);
            parameters.DomainNoSlip = new float3(0f, 1f, 0f);
            parameters.Gravity = new float3(BodyForce, 0f, 0f);
            parameters.Viscosity = Viscosity;
            return parameters;
        }

        public void Setup()
        {
            FluidParameters p = Channel(m_Parameters, m_Layers);
            m_Constants = new FluidConstants(p);
            m_Buffers = new FluidBuffers(Size, m_Constants.Grid);
            FluidScene.FillBlock(m_Buffers, p.DomainMin, p.DomainMax, p.ParticleSpacing);
            m_Initial = m_Buffers.Status.Count;
            int frames = (int)Math.Round(m_Settle / k_Frame);
            int averaged = Math.Min(m_Averaged, frames);
            var speed = new double[m_Layers];
            var height = new double[m_Layers];
            for (int f = 0; f < frames; f++)
            {
                Frame();
                if (f < frames - averaged)
                    continue;
                var (u, y) = MeanProfile(m_Buffers, m_Layers);
                for (int k = 0; k < m_Layers; k++)
                {
                    speed[k] += u[k] / averaged;
                    height[k] += y[k] / averaged;
                }
            }
            Measure(speed, height);
        }

        FluidStepReport Frame()
        {
            FluidStepReport r = FluidScene.Step(m_Constants, m_Buffers, k_Frame);
            m_Items = (long)r.Substeps * r.Count;
            return r;
        }

        /// <summary>
        /// The mean profile of <paramref name="b"/>: u_x and y averaged over each of <paramref name="layers"/> layers Δx thick
        /// across the channel (NaN for an empty layer), in m/s and m.
        /// </summary>
        public static (double[] speed, double[] height) MeanProfile(FluidBuffers b, int layers)
        {
            var sumU = new double[layers];
            var sumY = new double[layers];
            var count = new int[layers];
            for (int i = 0; i < b.Status.Count; i++)
            {
                float3 x = b.Positions[i];
                int layer = Math.Clamp((int)(x.y / Width * layers), 0, layers - 1);
                sumU[layer] += b.Velocities[i].x;
                sumY[layer] += x.y;
                count[layer]++;
            }
            for (int k = 0; k < layers; k++)
            {
                sumU[k] = count[k] > 0 ? sumU[k] / count[k] : double.NaN;
                sumY[k] = count[k] > 0 ? sumY[k] / count[k] : double.NaN;
            }
            return (sumU, sumY);
        }

        /// <summary>The particles' metrics now, and the profile error of the layer means <paramref name="speed"/> at <paramref name="height"/>.</summary>
        void Measure(double[] speed, double[] height)
        {
            FluidBuffers b = m_Buffers;
            int n = b.Status.Count;
            double scatter = 0, flow = 0, cross = 0, density = 0, rho0 = m_Constants.Parameters.RestDensity;
            for (int i = 0; i < n; i++)
            {
                float3 x = b.Positions[i], v = b.Velocities[i];
                double d = v.x - Analytic(x.y);
                scatter += d * d;
                flow += v.x;
                cross += math.sqrt(v.y * v.y + v.z * v.z);
                density += Math.Abs(b.Densities[i] / rho0 - 1);
            }
            double profile = 0;
            int layers = 0;
            for (int k = 0; k < m_Layers; k++)
            {
                if (double.IsNaN(speed[k]))
                    continue;
                double d = speed[k] - Analytic(height[k]);
                profile += d * d;
                layers++;
            }
            n = Math.Max(1, n);
            m_ProfileError = Math.Sqrt(profile / Math.Max(1, layers)) / PeakSpeed;
            m_Scatter = Math.Sqrt(scatter / n) / PeakSpeed;
            m_FlowError = Math.Abs(flow / n / (2.0 / 3.0 * PeakSpeed) - 1);
            m_CrossFlow = cross / n / PeakSpeed;
            m_DensityError = density / n;
        }

        /// <summary>RMS over the layers Δx thick of the mean u_x − u(mean y), as a fraction of u_max (after Setup; the means over the averaged frames).</summary>
        public double ProfileError => m_ProfileError;

        public void Step() => Frame();

        public IReadOnlyList<Metric> Evaluate() => new[]
        {
            new Metric("profile RMS error", m_ProfileError, MetricUnit.Fraction),
            new Metric("particle scatter", m_Scatter, MetricUnit.Fraction),
            new Metric("mean flow error", m_FlowError, MetricUnit.Fraction),
            new Metric("cross flow", m_CrossFlow, MetricUnit.Fraction),
            new Metric("density error", m_DensityError, MetricUnit.Fraction),
            new Metric("spacing", 1000.0 * Width / m_Layers, MetricUnit.Millimetre),
            new Metric("particles lost", m_Initial - m_Buffers.Status.Count, MetricUnit.Count),
        };
    }
}
