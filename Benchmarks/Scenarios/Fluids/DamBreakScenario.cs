using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Dam break of Martin &amp; Moyce 1952 (n² = 2): a water column a = 0.05715 m wide and 2a high against the left
    /// wall of a tank 6a long and 3a high, dry bed, as a slab four particles deep between free-slip walls (the
    /// experiment is two-dimensional; <see cref="FluidParameters.DomainFriction"/>.z stays 0 so they are symmetry planes).
    /// One Step is the whole run from release to T = <see cref="EndT"/>, in frames of 1/500 s (each split into CFL
    /// substeps); an item is one particle-substep. The front is the leading edge of the bulk (<see cref="FluidScene.BulkFront"/>,
    /// particles with ≥ 4 neighbours) and the residual column the bulk's height at the wall it stood against
    /// (<see cref="FluidScene.BulkHeightAtWall"/>), sampled every frame and interpolated at the tables' times.
    /// </summary>
    public sealed class DamBreakScenario : IScenario, IScenarioRepeatCap, IScenarioShortWarmup
    {
        /// <summary>Frame length (s) of the run: the front is sampled at this interval (ΔT ≈ 0.037).</summary>
        public const float FrameSeconds = 1f / 500f;
        /// <summary>Dimensionless end time of a run: past the height table's τ = 3.44 (T = τ√2 = 4.86), before the front's reflection returns.</summary>
        public const double EndT = 4.9;
        /// <summary>Height-table points a run covers: those with τ√2 ≤ <see cref="EndT"/> (τ = 0.56…3.44).</summary>
        public static readonly int HeightPoints = CountHeightPoints();
        const int k_Depth = 4;
        const int k_MinNeighbours = 4;

        readonly int m_CellsAcross;
        readonly FluidParameters m_Parameters;
        readonly string m_Setting;
        FluidConstants m_Constants;
        FluidBuffers m_Buffers;
        float3[] m_InitialPositions;
        int[] m_InitialIds;
        int m_InitialCount;
        double[] m_SampleT, m_SampleZ, m_SampleH;
        int m_Samples;
        long m_Items;
        double m_DensityErrorSum;
        int m_DensitySamples;
        int m_MaxSubsteps, m_Capped;

        /// <summary>A dam break at a/<paramref name="cellsAcross"/> spacing with the solver settings of <paramref name="parameters"/> (spacing and domain are set here).</summary>
        public DamBreakScenario(int cellsAcross, FluidParameters parameters, string setting)
        {
            m_CellsAcross = cellsAcross;
            m_Parameters = parameters;
            m_Setting = setting;
        }

        public string Name => "DamBreak";
        public string Method => $"{SolverName(m_Parameters.Solver)} {m_Setting}, a/{m_CellsAcross}";
        public int Size => m_InitialCount > 0 ? m_InitialCount : m_CellsAcross * 2 * m_CellsAcross * k_Depth;
        public string SizeUnit => "particles";
        public long ItemsPerStep => Math.Max(1, m_Items);
        /// <summary>Three timed runs at a/10; one at finer resolutions, where a run takes seconds (the warm-up adds one more).</summary>
        public int MaxRepeats => m_CellsAcross >= 20 ? 1 : 3;

        public static string SolverName(FluidSolverKind solver) => solver == FluidSolverKind.WeaklyCompressible ? "WCSPH" : "PBF";

        /// <summary>Reference speed √(2g·2a) of the column (m/s): the speed of sound is a multiple of it.</summary>
        public static float ReferenceSpeed => (float)Math.Sqrt(2 * 9.81 * 2 * MartinMoyce1952.ColumnWidth);

        public void Setup()
        {
            float a = (float)MartinMoyce1952.ColumnWidth;
            float dx = a / m_CellsAcross;
            FluidParameters p = m_Parameters;
            p.MaxSubsteps = FluidParameters.SubstepLimit;
            m_Buffers = FluidScene.BlockInBox(p, dx, new float3(6f * a, 3f * a, k_Depth * dx), new float3(a, 2f * a, k_Depth * dx), out m_Constants);
            m_InitialCount = m_Buffers.Status.Count;
            m_InitialPositions = (float3[])m_Buffers.Positions.Clone();
            m_InitialIds = (int[])m_Buffers.Ids.Clone();
            int frames = (int)Math.Ceiling(EndT / MartinMoyce1952.DimensionlessTime(FrameSeconds)) + 2;
            m_SampleT = new double[frames];
            m_SampleZ = new double[frames];
            m_SampleH = new double[frames];
        }

        static int CountHeightPoints()
        {
            int n = 0;
            while (n < MartinMoyce1952.Tau.Length && MartinMoyce1952.Tau[n] * Math.Sqrt(2) <= EndT)
                n++;
            return n;
        }

        void Reset()
        {
            FluidBuffers b = m_Buffers;
            Array.Copy(m_InitialPositions, b.Positions, m_InitialCount);
            Array.Copy(m_InitialIds, b.Ids, m_InitialCount);
            Array.Clear(b.Velocities, 0, m_InitialCount);
            Array.Clear(b.Ages, 0, m_InitialCount);
            Array.Clear(b.Lifetimes, 0, m_InitialCount);
            b.Status = new FluidStatus { Count = m_InitialCount, NextId = m_InitialCount, Spawned = m_InitialCount };
        }

        /// <summary>Frames of the short warm-up.</summary>
        const int k_WarmupFrames = 10;

        public void Step() => Run(int.MaxValue);

        public void WarmupFrames() => Run(k_WarmupFrames);

        /// <summary>The run from release, ended at T = <see cref="EndT"/> or after <paramref name="maxFrames"/> frames.</summary>
        void Run(int maxFrames)
        {
            Reset();
            FluidBuffers b = m_Buffers;
            float a = (float)MartinMoyce1952.ColumnWidth;
            m_Samples = 0;
            m_Items = 0;
            m_DensityErrorSum = 0;
            m_DensitySamples = 0;
            m_MaxSubsteps = 0;
            m_Capped = 0;
            m_SampleT[m_Samples] = 0;
            m_SampleH[m_Samples] = 1;
            m_SampleZ[m_Samples++] = 1;
            double t = 0;
            while (MartinMoyce1952.DimensionlessTime(t) < EndT && m_Samples < m_SampleT.Length && m_Samples <= maxFrames)
            {
                FluidStepReport r = FluidSolver.Step(m_Constants, ReadOnlySpan<ColliderShape>.Empty, FrameSeconds, b.Particles, b.Scratch, ref b.Status);
                t += FrameSeconds;
                m_Items += (long)r.Substeps * r.Count;
                m_MaxSubsteps = Math.Max(m_MaxSubsteps, r.Substeps);
                if (r.SubstepsWanted > r.Substeps)
                    m_Capped++;
                float dx = m_Constants.Parameters.ParticleSpacing;
                m_SampleT[m_Samples] = MartinMoyce1952.DimensionlessTime(t);
                m_SampleH[m_Samples] = FluidScene.BulkHeightAtWall(b, dx, k_MinNeighbours, 2.5f * dx) / (2 * a);
                m_SampleZ[m_Samples++] = FluidScene.BulkFront(b, dx, k_MinNeighbours) / a;
                double e = FluidScene.MeanBulkDensityError(b, m_Constants.Parameters.RestDensity, k_MinNeighbours);
                if (!double.IsNaN(e))
                {
                    m_DensityErrorSum += e;
                    m_DensitySamples++;
                }
            }
        }

        /// <summary>RMS of Z_sim(T + shift) − Z_data over the table's points.</summary>
        public double FrontError(double shift)
        {
            double sum = 0;
            for (int k = 0; k < MartinMoyce1952.T.Length; k++)
            {
                double z = FluidScene.Interpolate(m_SampleT, m_SampleZ, m_Samples, MartinMoyce1952.T[k] - shift);
                double d = z - MartinMoyce1952.Z[k];
                sum += d * d;
            }
            return Math.Sqrt(sum / MartinMoyce1952.T.Length);
        }

        /// <summary>RMS of H_sim(T + shift) − H_data over the height table's first <see cref="HeightPoints"/> points (T = τ√2).</summary>
        public double HeightError(double shift)
        {
            double sum = 0;
            for (int k = 0; k < HeightPoints; k++)
            {
                double h = FluidScene.Interpolate(m_SampleT, m_SampleH, m_Samples, MartinMoyce1952.Tau[k] * Math.Sqrt(2) - shift);
                double d = h - MartinMoyce1952.Height[k];
                sum += d * d;
            }
            return Math.Sqrt(sum / Math.Max(1, HeightPoints));
        }

        /// <summary>The simulated residual height H (of 2a) at dimensionless time <paramref name="T"/>.</summary>
        public double HeightAt(double T) => FluidScene.Interpolate(m_SampleT, m_SampleH, m_Samples, T);

        /// <summary>Start of the late window (T) over which the front speed is fitted.</summary>
        public const double LateT = 2.0;
        /// <summary>End of the table (T).</summary>
        public const double LastTableT = 3.33;

        /// <summary>Least-squares slope dZ/dT of the points with <paramref name="from"/> ≤ T ≤ <paramref name="to"/> (NaN with fewer than two).</summary>
        public static double FrontSpeed(double[] ts, double[] zs, int count, double from, double to)
        {
            double st = 0, sz = 0, stt = 0, stz = 0;
            int n = 0;
            for (int k = 0; k < count; k++)
            {
                if (ts[k] < from || ts[k] > to)
                    continue;
                st += ts[k];
                sz += zs[k];
                stt += ts[k] * ts[k];
                stz += ts[k] * zs[k];
                n++;
            }
            double d = n * stt - st * st;
            return n >= 2 && d > 0 ? (n * stz - st * sz) / d : double.NaN;
        }

        public IReadOnlyList<Metric> Evaluate()
        {
            // The best shift in [0, 0.2] (the gate's opening time) on a 0.01 grid: for the front alone, and one shared by
            // front and height (least front² + height²).
            double best = double.PositiveInfinity, bestShift = 0, bestShared = double.PositiveInfinity, sharedShift = 0;
            for (int s = 0; s <= 20; s++)
            {
                double e = FrontError(0.01 * s);
                if (e < best)
                {
                    best = e;
                    bestShift = 0.01 * s;
                }
                double eh = HeightError(0.01 * s);
                if (e * e + eh * eh < bestShared)
                {
                    bestShared = e * e + eh * eh;
                    sharedShift = 0.01 * s;
                }
            }
            return new[]
            {
                new Metric("front RMS error", FrontError(0), MetricUnit.ColumnWidth),
                new Metric("front RMS error (shifted)", best, MetricUnit.ColumnWidth),
                new Metric("shift", bestShift, MetricUnit.DimensionlessTime),
                new Metric("height RMS error", HeightError(0), MetricUnit.Dimensionless),
                new Metric("shared shift", sharedShift, MetricUnit.DimensionlessTime),
                new Metric("front RMS error (shared shift)", FrontError(sharedShift), MetricUnit.ColumnWidth),
                new Metric("height RMS error (shared shift)", HeightError(sharedShift), MetricUnit.Dimensionless),
                new Metric("density error", m_DensityErrorSum / Math.Max(1, m_DensitySamples), MetricUnit.Fraction),
                new Metric("Z at T=3.33", FluidScene.Interpolate(m_SampleT, m_SampleZ, m_Samples, LastTableT), MetricUnit.ColumnWidth),
                new Metric("late front speed", FrontSpeed(m_SampleT, m_SampleZ, m_Samples, LateT, LastTableT), MetricUnit.Dimensionless),
                new Metric("max substeps per frame", m_MaxSubsteps, MetricUnit.Count),
                new Metric("capped frames", m_Capped, MetricUnit.Count),
                new Metric("particles lost", m_InitialCount - m_Buffers.Status.Count, MetricUnit.Count),
            };
        }
    }
}
