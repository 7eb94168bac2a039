using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>The inputs that break a naive particle fluid, each run as one row of <see cref="FluidHardCaseScenario"/>.</summary>
    public enum FluidHardCase
    {
        /// <summary>1000 particles at the same point (r = 0 for every pair, 999 neighbours each), 0.5 s.</summary>
        OnePoint,
        /// <summary>One particle alone in the air (no neighbour, no wall within a kernel), 1/6 s of free fall.</summary>
        Isolated,
        /// <summary>1000 particles on a lattice at half the spacing (eight times the rest density, as a burst into one spot), 0.5 s.</summary>
        DensePile,
        /// <summary>A resting block of 1000 particles stepped with dt = 1 s three times (the CFL limit asks for far more substeps than the cap).</summary>
        HugeStep,
        /// <summary>A resting block of 1000 particles; after one frame one position gets NaN, one velocity +∞ and one position 1e20 m, then 30 frames.</summary>
        NaNInjected,
    }

    /// <summary>
    /// A hard case for one solver, in a 0.4 m box of water at Δx = 2 cm: each Step runs the case from its start and sums what
    /// the step reports (<see cref="FluidStepReport"/>); Evaluate says whether every particle is finite and in the box, how
    /// many are alive and were removed as invalid, and the report's counters (speed clamps, over-compressed and
    /// neighbour-overflow particle-substeps, the largest density ratio, and after the first frame, substeps wanted against run,
    /// and the fraction of the asked time simulated: below 1 when the substep cap held a frame back). An item is one
    /// particle-substep.
    /// </summary>
    public sealed class FluidHardCaseScenario : IScenario, IScenarioRepeatCap, IScenarioShortWarmup
    {
        const float k_Spacing = 0.02f;
        const float k_Frame = 1f / 60f;
        const int k_Side = 10;
        const float k_Box = 0.4f;

        readonly FluidHardCase m_Case;
        readonly FluidSolverKind m_Solver;
        FluidConstants m_Constants;
        FluidBuffers m_Buffers;
        long m_Items;
        int m_Particles;
        long m_SpeedClamped, m_OverCompressed, m_NeighbourOverflow;
        int m_SubstepsWanted, m_SubstepsRun;
        float m_MaxDensityRatio, m_LateMaxDensityRatio;
        int m_Frames;
        double m_Asked, m_Simulated;
        double m_FreeFallError, m_Spread;

        public FluidHardCaseScenario(FluidHardCase hardCase, FluidSolverKind solver)
        {
            m_Case = hardCase;
            m_Solver = solver;
        }

        public string Name => "HardCase";
        public string Method => $"{DamBreakScenario.SolverName(m_Solver)} {CaseName(m_Case)}";
        public int Size => m_Case == FluidHardCase.Isolated ? 1 : k_Side * k_Side * k_Side;
        public string SizeUnit => "particles";
        public long ItemsPerStep => Math.Max(1, m_Items);
        public int MaxRepeats => 1;

        /// <summary>Row label of a case.</summary>
        public static string CaseName(FluidHardCase hardCase) => hardCase switch
        {
            FluidHardCase.OnePoint => "every particle at one point",
            FluidHardCase.Isolated => "isolated particle",
            FluidHardCase.DensePile => "dense pile (8 ρ₀)",
            FluidHardCase.HugeStep => "huge step (dt = 1 s)",
            _ => "NaN, ∞ and 1e20 injected",
        };

        public void Setup()
        {
            FluidParameters p = FluidParameters.Default;
            p.Solver = m_Solver;
            p.ParticleSpacing = k_Spacing;
            p.ViscosityIterations = 1;
            p.DomainMin = float3.zero;
            p.DomainMax = new float3(k_Box);
            m_Constants = new FluidConstants(p);
            m_Buffers = new FluidBuffers(Size, m_Constants.Grid);
        }

        /// <summary>One 1/60 s frame of the case's start (the step places the particles again).</summary>
        public void WarmupFrames()
        {
            Place(m_Buffers);
            Frame(k_Frame);
        }

        public void Step()
        {
            FluidBuffers b = m_Buffers;
            Place(b);
            m_Particles = b.Status.Count;
            m_Items = 0;
            m_SpeedClamped = m_OverCompressed = m_NeighbourOverflow = 0;
            m_SubstepsWanted = m_SubstepsRun = 0;
            m_MaxDensityRatio = m_LateMaxDensityRatio = 0f;
            m_Frames = 0;
            m_Asked = m_Simulated = 0;
            switch (m_Case)
            {
                case FluidHardCase.Isolated:
                {
                    float y0 = b.Positions[0].y;
                    for (int f = 0; f < 10; f++)
                        Frame(k_Frame);
                    // Drop against ½gt²: the symplectic Euler substeps add g·h·t/2 (first order in the substep h).
                    double t = 10 * k_Frame;
                    double exact = 0.5 * 9.81 * t * t;
                    m_FreeFallError = b.Status.Count == 1 ? Math.Abs((y0 - b.Positions[0].y) / exact - 1) : double.NaN;
                    break;
                }
                case FluidHardCase.HugeStep:
                    for (int f = 0; f < 3; f++)
                        Frame(1f);
                    break;
                case FluidHardCase.NaNInjected:
                    Frame(k_Frame);
                    b.Positions[17] = new float3(float.NaN, b.Positions[17].y, b.Positions[17].z);
                    b.Velocities[42] = new float3(0f, float.PositiveInfinity, 0f);
                    b.Positions[99] = new float3(1e20f, b.Positions[99].y, b.Positions[99].z);
                    for (int f = 0; f < 30; f++)
                        Frame(k_Frame);
                    break;
                default:
                    for (int f = 0; f < 30; f++)
                        Frame(k_Frame);
                    break;
            }
            // Spread: mean horizontal distance from the start point, in spacings (the pile must come apart).
            double spread = 0;
            for (int i = 0; i < b.Status.Count; i++)
            {
                float3 d = b.Positions[i] - new float3(0.5f * k_Box);
                spread += Math.Sqrt(d.x * d.x + d.z * d.z);
            }
            m_Spread = spread / Math.Max(1, b.Status.Count) / k_Spacing;
        }

        void Place(FluidBuffers b)
        {
            int n = 0;
            float3 centre = new float3(0.5f * k_Box);
            switch (m_Case)
            {
                case FluidHardCase.OnePoint:
                    for (; n < Size; n++)
                        b.Positions[n] = centre;
                    break;
                case FluidHardCase.Isolated:
                    b.Positions[n++] = new float3(centre.x, 0.85f * k_Box, centre.z);
                    break;
                default:
                {
                    // A cube of 10³ lattice points on the floor in the middle of the box, at Δx/2 for the pile.
                    float d = m_Case == FluidHardCase.DensePile ? 0.5f * k_Spacing : k_Spacing;
                    float3 lo = new float3(centre.x - 0.5f * k_Side * d, 0.5f * k_Spacing, centre.z - 0.5f * k_Side * d);
                    for (int z = 0; z < k_Side; z++)
                    for (int y = 0; y < k_Side; y++)
                    for (int x = 0; x < k_Side; x++)
                        b.Positions[n++] = lo + new float3(x + 0.5f, y, z + 0.5f) * d;
                    break;
                }
            }
            for (int i = 0; i < n; i++)
            {
                b.Velocities[i] = float3.zero;
                b.Ages[i] = 0f;
                b.Lifetimes[i] = 0f;
                b.Attributes[i] = 0f;
                b.Ids[i] = i;
            }
            b.Status = new FluidStatus { Count = n, NextId = n, Spawned = n };
        }

        void Frame(float dt)
        {
            FluidBuffers b = m_Buffers;
            FluidStepReport r = FluidSolver.Step(m_Constants, ReadOnlySpan<ColliderShape>.Empty, dt, b.Particles, b.Scratch, ref b.Status);
            m_Items += (long)r.Substeps * r.Count;
            m_SpeedClamped += r.SpeedClamped;
            m_OverCompressed += r.OverCompressed;
            m_NeighbourOverflow += r.NeighbourOverflow;
            m_MaxDensityRatio = math.max(m_MaxDensityRatio, r.MaxDensityRatio);
            if (m_Frames++ > 0)
                m_LateMaxDensityRatio = math.max(m_LateMaxDensityRatio, r.MaxDensityRatio);
            m_Asked += dt;
            m_Simulated += r.SimulatedTime;
            m_SubstepsWanted = Math.Max(m_SubstepsWanted, r.SubstepsWanted);
            m_SubstepsRun = Math.Max(m_SubstepsRun, r.Substeps);
        }

        public IReadOnlyList<Metric> Evaluate()
        {
            FluidBuffers b = m_Buffers;
            FluidParameters p = m_Constants.Parameters;
            int finite = 1, inside = 1;
            double maxSpeed = 0;
            for (int i = 0; i < b.Status.Count; i++)
            {
                if (!math.all(math.isfinite(b.Positions[i])) || !math.all(math.isfinite(b.Velocities[i])))
                    finite = 0;
                if (!math.all(b.Positions[i] >= p.DomainMin) || !math.all(b.Positions[i] <= p.DomainMax))
                    inside = 0;
                maxSpeed = Math.Max(maxSpeed, math.length(b.Velocities[i]));
            }
            var metrics = new List<Metric>
            {
                new Metric("finite", finite, MetricUnit.Flag),
                new Metric("in box", inside, MetricUnit.Flag),
                new Metric("alive", b.Status.Count, MetricUnit.Count),
                new Metric("invalid removed", b.Status.Invalid, MetricUnit.Count),
                new Metric("max speed", maxSpeed, MetricUnit.MetrePerSecond),
                new Metric("speed clamped", m_SpeedClamped, MetricUnit.Count),
                new Metric("over-compressed", m_OverCompressed, MetricUnit.Count),
                new Metric("neighbour overflow", m_NeighbourOverflow, MetricUnit.Count),
                new Metric("max density ratio", m_MaxDensityRatio, MetricUnit.Dimensionless),
                new Metric("late max density ratio", m_LateMaxDensityRatio, MetricUnit.Dimensionless),
                new Metric("simulated", m_Asked > 0 ? m_Simulated / m_Asked : 1.0, MetricUnit.Fraction),
                new Metric("substeps wanted", m_SubstepsWanted, MetricUnit.Count),
                new Metric("substeps run", m_SubstepsRun, MetricUnit.Count),
                new Metric("spread", m_Spread, MetricUnit.ParticleSpacing),
            };
            if (m_Case == FluidHardCase.Isolated)
                metrics.Add(new Metric("free-fall error", m_FreeFallError, MetricUnit.Fraction));
            return metrics;
        }

        /// <summary>Every case for both solvers (the quick run: three weakly compressible ones).</summary>
        public static IEnumerable<IScenario> All(bool quick)
        {
            if (quick)
            {
                foreach (FluidHardCase hardCase in new[] { FluidHardCase.OnePoint, FluidHardCase.HugeStep, FluidHardCase.NaNInjected })
                    yield return new FluidHardCaseScenario(hardCase, FluidSolverKind.WeaklyCompressible);
                yield break;
            }
            foreach (FluidSolverKind solver in new[] { FluidSolverKind.WeaklyCompressible, FluidSolverKind.PositionBased })
            foreach (FluidHardCase hardCase in (FluidHardCase[])Enum.GetValues(typeof(FluidHardCase)))
                yield return new FluidHardCaseScenario(hardCase, solver);
        }
    }
}
