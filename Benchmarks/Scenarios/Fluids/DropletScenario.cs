using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Droplet: a 10 cm cube of fluid (Δx = 1 cm, 1000 particles) without gravity relaxes toward a sphere under its
    /// cohesion. Shape error = r_max/R − 1, the farthest particle centre from the centre of mass over the radius R
    /// of the ball of the same volume (0.26 for the cube's corners, 0 for a ball of lattice points up to half a
    /// spacing; negative when cohesion squeezes the drop below the ball of its rest volume); time to round = first time
    /// |shape error| drops below 5 %. One Step is the whole 2 s run in 1/60 s
    /// frames; an item is one particle-substep.
    /// </summary>
    public sealed class DropletScenario : IScenario, IScenarioRepeatCap
    {
        const float k_Spacing = 0.01f;
        const int k_Side = 10;
        const float k_Frame = 1f / 60f;
        const float k_Seconds = 2f;

        readonly FluidParameters m_Parameters;
        readonly string m_Setting;
        FluidConstants m_Constants;
        FluidBuffers m_Buffers;
        float3[] m_Initial;
        long m_Items;
        double m_ShapeError, m_TimeToRound, m_DensityError, m_Speed;

        public DropletScenario(FluidParameters parameters, string setting)
        {
            m_Parameters = parameters;
            m_Setting = setting;
        }

        public string Name => "Droplet";
        public string Method => $"{DamBreakScenario.SolverName(m_Parameters.Solver)} {m_Setting}";
        public int Size => k_Side * k_Side * k_Side;
        public string SizeUnit => "particles";
        public long ItemsPerStep => Math.Max(1, m_Items);
        public int MaxRepeats => 3;

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
        }

        public void Step()
        {
            FluidBuffers b = m_Buffers;
            Array.Copy(m_Initial, b.Positions, Size);
            Array.Clear(b.Velocities, 0, Size);
            Array.Clear(b.Ages, 0, Size);
            for (int i = 0; i < Size; i++)
                b.Ids[i] = i;
            b.Status = new FluidStatus { Count = Size, NextId = Size, Spawned = Size };
            double radius = Math.Pow(3.0 * Size * k_Spacing * k_Spacing * k_Spacing / (4 * Math.PI), 1.0 / 3.0);
            int frames = (int)Math.Round(k_Seconds / k_Frame);
            m_Items = 0;
            m_TimeToRound = double.NaN;
            for (int f = 1; f <= frames; f++)
            {
                FluidStepReport r = FluidSolver.Step(m_Constants, ReadOnlySpan<ColliderShape>.Empty, k_Frame, b.Particles, b.Scratch, ref b.Status);
                m_Items += (long)r.Substeps * r.Count;
                m_ShapeError = FarthestFromCentre(b) / radius - 1;
                if (double.IsNaN(m_TimeToRound) && Math.Abs(m_ShapeError) < 0.05)
                    m_TimeToRound = f * k_Frame;
            }
            m_DensityError = FluidScene.MeanBulkDensityError(b, m_Constants.Parameters.RestDensity, 0);
            double v2 = 0;
            for (int i = 0; i < b.Status.Count; i++)
                v2 += math.lengthsq(b.Velocities[i]);
            m_Speed = Math.Sqrt(v2 / Math.Max(1, b.Status.Count));
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

        public IReadOnlyList<Metric> Evaluate() => new[]
        {
            new Metric("shape error", 100 * m_ShapeError, "%"),
            new Metric("time to round", m_TimeToRound, "s"),
            new Metric("density error", 100 * m_DensityError, "%"),
            new Metric("RMS speed", m_Speed, "m/s"),
        };
    }
}
