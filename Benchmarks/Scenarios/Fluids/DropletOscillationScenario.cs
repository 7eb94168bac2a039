using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Droplet oscillation: a lattice ball of radius <see cref="BallRadius"/> (no gravity) settles for
    /// <see cref="SettleSeconds"/>, then σ is measured twice. From the pressure: σ_p = P·R/2 (Laplace), P the interior's
    /// mechanical pressure by the virial of the pair forces, P = (1/(3V))·Σ_pairs xᵢⱼ·Fᵢⱼ over the particles deeper than
    /// one kernel radius (<see cref="Measure"/>), which counts the cohesion's own tension with the equation-of-state
    /// pressure. From the frequency: the drop is given the l = 2 velocity v = ε·(−x, −y, 2z) about its centre of mass,
    /// the quadrupole Q = mean(2z² − x² − y²) is recorded every 1/60 s frame and fitted by a damped sine
    /// (<see cref="DampedSineFit"/>), and Rayleigh's ω² = 8σ/(ρR³) (Rayleigh 1879, l = 2) gives σ_f = ω²·3M/(32π),
    /// which needs only the mass M = N·m since ρR³ = 3M/(4π). R = (3V/(4π))^⅓ with V = N·m/ρ̄, ρ̄ the interior's mean
    /// density; volume change = ρ₀/ρ̄ − 1 (the bulk's compression), gyration volume change = (R_g/R_g,0)³ − 1 with R_g the
    /// gyration radius and R_g,0 that of the starting lattice ball (the compaction of the whole mass, the surface layer's
    /// included). Each timed Step is one more 1/60 s frame; an item is one particle-substep.
    /// </summary>
    public sealed class DropletOscillationScenario : IScenario
    {
        /// <summary>Radius of the lattice ball the drop starts as (m).</summary>
        public const float BallRadius = 0.05f;
        /// <summary>Settling time before the measurements (s).</summary>
        public const float SettleSeconds = 3f;
        /// <summary>Default surface amplitude of the excited mode over R (the drop's a/R): ε = a/R·ω/2.</summary>
        public const double DefaultAmplitude = 0.1;
        /// <summary>Periods of the mode (at the pressure's σ) recorded.</summary>
        public const double Periods = 3;
        /// <summary>Frames at the end of the settling over which the stress is averaged.</summary>
        public const int AveragedFrames = 15;
        const float k_Frame = 1f / 60f;

        readonly float m_Spacing;
        readonly FluidParameters m_Parameters;
        readonly string m_Setting;
        readonly double m_Excitation;
        readonly int m_Members;
        DropletOscillationScenario[] m_Ensemble;
        FluidConstants m_Constants;
        FluidBuffers m_Buffers;
        long m_Items;
        int m_Initial;
        DropletStress m_Stress;
        double m_Omega, m_Damping, m_Residual, m_FittedAmplitude, m_InitialGyration;

        /// <param name="spacing">Particle spacing Δx (m).</param>
        /// <param name="parameters">The fluid and its cohesion; spacing, domain and gravity are set by the scene.</param>
        /// <param name="setting">The row's label.</param>
        /// <param name="amplitude">Surface amplitude a/R of the excited mode.</param>
        /// <param name="members">
        /// Drops run in parallel whose ν is scaled by 1 + k/100 (k = 0 … members − 1; water's ν, nothing a drop can feel):
        /// one drop's σ ratio moves by 0.1–0.4 under such a change, so the metrics are the members' means, the σ ratio with its spread.
        /// </param>
        public DropletOscillationScenario(float spacing, FluidParameters parameters, string setting, double amplitude = DefaultAmplitude, int members = 1)
        {
            m_Members = Math.Max(1, members);
            m_Excitation = amplitude;
            m_Spacing = spacing;
            m_Parameters = parameters;
            m_Setting = setting;
        }

        public string Name => "DropletOscillation";
        public string Method => $"{DamBreakScenario.SolverName(m_Parameters.Solver)} {m_Setting}, Δx = {1000f * m_Spacing:0.#} mm";
        public int Size => BallCount(m_Spacing);
        public string SizeUnit => "particles";
        public long ItemsPerStep => Math.Max(1, m_Items);

        /// <summary>Lattice points (a point at the centre) within <see cref="BallRadius"/>.</summary>
        public static int BallCount(float spacing) => BallPoints(spacing).Count;

        /// <summary>The points of a cubic lattice of <paramref name="spacing"/>, one at the origin, within <see cref="BallRadius"/>.</summary>
        static List<float3> BallPoints(float spacing)
        {
            var points = new List<float3>();
            int n = (int)math.floor(BallRadius / spacing + 1e-3f);
            for (int z = -n; z <= n; z++)
            for (int y = -n; y <= n; y++)
            for (int x = -n; x <= n; x++)
            {
                float3 xi = new float3(x, y, z) * spacing;
                if (math.lengthsq(xi) <= BallRadius * BallRadius * (1f + 1e-4f))
                    points.Add(xi);
            }
            return points;
        }

        /// <summary>The scene's fluid: <paramref name="parameters"/> at <paramref name="spacing"/> in a 0.4 m box, no gravity, no slow motion.</summary>
        public static FluidParameters Scene(FluidParameters parameters, float spacing)
        {
            parameters.ParticleSpacing = spacing;
            parameters.DomainMin = new float3(-0.2f);
            parameters.DomainMax = new float3(0.2f);
            parameters.Gravity = float3.zero;
            parameters.MaxSubsteps = FluidParameters.SubstepLimit;
            return parameters;
        }

        /// <summary>Buffers holding the lattice ball.</summary>
        public static FluidBuffers Ball(in FluidConstants c, float spacing)
        {
            List<float3> points = BallPoints(spacing);
            var b = new FluidBuffers(points.Count, c.Grid);
            for (int i = 0; i < points.Count; i++)
            {
                b.Positions[i] = points[i];
                b.Ids[i] = i;
            }
            b.Status = new FluidStatus { Count = points.Count, NextId = points.Count, Spawned = points.Count };
            return b;
        }

        public void Setup()
        {
            m_Ensemble = FluidScene.Ensemble(this, m_Members, m_Parameters,
                p => new DropletOscillationScenario(m_Spacing, p, m_Setting, m_Excitation), m => m.Run());
        }

        /// <summary>Settles this member's drop, measures its stress, excites the l = 2 mode and fits it.</summary>
        void Run()
        {
            m_Constants = new FluidConstants(Scene(m_Parameters, m_Spacing));
            m_Buffers = Ball(m_Constants, m_Spacing);
            m_Initial = m_Buffers.Status.Count;
            m_InitialGyration = Measure(m_Constants, m_Buffers).GyrationRadius;
            int settle = (int)Math.Round(SettleSeconds / k_Frame);
            for (int f = 0; f < settle - AveragedFrames; f++)
                Frame();
            // The stress is averaged over the last frames of the settling: the drop still breathes a little.
            var samples = new DropletStress[AveragedFrames];
            for (int f = 0; f < AveragedFrames; f++)
            {
                Frame();
                samples[f] = Measure(m_Constants, m_Buffers);
            }
            m_Stress = DropletStress.Mean(samples);
            double guess = m_Stress.RayleighOmega(m_Stress.PressureTension);
            Excite(m_Buffers, m_Excitation * guess / 2);
            int frames = (int)Math.Ceiling(Periods * 2 * Math.PI / guess / k_Frame);
            var t = new double[frames + 1];
            var q = new double[frames + 1];
            q[0] = Quadrupole(m_Buffers);
            for (int f = 1; f <= frames; f++)
            {
                t[f] = t[f - 1] + Frame().SimulatedTime;
                q[f] = Quadrupole(m_Buffers);
            }
            var fit = DampedSineFit.Fit(t, q, CrossingOmega(t, q, guess));
            m_Omega = fit.omega;
            m_Damping = fit.damping;
            m_Residual = fit.residual;
            m_FittedAmplitude = fit.amplitude;
        }

        /// <summary>The settled drop's stress (after Setup).</summary>
        public DropletStress Stress => m_Stress;

        /// <summary>σ from the frequency, σ_f = ω²·3M/(32π) (N/m).</summary>
        public double FrequencyTension => m_Omega * m_Omega * 3 * m_Stress.Mass / (32 * Math.PI);

        FluidStepReport Frame()
        {
            FluidStepReport r = FluidScene.Step(m_Constants, m_Buffers, k_Frame);
            m_Items = (long)r.Substeps * r.Count;
            return r;
        }

        static float3 Centre(FluidBuffers b)
        {
            double x = 0, y = 0, z = 0;
            for (int i = 0; i < b.Status.Count; i++)
            {
                x += b.Positions[i].x;
                y += b.Positions[i].y;
                z += b.Positions[i].z;
            }
            int n = math.max(1, b.Status.Count);
            return new float3((float)(x / n), (float)(y / n), (float)(z / n));
        }

        /// <summary>Sets v = ε·(−x, −y, 2z) about the centre of mass (the linear l = 2 flow, ∇·v = 0) plus the drop's mean velocity.</summary>
        public static void Excite(FluidBuffers b, double epsilon)
        {
            float3 centre = Centre(b);
            for (int i = 0; i < b.Status.Count; i++)
            {
                float3 x = b.Positions[i] - centre;
                b.Velocities[i] += (float)epsilon * new float3(-x.x, -x.y, 2f * x.z);
            }
        }

        /// <summary>Q = mean(2z² − x² − y²) about the centre of mass (m²).</summary>
        public static double Quadrupole(FluidBuffers b)
        {
            float3 centre = Centre(b);
            double sum = 0;
            for (int i = 0; i < b.Status.Count; i++)
            {
                float3 x = b.Positions[i] - centre;
                sum += 2.0 * x.z * x.z - x.x * x.x - x.y * x.y;
            }
            return sum / math.max(1, b.Status.Count);
        }

        /// <summary>π over the mean time between the crossings of the mean by <paramref name="y"/>; <paramref name="fallback"/> with fewer than two.</summary>
        static double CrossingOmega(double[] t, double[] y, double fallback)
        {
            double mean = 0;
            foreach (double v in y)
                mean += v / y.Length;
            double first = double.NaN, last = double.NaN;
            int crossings = 0;
            for (int i = 1; i < y.Length; i++)
            {
                if ((y[i - 1] - mean) * (y[i] - mean) >= 0)
                    continue;
                double tc = t[i - 1] + (t[i] - t[i - 1]) * (mean - y[i - 1]) / (y[i] - y[i - 1]);
                if (crossings++ == 0)
                    first = tc;
                last = tc;
            }
            return crossings >= 2 ? Math.PI * (crossings - 1) / (last - first) : fallback;
        }

        /// <summary>
        /// The stress of the drop in <paramref name="b"/> at its positions: a sort, density and normals pass (as a substep
        /// starts), then over the interior (particles closer to the centre of mass than R − <paramref name="margin"/>·h) the virial pressures
        /// P = (1/(3V))·Σᵢ ½Σⱼ xᵢⱼ·m·aᵢⱼ of the pressure pair term (with the artificial viscosity) and of the Akinci pair
        /// term, V = Σᵢ m/ρᵢ, and the mean equation-of-state pressure. Reorders the particles.
        /// </summary>
        public static DropletStress Measure(in FluidConstants c, FluidBuffers b, float margin = 1f)
        {
            FluidParameters prm = c.Parameters;
            SphKernels k = c.Kernels;
            int count = b.Status.Count;
            var counters = new FluidPassCounters();
            FluidPasses.Run(FluidPass.Sort, c, ReadOnlySpan<ColliderShape>.Empty, b.Particles, b.Scratch, 0, 1, ref count, 0f, ref counters);
            FluidPasses.Run(FluidPass.Density, c, ReadOnlySpan<ColliderShape>.Empty, b.Particles, b.Scratch, 0, 1, ref count, 0f, ref counters);
            FluidPasses.Run(FluidPass.SurfaceNormals, c, ReadOnlySpan<ColliderShape>.Empty, b.Particles, b.Scratch, 0, 1, ref count, 0f, ref counters);
            float3 centre = Centre(b);
            float m = c.Mass, rho0 = prm.RestDensity;
            bool akinci = prm.Cohesion == FluidCohesionModel.Akinci;
            // Radius of gyration: Σ|x|²/N + Δx²/4 (each point's own cube) = (3/5)R² for a uniform ball.
            double r2 = 0;
            for (int i = 0; i < count; i++)
                r2 += math.lengthsq(b.Positions[i] - centre);
            double gyration = Math.Sqrt(5.0 / 3.0 * (r2 / count + prm.ParticleSpacing * prm.ParticleSpacing / 4.0));
            double deep = gyration - margin * k.H;
            float alphaCh = 2f * c.EffectiveArtificialViscosity * prm.SpeedOfSound * k.H, eta2 = 0.01f * k.H2;
            double volume = 0, eos = 0, pressureVirial = 0, cohesionVirial = 0, kinetic = 0;
            int interior = 0;
            for (int i = 0; i < count; i++)
            {
                float3 xi = b.Positions[i];
                if (!(math.length(xi - centre) < deep))
                    continue;
                interior++;
                float rhoi = b.Densities[i];
                volume += m / rhoi;
                eos += c.TaitPressure(rhoi);
                kinetic += m * math.lengthsq(b.Velocities[i]);
                for (int a = 0; a < b.NeighbourCounts[i]; a++)
                {
                    int j = b.Neighbours[i * FluidScratch.MaxNeighbours + a];
                    float3 rij = xi - b.Positions[j];
                    float r = math.length(rij);
                    if (!(r > 0f) || !(r < k.H))
                        continue;
                    // Pressure pair force m·aᵢⱼ = −m²·C_spiky·κ∇·(p̃ᵢ + p̃ⱼ + Πᵢⱼ)·(h − r)²·r̂, so xᵢⱼ·F = −m²·C·κ∇·s·(h − r)²·r.
                    float approach = math.min(math.dot(b.Velocities[i] - b.Velocities[j], rij), 0f);
                    float scale = b.Pressures[i] + b.Pressures[j] - alphaCh * approach / ((rhoi + b.Densities[j]) * (r * r + eta2));
                    float hr = k.H - r;
                    pressureVirial += 0.5 * -m * m * k.SpikyGradientCoefficient * c.GradientCorrection * scale * hr * hr * r;
                    if (akinci)
                    {
                        // Akinci pair force m·aᵢⱼ = −γ·m·Kᵢⱼ·(m·C(r)·r̂ + nᵢ − nⱼ).
                        float kij = 2f * rho0 / (rhoi + b.Densities[j]);
                        float3 f = -prm.SurfaceTension * m * kij * (m * k.Cohesion(r) / r * rij + b.VectorsB[i] - b.VectorsB[j]);
                        cohesionVirial += 0.5 * math.dot(rij, f);
                    }
                }
            }
            double density = interior > 0 ? interior * m / volume : double.NaN;
            return new DropletStress
            {
                Count = count,
                Interior = interior,
                Mass = count * m,
                Density = density,
                Radius = Math.Pow(3.0 * count * m / density / (4 * Math.PI), 1.0 / 3.0),
                GyrationRadius = gyration,
                EosPressure = eos / Math.Max(1, interior),
                PressureVirial = pressureVirial / (3 * volume),
                CohesionVirial = cohesionVirial / (3 * volume),
                KineticPressure = kinetic / (3 * volume),
            };
        }

        public void Step() => Frame();

        public IReadOnlyList<Metric> Evaluate()
        {
            int lost = 0;
            foreach (DropletOscillationScenario m in m_Ensemble)
                lost += m.m_Initial - m.m_Buffers.Status.Count;
            var ratio = FluidScene.MeanAndSpread(m_Ensemble, m => m.FrequencyTension / m.m_Stress.PressureTension);
            return new[]
            {
                new Metric("σ from pressure (N/m)", Mean(m => m.m_Stress.PressureTension), MetricUnit.Dimensionless),
                new Metric("σ from EOS pressure (N/m)", Mean(m => m.m_Stress.EosTension), MetricUnit.Dimensionless),
                new Metric("σ from frequency (N/m)", Mean(m => m.FrequencyTension), MetricUnit.Dimensionless),
                new Metric("σ ratio", ratio.Mean, MetricUnit.Dimensionless),
                new Metric("σ ratio spread", ratio.Spread, MetricUnit.Dimensionless),
                new Metric("frequency error", Mean(m => m.m_Omega / m.m_Stress.RayleighOmega(m.m_Stress.PressureTension) - 1), MetricUnit.Fraction),
                new Metric("damping ratio", Mean(m => m.m_Damping / m.m_Omega), MetricUnit.Dimensionless),
                new Metric("fit residual", Mean(m => m.m_Residual / m.m_FittedAmplitude), MetricUnit.Fraction),
                new Metric("volume change", Mean(m => m.m_Stress.VolumeChange(m.m_Parameters.RestDensity)), MetricUnit.Fraction),
                new Metric("gyration volume change", Mean(m => Math.Pow(m.m_Stress.GyrationRadius / m.m_InitialGyration, 3) - 1), MetricUnit.Fraction),
                new Metric("radius", 1000 * Mean(m => m.m_Stress.Radius), MetricUnit.Millimetre),
                new Metric("ensemble members", m_Members, MetricUnit.Count),
                new Metric("particles lost", lost, MetricUnit.Count),
            };
        }

        double Mean(Func<DropletOscillationScenario, double> metric) => FluidScene.MeanAndSpread(m_Ensemble, metric).Mean;
    }

    /// <summary>The stress of a settled drop (<see cref="DropletOscillationScenario.Measure"/>); pressures in Pa.</summary>
    public struct DropletStress
    {
        /// <summary>Particles in the drop and in its interior.</summary>
        public int Count, Interior;
        /// <summary>Drop mass N·m (kg), interior mean density ρ̄ = N_int·m/Σ(m/ρᵢ) (kg/m³), R = (3Nm/(4πρ̄))^⅓ and the gyration radius √(5/3·(⟨r²⟩ + Δx²/4)) (m).</summary>
        public double Mass, Density, Radius, GyrationRadius;
        /// <summary>Interior's mean Tait pressure, and the virial pressures of the pressure pair term, the Akinci pair term and the motion.</summary>
        public double EosPressure, PressureVirial, CohesionVirial, KineticPressure;

        /// <summary>The field-wise mean of <paramref name="samples"/> (counts from the first).</summary>
        public static DropletStress Mean(DropletStress[] samples)
        {
            DropletStress m = samples[0];
            m.Density = m.Radius = m.GyrationRadius = m.EosPressure = m.PressureVirial = m.CohesionVirial = m.KineticPressure = 0;
            foreach (DropletStress s in samples)
            {
                m.Density += s.Density / samples.Length;
                m.Radius += s.Radius / samples.Length;
                m.GyrationRadius += s.GyrationRadius / samples.Length;
                m.EosPressure += s.EosPressure / samples.Length;
                m.PressureVirial += s.PressureVirial / samples.Length;
                m.CohesionVirial += s.CohesionVirial / samples.Length;
                m.KineticPressure += s.KineticPressure / samples.Length;
            }
            return m;
        }

        /// <summary>Total mechanical pressure of the interior.</summary>
        public double Pressure => PressureVirial + CohesionVirial + KineticPressure;

        /// <summary>σ_p = P·R/2 (Laplace).</summary>
        public double PressureTension => Pressure * Radius / 2;

        /// <summary>σ from the Tait pressure alone, p·R/2.</summary>
        public double EosTension => EosPressure * Radius / 2;

        /// <summary>Rayleigh's l = 2 angular frequency for <paramref name="sigma"/>: ω² = 8σ/(ρR³) = 32πσ/(3M).</summary>
        public double RayleighOmega(double sigma) => Math.Sqrt(32 * Math.PI * sigma / (3 * Mass));

        /// <summary>Volume change N·m/ρ̄ over N·m/ρ₀, minus 1.</summary>
        public double VolumeChange(double restDensity) => restDensity / Density - 1;
    }
}
