using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Droplet: a 10 cm cube of fluid (Δx = 1 cm, 1000 particles) without gravity relaxes toward a sphere under its
    /// cohesion. Sphericity = the cloud's smallest width over its largest, over <see cref="DirectionCount"/> directions
    /// (a Fibonacci set on the half-sphere; width = the spread of the particle centres along the direction plus one spacing,
    /// the extent of the end particles' volumes): 1 for a ball, 0.60 for this cube (1/√3 for a continuous cube), and blind
    /// to the drop's volume. Time to round = the first time the sphericity reaches <see cref="RoundSphericity"/>. Radius
    /// error = r_max/R − 1, the farthest particle centre from the centre of mass over the radius R of the ball of the same
    /// volume (0.26 for the cube, negative when cohesion squeezes the drop below its rest volume). One Step is the whole
    /// run in 1/60 s frames; an item is one particle-substep.
    /// </summary>
    public sealed class DropletScenario : IScenario, IScenarioRepeatCap, IScenarioShortWarmup
    {
        const float k_Spacing = 0.01f;
        const int k_Side = 10;
        const float k_Frame = 1f / 60f;
        /// <summary>Directions over which the widths are taken.</summary>
        public const int DirectionCount = 100;
        /// <summary>Sphericity that counts as round.</summary>
        public const double RoundSphericity = 0.95;
        /// <summary>Times (s) at which the sphericity is reported.</summary>
        public static readonly double[] ReportTimes = { 0.25, 0.5, 1.0 };
        static readonly float3[] s_Directions = HalfSphereDirections(DirectionCount);

        readonly FluidParameters m_Parameters;
        readonly string m_Setting;
        readonly float m_Seconds;
        FluidConstants m_Constants;
        FluidBuffers m_Buffers;
        float3[] m_Initial;
        double[] m_Sphericity;
        long m_Items;
        double m_RadiusError, m_TimeToRound, m_DensityError, m_Speed;

        /// <summary>A droplet with the cohesion of <paramref name="parameters"/> (spacing, domain and gravity are set here), run for <paramref name="seconds"/>.</summary>
        public DropletScenario(FluidParameters parameters, string setting, float seconds = 2f)
        {
            m_Parameters = parameters;
            m_Setting = setting;
            m_Seconds = seconds;
        }

        public string Name => "Droplet";
        public string Method => $"{DamBreakScenario.SolverName(m_Parameters.Solver)} {m_Setting}";
        public int Size => k_Side * k_Side * k_Side;
        public string SizeUnit => "particles";
        public long ItemsPerStep => Math.Max(1, m_Items);
        public int MaxRepeats => 1;

        public void Setup()
        {
            FluidParameters p = m_Parameters;
            p.ParticleSpacing = k_Spacing;
            p.DomainMin = new float3(-0.2f);
            p.DomainMax = new float3(0.2f);
            p.Gravity = float3.zero;
            m_Constants = new FluidConstants(p);
            m_Buffers = new FluidBuffers(Size, m_Constants.Grid);
            float half = 0.5f * k_Side * k_Spacing;
            FluidScene.FillBlock(m_Buffers, new float3(-half), new float3(half), k_Spacing);
            m_Initial = (float3[])m_Buffers.Positions.Clone();
            m_Sphericity = new double[Frames + 1];
        }

        int Frames => (int)Math.Round(m_Seconds / k_Frame);

        /// <summary>Frames of the short warm-up.</summary>
        const int k_WarmupFrames = 5;

        public void Step() => Run(Frames);

        public void WarmupFrames() => Run(Math.Min(k_WarmupFrames, Frames));

        /// <summary>The run from the cube: <paramref name="frames"/> frames, then the end-state measures.</summary>
        void Run(int frames)
        {
            FluidBuffers b = m_Buffers;
            FluidScene.Restart(b, m_Initial);
            double radius = Math.Pow(3.0 * Size * k_Spacing * k_Spacing * k_Spacing / (4 * Math.PI), 1.0 / 3.0);
            m_Items = 0;
            m_TimeToRound = double.NaN;
            m_Sphericity[0] = Sphericity(b, k_Spacing);
            for (int f = 1; f <= frames; f++)
            {
                FluidStepReport r = FluidSolver.Step(m_Constants, ReadOnlySpan<ColliderShape>.Empty, k_Frame, b.Particles, b.Scratch, ref b.Status);
                m_Items += (long)r.Substeps * r.Count;
                m_Sphericity[f] = Sphericity(b, k_Spacing);
                if (double.IsNaN(m_TimeToRound) && m_Sphericity[f] >= RoundSphericity)
                    m_TimeToRound = f * k_Frame;
            }
            m_RadiusError = FarthestFromCentre(b) / radius - 1;
            m_DensityError = FluidScene.MeanBulkDensityError(b, m_Constants.Parameters.RestDensity, 0);
            double v2 = 0;
            for (int i = 0; i < b.Status.Count; i++)
                v2 += math.lengthsq(b.Velocities[i]);
            m_Speed = Math.Sqrt(v2 / Math.Max(1, b.Status.Count));
        }

        /// <summary>Smallest over largest width of the particles over the direction set (widths + <paramref name="spacing"/>); 0 without particles.</summary>
        public static double Sphericity(FluidBuffers b, float spacing)
        {
            int n = b.Status.Count;
            if (n == 0)
                return 0;
            double narrowest = double.PositiveInfinity, widest = 0;
            foreach (float3 u in s_Directions)
            {
                float lo = float.PositiveInfinity, hi = float.NegativeInfinity;
                for (int i = 0; i < n; i++)
                {
                    float s = math.dot(b.Positions[i], u);
                    lo = math.min(lo, s);
                    hi = math.max(hi, s);
                }
                double width = hi - lo + spacing;
                narrowest = Math.Min(narrowest, width);
                widest = Math.Max(widest, width);
            }
            return narrowest / widest;
        }

        /// <summary><paramref name="count"/> unit vectors spread over the half-sphere z &gt; 0 (a Fibonacci lattice: z uniform, golden-angle azimuth).</summary>
        static float3[] HalfSphereDirections(int count)
        {
            var directions = new float3[count];
            double golden = Math.PI * (3 - Math.Sqrt(5));
            for (int k = 0; k < count; k++)
            {
                double z = (k + 0.5) / count, r = Math.Sqrt(1 - z * z), phi = k * golden;
                directions[k] = new float3((float)(r * Math.Cos(phi)), (float)(r * Math.Sin(phi)), (float)z);
            }
            return directions;
        }

        static double FarthestFromCentre(FluidBuffers b)
        {
            double cx = 0, cy = 0, cz = 0;
            int n = Math.Max(1, b.Status.Count);
            for (int i = 0; i < b.Status.Count; i++)
            {
                cx += b.Positions[i].x;
                cy += b.Positions[i].y;
                cz += b.Positions[i].z;
            }
            cx /= n;
            cy /= n;
            cz /= n;
            double far = 0;
            for (int i = 0; i < b.Status.Count; i++)
            {
                double dx = b.Positions[i].x - cx, dy = b.Positions[i].y - cy, dz = b.Positions[i].z - cz;
                far = Math.Max(far, Math.Sqrt(dx * dx + dy * dy + dz * dz));
            }
            return far;
        }

        /// <summary>The sphericity at <paramref name="seconds"/> (the nearest frame), NaN past the run.</summary>
        public double SphericityAt(double seconds)
        {
            int f = (int)Math.Round(seconds / k_Frame);
            return f >= 0 && f <= Frames ? m_Sphericity[f] : double.NaN;
        }

        public IReadOnlyList<Metric> Evaluate()
        {
            var metrics = new List<Metric> { new Metric("sphericity at 0 s", m_Sphericity[0], MetricUnit.Dimensionless) };
            foreach (double t in ReportTimes)
                metrics.Add(new Metric($"sphericity at {t:0.##} s", SphericityAt(t), MetricUnit.Dimensionless));
            metrics.Add(new Metric("sphericity", m_Sphericity[Frames], MetricUnit.Dimensionless));
            metrics.Add(new Metric("time to round", m_TimeToRound, MetricUnit.Second));
            metrics.Add(new Metric("radius error", m_RadiusError, MetricUnit.Fraction));
            metrics.Add(new Metric("density error", m_DensityError, MetricUnit.Fraction));
            metrics.Add(new Metric("RMS speed", m_Speed, MetricUnit.MetrePerSecond));
            return metrics;
        }
    }
}
