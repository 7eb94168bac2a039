using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Hydrostatic column: a 0.3 × 0.4 × 0.3 m block of water (Δx = 2.5 cm, h = 5 cm, 2304 particles) released at rest in a
    /// box of the same footprint. Setup runs it for the settle time (10 s in the full run) in 1/60 s frames and
    /// measures: the interior pressure's L2 error against ρ₀·g·(H − y) and the error of its least-squares gradient against
    /// −ρ₀g, where that line reaches zero and the particles' scatter about it (interior = at least two kernel radii 2h from the walls, the floor and the surface, where the kernel's
    /// deficiency is expected: 128 particles; weakly compressible only, position-based fluids have no pressure), the mean interior
    /// density error, the kinetic energy per particle mass and how far the surface moved over the last 90 % of the
    /// run. Each timed Step is one more 1/60 s frame of the settled column; an item is one particle-substep.
    /// </summary>
    public sealed class HydrostaticColumnScenario : IScenario
    {
        const float k_Spacing = 0.025f;
        const float k_Frame = 1f / 60f;
        static readonly float3 s_Block = new float3(0.3f, 0.4f, 0.3f);

        readonly FluidParameters m_Parameters;
        readonly string m_Setting;
        readonly float m_SettleSeconds;
        FluidConstants m_Constants;
        FluidBuffers m_Buffers;
        long m_Items;
        int m_Initial;
        double m_PressureError, m_GradientError, m_DensityError, m_Kinetic, m_Drift, m_SurfaceOffset, m_PressureScatter;
        int m_Interior;

        public HydrostaticColumnScenario(FluidParameters parameters, string setting, float settleSeconds)
        {
            m_Parameters = parameters;
            m_Setting = setting;
            m_SettleSeconds = settleSeconds;
        }

        public string Name => "HydrostaticColumn";
        public string Method => $"{DamBreakScenario.SolverName(m_Parameters.Solver)} {m_Setting}, {m_SettleSeconds:0.#} s";
        public int Size => m_Initial > 0 ? m_Initial : FluidScene.BlockCount(float3.zero, s_Block, k_Spacing);
        public string SizeUnit => "particles";
        public long ItemsPerStep => Math.Max(1, m_Items);

        /// <summary>Reference speed √(2gH) of the column (m/s).</summary>
        public static float ReferenceSpeed => (float)Math.Sqrt(2 * 9.81 * s_Block.y);

        public void Setup()
        {
            m_Buffers = FluidScene.BlockInBox(m_Parameters, k_Spacing, new float3(s_Block.x, 1.5f * s_Block.y, s_Block.z), s_Block, out m_Constants);
            m_Initial = m_Buffers.Status.Count;
            int frames = (int)Math.Round(m_SettleSeconds / k_Frame);
            double early = double.NaN;
            for (int f = 0; f < frames; f++)
            {
                Frame();
                if (f == frames / 10)
                    early = Surface();
            }
            Measure(early);
        }

        FluidStepReport Frame()
        {
            FluidBuffers b = m_Buffers;
            FluidStepReport r = FluidSolver.Step(m_Constants, ReadOnlySpan<ColliderShape>.Empty, k_Frame, b.Particles, b.Scratch, ref b.Status);
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
            return top + 0.5 * k_Spacing;
        }

        void Measure(double early)
        {
            FluidBuffers b = m_Buffers;
            double H = Surface();
            double rho0 = m_Constants.Parameters.RestDensity, g = 9.81, border = 2 * m_Constants.Kernels.H;
            double pErr = 0, pRef = 0, dErr = 0, ke = 0;
            double sy = 0, sp = 0, syy = 0, syp = 0;
            int interior = 0;
            for (int i = 0; i < b.Status.Count; i++)
            {
                float3 x = b.Positions[i];
                ke += 0.5 * math.lengthsq(b.Velocities[i]);
                if (!Interior(x, border, H))
                    continue;
                interior++;
                double rho = b.Densities[i];
                dErr += Math.Abs(rho / rho0 - 1);
                double reference = rho0 * g * (H - x.y);
                double pressure = Pressure(i);
                pErr += (pressure - reference) * (pressure - reference);
                pRef += reference * reference;
                sy += x.y;
                sp += pressure;
                syy += (double)x.y * x.y;
                syp += x.y * pressure;
            }
            bool tait = m_Constants.Parameters.Solver == FluidSolverKind.WeaklyCompressible;
            m_PressureError = tait && pRef > 0 ? Math.Sqrt(pErr / pRef) : double.NaN;
            // Least-squares slope dp/dy of the interior pressure against the hydrostatic −ρ₀g: independent of where the
            // surface is taken to be (the kernel's deficiency there shifts p by a constant, not its gradient).
            double denominator = interior * syy - sy * sy;
            double slope = denominator > 0 ? (interior * syp - sy * sp) / denominator : double.NaN;
            m_GradientError = tait && interior > 2 ? Math.Abs(slope / (-rho0 * g) - 1) : double.NaN;
            // Where the fitted line reaches p = 0, below the particle surface H: the layer the kernel's deficiency leaves
            // without pressure (the density is clamped at ρ₀ there).
            double intercept = interior > 0 ? (sp - slope * sy) / interior : double.NaN;
            m_SurfaceOffset = tait && interior > 2 && slope < 0 ? H + intercept / slope : double.NaN;
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

        /// <summary>Pressure (Pa) of slot <paramref name="i"/> from the last density pass (stored as p/ρ² with ρ clamped at ρ₀).</summary>
        double Pressure(int i)
        {
            double rc = Math.Max(m_Buffers.Densities[i], m_Constants.Parameters.RestDensity);
            return m_Buffers.Scratch.Pressures[i] * rc * rc;
        }

        public void Step() => Frame();

        public IReadOnlyList<Metric> Evaluate() => new[]
        {
            new Metric("pressure L2 error", m_PressureError, MetricUnit.Fraction),
            new Metric("pressure gradient error", m_GradientError, MetricUnit.Fraction),
            new Metric("zero-pressure depth", 1000 * m_SurfaceOffset, MetricUnit.Millimetre),
            new Metric("pressure scatter", m_PressureScatter, MetricUnit.Fraction),
            new Metric("density error", m_DensityError, MetricUnit.Fraction),
            new Metric("kinetic energy", m_Kinetic, MetricUnit.JoulePerKilogram),
            new Metric("surface drift", 1000 * m_Drift, MetricUnit.Millimetre),
            new Metric("interior particles", m_Interior, MetricUnit.Count),
            new Metric("particles lost", m_Initial - m_Buffers.Status.Count, MetricUnit.Count),
        };
    }
}
