using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Stages of a weakly compressible substep timed on their own.</summary>
    public enum FluidStage
    {
        /// <summary>The whole substep (FluidSolver.Step with dt = one CFL substep).</summary>
        Substep,
        /// <summary>Keys, counting sort and the permutation of every particle array.</summary>
        Sort,
        /// <summary>Neighbour search, density and Tait pressure.</summary>
        Density,
        /// <summary>Pressure, artificial viscosity and gravity, v += h·a.</summary>
        Forces,
        /// <summary>One Jacobi iteration of implicit viscosity (with its two copies).</summary>
        Viscosity,
        /// <summary>Speed bound, x += h·v, domain box.</summary>
        Advect,
        /// <summary>Gather into and scatter back from an entity-ordered copy through a random permutation (the cost of one entity per particle).</summary>
        PackUnpack,
    }

    /// <summary>
    /// Throughput of one stage of a weakly compressible water block: a cube of N particles at Δx = 2 cm (about 30
    /// neighbours each) resting on the floor of a box, c₀ = 20 m/s, one viscosity iteration; an item is one particle
    /// through the stage once.
    /// </summary>
    public sealed class FluidThroughputScenario : IScenario, IScenarioRepeatCap
    {
        const float k_Spacing = 0.02f;
        readonly int m_Side;
        readonly FluidStage m_Stage;
        FluidConstants m_Constants;
        FluidBuffers m_Buffers;
        float m_Substep;
        int[] m_EntityOrder;
        float3[] m_PackedPositions, m_PackedVelocities;
        float[] m_PackedAges, m_PackedLifetimes, m_PackedAttributes;
        int m_Count;
        FluidPassCounters m_Counters;

        public FluidThroughputScenario(int side, FluidStage stage)
        {
            m_Side = side;
            m_Stage = stage;
        }

        public string Name => "FluidThroughput";
        public string Method => StageName(m_Stage);
        public int Size => m_Side * m_Side * m_Side;
        public string SizeUnit => "particles";
        public long ItemsPerStep => Size;
        public int MaxRepeats => Size >= 500000 ? 3 : 15;

        public static string StageName(FluidStage stage) => stage switch
        {
            FluidStage.Substep => "WCSPH substep",
            FluidStage.Sort => "sort (keys, counting sort, permute)",
            FluidStage.Density => "density + neighbour lists",
            FluidStage.Forces => "forces",
            FluidStage.Viscosity => "viscosity (1 Jacobi it)",
            FluidStage.Advect => "advect",
            _ => "pack/unpack (entity gather + scatter)",
        };

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
            if (m_Stage == FluidStage.PackUnpack)
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

        public void Step()
        {
            FluidBuffers b = m_Buffers;
            FluidParticles particles = b.Particles;
            FluidScratch scratch = b.Scratch;
            int n = b.Status.Count;
            float h = m_Substep;
            switch (m_Stage)
            {
                case FluidStage.Substep:
                    FluidSolver.Step(m_Constants, ReadOnlySpan<ColliderShape>.Empty, h, particles, scratch, ref b.Status);
                    break;
                case FluidStage.Sort:
                    b.Status.Count = FluidSolver.SortParticles(m_Constants, particles, scratch, n, false, ref m_Counters);
                    break;
                case FluidStage.Density:
                    FluidPasses.Density(m_Constants, ReadOnlySpan<ColliderShape>.Empty, particles, scratch, 0, n, ref m_Counters);
                    break;
                case FluidStage.Forces:
                    FluidPasses.Forces(m_Constants, ReadOnlySpan<ColliderShape>.Empty, particles, scratch, scratch.VectorsA, 0, n, h, true);
                    scratch.VectorsA.Slice(0, n).CopyTo(particles.Velocities);
                    break;
                case FluidStage.Viscosity:
                    particles.Velocities.Slice(0, n).CopyTo(scratch.VectorsA);
                    FluidPasses.ViscosityIteration(m_Constants, particles, scratch, scratch.VectorsA, scratch.VectorsB, 0, n, h);
                    scratch.VectorsB.Slice(0, n).CopyTo(particles.Velocities);
                    break;
                case FluidStage.Advect:
                    FluidPasses.Advect(m_Constants, particles, scratch, 0, n, h, ref m_Counters);
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

        public IReadOnlyList<Metric> Evaluate() => new[]
        {
            new Metric("neighbours", MeanNeighbours()),
            new Metric("bytes per particle", FluidBuffers.BytesPerParticle + 4.0 * (m_Constants.Grid.CellCount + 2) / Size, "B"),
            new Metric("particles lost", m_Count - m_Buffers.Status.Count),
        };

        double MeanNeighbours()
        {
            long sum = 0;
            for (int i = 0; i < m_Buffers.Status.Count; i++)
                sum += m_Buffers.NeighbourCounts[i];
            return (double)sum / Math.Max(1, m_Buffers.Status.Count);
        }
    }
}
