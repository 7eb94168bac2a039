#if SBD_PERFORMANCE_TESTING
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Jobs;
using Unity.Mathematics;
using Unity.PerformanceTesting;

namespace SoftBodyDynamics.Benchmarks
{
    /// <summary>
    /// What users get from the fluid solver: one CFL substep of a resting cube of water (Δx = 2 cm, c₀ = 20 m/s, one
    /// viscosity iteration, about 30 neighbours), the workload of the headless FluidThroughput suite, as Burst code in
    /// one job (<see cref="FluidStepJob"/> with <c>Run()</c>), at 22³ ≈ 10k and 46³ ≈ 100k particles. Divide the particles
    /// by the median to get particle-substeps per second. The cube is put back on its lattice every 60 steps, outside the
    /// timed region. <see cref="Fluid_Substep_BurstJobChain"/> times the same substep as the packed-fluid system runs
    /// it: a chain of parallel pass jobs on all worker threads (<see cref="FluidJobChain"/>). Burst's safety checks are on
    /// in the Editor unless switched off in the Jobs ▸ Burst menu.
    /// </summary>
    public class FluidBurstPerformanceTests
    {

        [Test, Performance]
        public void Fluid_Substep_BurstJob([Values(22, 46)] int side)
        {
            FluidParameters p = Scenarios.FluidThroughputScenario.CubeParameters(side);
            var c = new FluidConstants(p);
            CubeArrays cube = CubeArrays.Create(side, c);
            var job = new FluidStepJob
            {
                Parameters = p,
                DeltaTime = 0.9f * FluidSolver.CflSubstep(c, 0f, 1f),
                Positions = cube.Positions, Velocities = cube.Velocities, Ages = cube.Ages, Lifetimes = cube.Lifetimes,
                Attributes = cube.Attributes, Ids = cube.Ids,
                ScratchInts = cube.ScratchInts, ScratchFloats = cube.ScratchFloats, ScratchVectors = cube.ScratchVectors,
                Status = new NativeArray<FluidStatus>(1, Allocator.Persistent),
                Report = new NativeArray<FluidStepReport>(1, Allocator.Persistent),
            };
            try
            {
                StepCycleMeasure.Steps(() => job.Run(), () => job.Status[0] = cube.Reset(),
                    60, $"Fluid WCSPH substep x{cube.Count} Burst job", 5, 20);
                Assert.AreEqual(1, job.Report[0].Substeps, "one substep per step");
                Assert.AreEqual(cube.Count, job.Report[0].Count, "no particle lost");
            }
            finally
            {
                cube.Dispose();
                job.Status.Dispose();
                job.Report.Dispose();
            }
        }

        [Test, Performance]
        public void Fluid_Substep_BurstJobChain([Values(22, 46)] int side)
        {
            FluidParameters p = Scenarios.FluidThroughputScenario.CubeParameters(side);
            var c = new FluidConstants(p);
            CubeArrays cube = CubeArrays.Create(side, c);
            float dt = 0.9f * FluidSolver.CflSubstep(c, 0f, 1f);
            int batches = FluidJobChain.BatchCount(cube.Count);
            var colliders = new NativeArray<ColliderShape>(0, Allocator.Persistent);
            var job = new FluidPassJob
            {
                Constants = c,
                Batches = batches,
                Colliders = colliders,
                Positions = cube.Positions, Velocities = cube.Velocities, Ages = cube.Ages, Lifetimes = cube.Lifetimes,
                Attributes = cube.Attributes, Ids = cube.Ids,
                ScratchInts = cube.ScratchInts, ScratchFloats = cube.ScratchFloats, ScratchVectors = cube.ScratchVectors,
                Count = new NativeArray<int>(1, Allocator.Persistent),
                Counters = new NativeArray<FluidPassCounters>(batches, Allocator.Persistent),
            };
            var status = new FluidStatus();
            try
            {
                StepCycleMeasure.Steps(() =>
                    {
                        var particles = new FluidParticles(cube.Positions.AsSpan(), cube.Velocities.AsSpan(), cube.Ages.AsSpan(),
                            cube.Lifetimes.AsSpan(), cube.Attributes.AsSpan(), cube.Ids.AsSpan());
                        FluidSolver.Plan plan = FluidSolver.Begin(c, dt, particles, ref status);
                        job.Count[0] = status.Count;
                        FluidJobChain.Schedule(job, plan, default).Complete();
                        status.Count = job.Count[0];
                    }, () => status = cube.Reset(),
                    60, $"Fluid WCSPH substep x{cube.Count} Burst job chain, {batches} batches", 5, 20);
                Assert.AreEqual(cube.Count, job.Count[0], "no particle lost");
            }
            finally
            {
                cube.Dispose();
                colliders.Dispose();
                job.Count.Dispose();
                job.Counters.Dispose();
            }
        }

        /// <summary>A fluid's arrays in native memory, filled with the resting cube; shared by both tests.</summary>
        struct CubeArrays
        {
            public NativeArray<float3> Lattice, Positions, Velocities, ScratchVectors;
            public NativeArray<float> Ages, Lifetimes, Attributes, ScratchFloats;
            public NativeArray<int> Ids, ScratchInts;
            public int Count;

            public static CubeArrays Create(int side, in FluidConstants c)
            {
                int n = side * side * side;
                var a = new CubeArrays
                {
                    Count = n,
                    Lattice = new NativeArray<float3>(n, Allocator.Persistent),
                    Positions = new NativeArray<float3>(n, Allocator.Persistent),
                    Velocities = new NativeArray<float3>(n, Allocator.Persistent),
                    Ages = new NativeArray<float>(n, Allocator.Persistent),
                    Lifetimes = new NativeArray<float>(n, Allocator.Persistent),
                    Attributes = new NativeArray<float>(n, Allocator.Persistent),
                    Ids = new NativeArray<int>(n, Allocator.Persistent),
                    ScratchInts = new NativeArray<int>(FluidScratch.FlatInts(n, c.Grid.CellCount), Allocator.Persistent),
                    ScratchFloats = new NativeArray<float>(FluidScratch.FlatFloats(n), Allocator.Persistent),
                    ScratchVectors = new NativeArray<float3>(FluidScratch.FlatVectors(n), Allocator.Persistent),
                };
                for (int z = 0, i = 0; z < side; z++)
                for (int y = 0; y < side; y++)
                for (int x = 0; x < side; x++, i++)
                    a.Lattice[i] = (new float3(x, y, z) + 0.5f) * c.Parameters.ParticleSpacing;
                return a;
            }

            /// <summary>Puts the cube back on its lattice, at rest; returns its status.</summary>
            public FluidStatus Reset()
            {
                for (int i = 0; i < Count; i++)
                {
                    Positions[i] = Lattice[i];
                    Velocities[i] = float3.zero;
                    Lifetimes[i] = 0f;
                    Ids[i] = i;
                }
                return new FluidStatus { Count = Count, NextId = Count, Spawned = Count };
            }

            public void Dispose()
            {
                Lattice.Dispose();
                Positions.Dispose();
                Velocities.Dispose();
                Ages.Dispose();
                Lifetimes.Dispose();
                Attributes.Dispose();
                Ids.Dispose();
                ScratchInts.Dispose();
                ScratchFloats.Dispose();
                ScratchVectors.Dispose();
            }
        }
    }
}
#endif
