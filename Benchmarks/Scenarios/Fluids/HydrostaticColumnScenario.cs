using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Hydrostatic column: a 0.3 × 0.4 × 0.3 m block of water (Δx = 2.5 cm, h = 5 cm, 2304 particles; or a finer spacing)
    /// released at rest in a box of the same footprint. Setup runs it for the settle time (10 s in the full run) in 1/60 s frames and
    /// measures: the interior pressure's L2 error against ρ₀·g·(H − y) and the error against −ρ₀g of its least-squares
    /// gradient averaged over the last second's 60 frames (one frame's fit moves by several per cent with the particles'
    /// slow rearrangement and acoustic noise) and against −ρ̄g with ρ̄ the interior's mean density (the weakly compressible
    /// fluid's own analytic gradient, dp/dy = −ρ(p)·g), where the last frame's line reaches zero and the particles' scatter about it (interior = at least two kernel radii 2h from the walls, the floor and the surface, where the half-space walls of
    /// earlier releases left the kernel deficient; kept so that the rows compare: 128 particles; weakly compressible only, position-based fluids have no pressure), the mean interior
    /// density error, the kinetic energy per particle mass and how far the surface moved over the last 90 % of the
    /// run. The settled state is chaotic: a change as small as water's ν × 1.01 moves the averaged slope by several per
    /// cent, so an ensemble of columns whose ν is scaled by 1 + k/100 (k = 0 … members − 1; water's ν is 1/2500 of the
    /// artificial viscosity's, no physical change) settles in parallel and each metric is the members' mean, the gradient
    /// errors as the mean of their signed values with its spread (standard deviation over the members). Each timed Step is
    /// one more 1/60 s frame of the first member; an item is one particle-substep.
    /// </summary>
    public sealed class HydrostaticColumnScenario : IScenario
    {
        /// <summary>Default particle spacing Δx (m).</summary>
        public const float DefaultSpacing = 0.025f;
        const float k_Frame = 1f / 60f;
        /// <summary>Frames over which the pressure gradient is averaged: the last second.</summary>
        const int k_AveragedFrames = 60;
        static readonly float3 s_Block = new float3(0.3f, 0.4f, 0.3f);

        readonly FluidParameters m_Parameters;
        readonly string m_Setting;
        readonly float m_SettleSeconds;
        readonly float m_Spacing;
        readonly int m_Members;
        HydrostaticColumnScenario[] m_Ensemble;
        FluidConstants m_Constants;
        FluidBuffers m_Buffers;
        long m_Items;
        int m_Initial;
        double m_PressureError, m_DensityError, m_Kinetic, m_Drift, m_SurfaceOffset, m_PressureScatter;
        /// <summary>Signed errors of the averaged slope against −ρ₀g and −ρ̄g (positive: steeper).</summary>
        double m_GradientBias, m_OwnDensityGradientBias;
        int m_Interior;

        public HydrostaticColumnScenario(FluidParameters parameters, string setting, float settleSeconds, float spacing = DefaultSpacing, int members = 1)
        {
            m_Spacing = spacing;
            m_Members = Math.Max(1, members);
            m_Parameters = parameters;
            m_Setting = setting;
            m_SettleSeconds = settleSeconds;
        }

        public string Name => "HydrostaticColumn";
        public string Method => $"{DamBreakScenario.SolverName(m_Parameters.Solver)} {m_Setting}, {m_SettleSeconds:0.#} s";
        public int Size => m_Initial > 0 ? m_Initial : FluidScene.BlockCount(float3.zero, s_Block, m_Spacing);
        public string SizeUnit => "particles";
        public long ItemsPerStep => Math.Max(1, m_Items);

        /// <summary>Reference speed √(2gH) of the column (m/s).</summary>
        public static float ReferenceSpeed => (float)Math.Sqrt(2 * 9.81 * s_Block.y);

        public void Setup()
        {
            m_Ensemble = FluidScene.Ensemble(this, m_Members, m_Parameters,
                p => new HydrostaticColumnScenario(p, m_Setting, m_SettleSeconds, m_Spacing), m => m.Settle());
        }

        /// <summary>Settles this member's column and measures it.</summary>
        void Settle()
        {
            m_Buffers = FluidScene.BlockInBox(m_Parameters, m_Spacing, new float3(s_Block.x, 1.5f * s_Block.y, s_Block.z), s_Block, out m_Constants);
            m_Initial = m_Buffers.Status.Count;
            int frames = (int)Math.Round(m_SettleSeconds / k_Frame);
            int averaged = Math.Min(k_AveragedFrames, frames);
            double early = double.NaN, slopes = 0, ownSlopes = 0;
            for (int f = 0; f < frames; f++)
            {
                Frame();
                if (f == frames / 10)
                    early = Surface();
                if (f >= frames - averaged)
                {
                    var fit = Fit(Surface());
                    slopes += fit.Slope;
                    ownSlopes += fit.Slope / fit.Density;
                }
            }
            Measure(early, slopes / averaged, ownSlopes / averaged);
        }

        FluidStepReport Frame()
        {
            FluidStepReport r = FluidScene.Step(m_Constants, m_Buffers, k_Frame);
            m_Items = (long)r.Substeps * r.Count;
            return r;
        }

        /// <summary>Surface height H (m): the highest particle with neighbours, plus half a spacing.</summary>
        double Surface()
        {
            double top = 0;
            for (int i = 0; i < m_Buffers.Status.Count; i++)
                if (m_Buffers.NeighbourCounts[i] >= 4)
                    top = Math.Max(top, m_Buffers.Positions[i].y);
            return top + 0.5 * m_Spacing;
        }

        /// <summary>The least-squares line p = intercept + slope·y of the interior particles' pressures, their count and mean density.</summary>
        (double Intercept, double Slope, int Count, double Density) Fit(double surface)
        {
            FluidBuffers b = m_Buffers;
            double border = 2 * m_Constants.Kernels.H, sy = 0, sp = 0, syy = 0, syp = 0, density = 0;
            int n = 0;
            for (int i = 0; i < b.Status.Count; i++)
            {
                float3 x = b.Positions[i];
                if (!Interior(x, border, surface))
                    continue;
                double pressure = Pressure(i);
                n++;
                sy += x.y;
                sp += pressure;
                syy += (double)x.y * x.y;
                syp += x.y * pressure;
                density += b.Densities[i];
            }
            double denominator = n * syy - sy * sy;
            double slope = n > 2 && denominator > 0 ? (n * syp - sy * sp) / denominator : double.NaN;
            return (n > 0 ? (sp - slope * sy) / n : double.NaN, slope, n, n > 0 ? density / n : double.NaN);
        }

        void Measure(double early, double meanSlope, double meanSlopePerDensity)
        {
            FluidBuffers b = m_Buffers;
            double H = Surface();
            double rho0 = m_Constants.Parameters.RestDensity, g = 9.81, border = 2 * m_Constants.Kernels.H;
            double pErr = 0, pRef = 0, dErr = 0, ke = 0;
            for (int i = 0; i < b.Status.Count; i++)
            {
                float3 x = b.Positions[i];
                ke += 0.5 * math.lengthsq(b.Velocities[i]);
                if (!Interior(x, border, H))
                    continue;
                dErr += Math.Abs(b.Densities[i] / rho0 - 1);
                double reference = rho0 * g * (H - x.y);
                double pressure = Pressure(i);
                pErr += (pressure - reference) * (pressure - reference);
                pRef += reference * reference;
            }
            var (intercept, slope, interior, _) = Fit(H);
            bool tait = m_Constants.Parameters.Solver == FluidSolverKind.WeaklyCompressible;
            m_PressureError = tait && pRef > 0 ? Math.Sqrt(pErr / pRef) : double.NaN;
            // The slope dp/dy against the hydrostatic −ρ₀g is independent of where the surface is taken to be (the kernel's
            // deficiency there shifts p by a constant, not its gradient).
            m_GradientBias = tait ? meanSlope / (-rho0 * g) - 1 : double.NaN;
            m_OwnDensityGradientBias = tait ? meanSlopePerDensity / -g - 1 : double.NaN;
            // Where the last frame's fitted line reaches p = 0, below the particle surface H: the layer the kernel's
            // deficiency leaves without pressure (the density is clamped at ρ₀ there).
            m_SurfaceOffset = tait && slope < 0 ? H + intercept / slope : double.NaN;
            // Scatter of the particles' pressures about the fitted line (the stiff Tait law's acoustic noise), over the RMS reference.
            double residual = 0;
            for (int i = 0; i < b.Status.Count; i++)
            {
                if (!Interior(b.Positions[i], border, H))
                    continue;
                double d = Pressure(i) - (intercept + slope * b.Positions[i].y);
                residual += d * d;
            }
            m_PressureScatter = tait && pRef > 0 ? Math.Sqrt(residual / pRef) : double.NaN;
            m_DensityError = interior > 0 ? dErr / interior : double.NaN;
            m_Kinetic = ke / Math.Max(1, b.Status.Count);
            m_Drift = Math.Abs(H - early);
            m_Interior = interior;
        }

        bool Interior(float3 x, double border, double surface) =>
            !(x.x < border || x.x > s_Block.x - border || x.z < border || x.z > s_Block.z - border || x.y < border || x.y > surface - border);

        /// <summary>Pressure (Pa) of slot <paramref name="i"/>: the Tait pressure of its density from the last density pass.</summary>
        double Pressure(int i) => m_Constants.TaitPressure(m_Buffers.Densities[i]);

        public void Step() => Frame();

        public IReadOnlyList<Metric> Evaluate()
        {
            var bias = Mean(m => m.m_GradientBias);
            var ownBias = Mean(m => m.m_OwnDensityGradientBias);
            int lost = 0;
            foreach (HydrostaticColumnScenario m in m_Ensemble)
                lost += m.m_Initial - m.m_Buffers.Status.Count;
            return new[]
            {
                new Metric("pressure L2 error", Mean(m => m.m_PressureError).Mean, MetricUnit.Fraction),
                new Metric("pressure gradient error", Math.Abs(bias.Mean), MetricUnit.Fraction),
                new Metric("pressure gradient error spread", bias.Spread, MetricUnit.Fraction),
                new Metric("pressure gradient error (own density)", Math.Abs(ownBias.Mean), MetricUnit.Fraction),
                new Metric("pressure gradient error (own density) spread", ownBias.Spread, MetricUnit.Fraction),
                new Metric("zero-pressure depth", 1000 * Mean(m => m.m_SurfaceOffset).Mean, MetricUnit.Millimetre),
                new Metric("pressure scatter", Mean(m => m.m_PressureScatter).Mean, MetricUnit.Fraction),
                new Metric("density error", Mean(m => m.m_DensityError).Mean, MetricUnit.Fraction),
                new Metric("kinetic energy", Mean(m => m.m_Kinetic).Mean, MetricUnit.JoulePerKilogram),
                new Metric("surface drift", 1000 * Mean(m => m.m_Drift).Mean, MetricUnit.Millimetre),
                new Metric("interior particles", Mean(m => m.m_Interior).Mean, MetricUnit.Count),
                new Metric("ensemble members", m_Members, MetricUnit.Count),
                new Metric("particles lost", lost, MetricUnit.Count),
            };
        }

        (double Mean, double Spread) Mean(Func<HydrostaticColumnScenario, double> metric) => FluidScene.MeanAndSpread(m_Ensemble, metric);
    }
}
