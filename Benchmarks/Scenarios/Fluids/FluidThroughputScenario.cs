using System;
using System.Collections.Generic;
using System.Diagnostics;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>What a <see cref="FluidThroughputScenario"/> row times.</summary>
    public enum FluidThroughputRow
    {
        /// <summary>One weakly compressible substep through <see cref="FluidSolver.Step"/> (dt = 90 % of the CFL substep at rest, so one substep).</summary>
        Substep,
        /// <summary>The same substep pass by pass, in <see cref="FluidSolver"/>'s order, with a stopwatch around each stage.</summary>
        Staged,
        /// <summary>Gather into and scatter back from an entity-ordered copy through a random permutation (the cost of one entity per particle).</summary>
        PackUnpack,
    }

    /// <summary>Stages of the staged substep (<see cref="FluidThroughputRow.Staged"/>).</summary>
    public enum FluidStage
    {
        /// <summary>The step's begin and finish: ages += dt, the fastest speed for the CFL limit, the status and report.</summary>
        Preamble,
        /// <summary>Keys, counting sort and the permutation of the six particle arrays.</summary>
        Sort,
        /// <summary>Neighbour search and lists, density and Tait pressure.</summary>
        Density,
        /// <summary>Pressure, artificial viscosity, gravity and walls, v += h·a (with its copy back).</summary>
        Forces,
        /// <summary>Implicit viscosity: one Jacobi iteration with its two copies.</summary>
        Viscosity,
        /// <summary>Speed bound, x += h·v, domain box.</summary>
        Advect,
        /// <summary>Any other pass of the substep (none for this fluid: no cohesion, alignment or colliders).</summary>
        Other,
    }

    /// <summary>
    /// Throughput of a weakly compressible water block: a cube of N particles at Δx = 2 cm resting on the floor of a box
    /// of its footprint, c₀ = 20 m/s, one viscosity iteration, h = 2Δx (a rest lattice has 26 neighbours within h; the
    /// settled block 27–29). An item is one particle-substep (pack/unpack: one particle gathered and scattered).
    /// The staged row runs the step exactly as <see cref="FluidSolver.Step"/> does (begin, the substep's list of
    /// <see cref="FluidPasses"/>, finish; Setup checks that it gives the same bits as the solver), with
    /// <see cref="Stopwatch"/> timestamps between passes; each stage's cost is the median over the row's steps.
    /// </summary>
    public sealed class FluidThroughputScenario : IScenario, IScenarioRepeatCap
    {
        const float k_Spacing = 0.02f;
        const int k_MaxRecorded = 4096;
        static readonly int s_StageCount = Enum.GetValues(typeof(FluidStage)).Length;

        readonly int m_Side;
        readonly FluidThroughputRow m_Row;
        FluidConstants m_Constants;
        FluidBuffers m_Buffers;
        float m_Substep;
        int[] m_EntityOrder;
        float3[] m_PackedPositions, m_PackedVelocities;
        float[] m_PackedAges, m_PackedLifetimes, m_PackedAttributes;
        int m_Count;
        long[] m_StageTicks;
        int m_Recorded;
        int m_SameBits = -1;
        FluidPass[] m_Passes;

        public FluidThroughputScenario(int side, FluidThroughputRow row)
        {
            m_Side = side;
            m_Row = row;
        }

        public string Name => "FluidThroughput";
        public string Method => RowName(m_Row);
        public int Size => m_Side * m_Side * m_Side;
        public string SizeUnit => "particles";
        public long ItemsPerStep => Size;
        public int MaxRepeats => Size >= 500000 ? 3 : 15;

        public static string RowName(FluidThroughputRow row) => row switch
        {
            FluidThroughputRow.Substep => "WCSPH substep (FluidSolver.Step)",
            FluidThroughputRow.Staged => "WCSPH substep, staged",
            _ => "pack/unpack (entity gather + scatter)",
        };

        public static string StageName(FluidStage stage) => stage switch
        {
            FluidStage.Preamble => "step begin and finish (ages, CFL speed)",
            FluidStage.Sort => "sort (keys, counting sort, permute)",
            FluidStage.Density => "density + neighbour lists",
            FluidStage.Forces => "forces",
            FluidStage.Viscosity => "viscosity (1 Jacobi it)",
            FluidStage.Advect => "advect",
            _ => "other passes",
        };

        /// <summary>Name of the metric holding a stage's ns per particle in the staged row.</summary>
        public static string StageMetric(FluidStage stage) => StageName(stage) + " ns";

        /// <summary>The benchmark fluid for a cube of <paramref name="side"/>³ particles: water at Δx = 2 cm, c₀ = 20 m/s, one viscosity iteration, in a box of the cube's footprint 1.5 cubes high.</summary>
        public static FluidParameters CubeParameters(int side)
        {
            FluidParameters p = FluidParameters.Default;
            p.ParticleSpacing = k_Spacing;
            p.SpeedOfSound = 20f;
            p.ViscosityIterations = 1;
            float edge = side * k_Spacing;
            p.DomainMin = float3.zero;
            p.DomainMax = new float3(edge, 1.5f * edge, edge);
            return p;
        }

        public void Setup()
        {
            FluidParameters p = CubeParameters(m_Side);
            float edge = m_Side * k_Spacing;
            m_Constants = new FluidConstants(p);
            m_Buffers = new FluidBuffers(Size, m_Constants.Grid);
            m_Count = FluidScene.FillBlock(m_Buffers, float3.zero, new float3(edge), k_Spacing);
            // 90 % of the CFL substep at rest, so a step of it stays one substep while the block settles.
            m_Substep = 0.9f * FluidSolver.CflSubstep(m_Constants, 0f, 1f);
            // One substep so that the sort order, densities and neighbour lists are those of a running fluid.
            FluidBuffers b = m_Buffers;
            FluidSolver.Step(m_Constants, ReadOnlySpan<ColliderShape>.Empty, m_Substep, b.Particles, b.Scratch, ref b.Status);
            if (m_Row == FluidThroughputRow.Staged)
            {
                Span<FluidPass> passes = stackalloc FluidPass[FluidSubstepPasses.MaxPasses];
                m_Passes = passes.Slice(0, FluidSubstepPasses.Write(m_Constants, m_Substep, false, passes)).ToArray();
                m_StageTicks = new long[k_MaxRecorded * s_StageCount];
                m_SameBits = StagedMatchesSolver() ? 1 : 0;
                m_Recorded = 0;
            }
            if (m_Row == FluidThroughputRow.PackUnpack)
            {
                var random = new System.Random(1);
                m_EntityOrder = new int[m_Count];
                for (int i = 0; i < m_Count; i++)
                    m_EntityOrder[i] = i;
                for (int i = m_Count - 1; i > 0; i--)
                {
                    int j = random.Next(i + 1);
                    (m_EntityOrder[i], m_EntityOrder[j]) = (m_EntityOrder[j], m_EntityOrder[i]);
                }
                m_PackedPositions = new float3[m_Count];
                m_PackedVelocities = new float3[m_Count];
                m_PackedAges = new float[m_Count];
                m_PackedLifetimes = new float[m_Count];
                m_PackedAttributes = new float[m_Count];
            }
        }

        /// <summary>One staged substep and one <see cref="FluidSolver.Step"/> from the same state: true when positions, velocities and ids agree bit for bit.</summary>
        bool StagedMatchesSolver()
        {
            FluidBuffers b = m_Buffers;
            int n = b.Status.Count;
            var positions = (float3[])b.Positions.Clone();
            var velocities = (float3[])b.Velocities.Clone();
            var ages = (float[])b.Ages.Clone();
            var lifetimes = (float[])b.Lifetimes.Clone();
            var attributes = (float[])b.Attributes.Clone();
            var ids = (int[])b.Ids.Clone();
            FluidStatus status = b.Status;
            Staged();
            var stagedPositions = (float3[])b.Positions.Clone();
            var stagedVelocities = (float3[])b.Velocities.Clone();
            var stagedIds = (int[])b.Ids.Clone();
            int stagedCount = b.Status.Count;
            Array.Copy(positions, b.Positions, n);
            Array.Copy(velocities, b.Velocities, n);
            Array.Copy(ages, b.Ages, n);
            Array.Copy(lifetimes, b.Lifetimes, n);
            Array.Copy(attributes, b.Attributes, n);
            Array.Copy(ids, b.Ids, n);
            b.Status = status;
            FluidStepReport r = FluidSolver.Step(m_Constants, ReadOnlySpan<ColliderShape>.Empty, m_Substep, b.Particles, b.Scratch, ref b.Status);
            if (r.Substeps != 1 || stagedCount != b.Status.Count)
                return false;
            for (int i = 0; i < stagedCount; i++)
            {
                if (stagedIds[i] != b.Ids[i] || !SameBits(stagedPositions[i], b.Positions[i]) || !SameBits(stagedVelocities[i], b.Velocities[i]))
                    return false;
            }
            return true;
        }

        static bool SameBits(float3 a, float3 b) =>
            math.asuint(a.x) == math.asuint(b.x) && math.asuint(a.y) == math.asuint(b.y) && math.asuint(a.z) == math.asuint(b.z);

        public void Step()
        {
            FluidBuffers b = m_Buffers;
            int n = b.Status.Count;
            switch (m_Row)
            {
                case FluidThroughputRow.Substep:
                    FluidSolver.Step(m_Constants, ReadOnlySpan<ColliderShape>.Empty, m_Substep, b.Particles, b.Scratch, ref b.Status);
                    break;
                case FluidThroughputRow.Staged:
                    Staged();
                    break;
                default:
                    // Unpack: the solver's slot k holds entity Ids[k]'s particle; entity order is a fixed random
                    // permutation of ids (chunks are not in cell order). Gather into entity order, then scatter back.
                    for (int k = 0; k < n; k++)
                    {
                        int e = m_EntityOrder[b.Ids[k]];
                        m_PackedPositions[e] = b.Positions[k];
                        m_PackedVelocities[e] = b.Velocities[k];
                        m_PackedAges[e] = b.Ages[k];
                        m_PackedLifetimes[e] = b.Lifetimes[k];
                        m_PackedAttributes[e] = b.Attributes[k];
                    }
                    for (int k = 0; k < n; k++)
                    {
                        int e = m_EntityOrder[b.Ids[k]];
                        b.Positions[k] = m_PackedPositions[e];
                        b.Velocities[k] = m_PackedVelocities[e];
                        b.Ages[k] = m_PackedAges[e];
                        b.Lifetimes[k] = m_PackedLifetimes[e];
                        b.Attributes[k] = m_PackedAttributes[e];
                    }
                    break;
            }
        }

        /// <summary>
        /// One step of <see cref="m_Substep"/> (one substep) exactly as <see cref="FluidSolver.Step"/> runs it:
        /// <see cref="FluidSolver.Begin"/>, the passes of <see cref="FluidSubstepPasses.Write"/> through
        /// <see cref="FluidPasses.Run"/>, <see cref="FluidSolver.Finish"/>, with a timestamp after each pass; a pass's ticks
        /// go to its stage (<see cref="StageOf"/>).
        /// </summary>
        void Staged()
        {
            FluidBuffers b = m_Buffers;
            FluidParticles p = b.Particles;
            FluidScratch s = b.Scratch;
            ref readonly FluidConstants c = ref m_Constants;
            int slot = m_Recorded < k_MaxRecorded ? m_Recorded++ : k_MaxRecorded - 1;
            Span<long> ticks = m_StageTicks.AsSpan(slot * s_StageCount, s_StageCount);
            ticks.Clear();

            long t0 = Stopwatch.GetTimestamp();
            FluidSolver.Plan plan = FluidSolver.Begin(c, m_Substep, p, ref b.Status);
            int count = b.Status.Count;
            var counters = new FluidPassCounters();
            long t = Stopwatch.GetTimestamp();
            ticks[(int)FluidStage.Preamble] += t - t0;
            FluidStage stage = FluidStage.Other;
            for (int k = 0; k < plan.Substeps; k++)
            {
                for (int q = 0; q < m_Passes.Length; q++)
                {
                    stage = StageOf(m_Passes[q], stage);
                    FluidPasses.Run(m_Passes[q], c, ReadOnlySpan<ColliderShape>.Empty, p, s, 0, 1, ref count, plan.H, ref counters);
                    long t1 = Stopwatch.GetTimestamp();
                    ticks[(int)stage] += t1 - t;
                    t = t1;
                }
            }
            FluidSolver.Finish(plan, counters, m_Substep, count, ref b.Status);
            ticks[(int)FluidStage.Preamble] += Stopwatch.GetTimestamp() - t;
        }

        /// <summary>The stage a pass counts in; a copy of velocities back counts in the stage of the pass before it (<paramref name="current"/>).</summary>
        public static FluidStage StageOf(FluidPass pass, FluidStage current) => pass switch
        {
            FluidPass.Sort or FluidPass.SortWithPrevious => FluidStage.Sort,
            FluidPass.Density or FluidPass.DensityFromNeighbours => FluidStage.Density,
            FluidPass.SurfaceNormals or FluidPass.Forces or FluidPass.CohesionForces => FluidStage.Forces,
            FluidPass.CopyVelocitiesToA or FluidPass.ViscosityAToB or FluidPass.ViscosityBToA or FluidPass.CopyBToVelocities => FluidStage.Viscosity,
            FluidPass.Advect or FluidPass.Predict => FluidStage.Advect,
            FluidPass.CopyAToVelocities => current,
            _ => FluidStage.Other,
        };

        public IReadOnlyList<Metric> Evaluate()
        {
            var metrics = new List<Metric>
            {
                new Metric("neighbours", MeanNeighbours(), MetricUnit.Dimensionless),
                new Metric("bytes per particle", FluidBuffers.BytesPerParticle + 4.0 * (m_Constants.Grid.CellCount + 2) / Size, MetricUnit.Byte),
                new Metric("particles lost", m_Count - m_Buffers.Status.Count, MetricUnit.Count),
            };
            if (m_Row == FluidThroughputRow.Staged)
            {
                metrics.Add(new Metric("same bits as FluidSolver.Step", m_SameBits, MetricUnit.Flag));
                var samples = new long[Math.Max(1, m_Recorded)];
                foreach (FluidStage stage in (FluidStage[])Enum.GetValues(typeof(FluidStage)))
                {
                    for (int k = 0; k < m_Recorded; k++)
                        samples[k] = m_StageTicks[k * s_StageCount + (int)stage];
                    Array.Sort(samples, 0, m_Recorded);
                    double median = m_Recorded == 0 ? double.NaN
                        : m_Recorded % 2 == 1 ? samples[m_Recorded / 2] : 0.5 * (samples[m_Recorded / 2 - 1] + samples[m_Recorded / 2]);
                    metrics.Add(new Metric(StageMetric(stage), median * 1e9 / Stopwatch.Frequency / Math.Max(1, m_Count), MetricUnit.Nanosecond));
                }
            }
            return metrics;
        }

        double MeanNeighbours()
        {
            long sum = 0;
            for (int i = 0; i < m_Buffers.Status.Count; i++)
                sum += m_Buffers.NeighbourCounts[i];
            return (double)sum / Math.Max(1, m_Buffers.Status.Count);
        }
    }
}
