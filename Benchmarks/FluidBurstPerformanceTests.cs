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
            int n = side * side * side;
            var lattice = new NativeArray<float3>(n, Allocator.Persistent);
            for (int z = 0, i = 0; z < side; z++)
            for (int y = 0; y < side; y++)
            for (int x = 0; x < side; x++, i++)
                lattice[i] = (new float3(x, y, z) + 0.5f) * p.ParticleSpacing;
            var job = new FluidStepJob
            {
                Parameters = p,
                DeltaTime = 0.9f * FluidSolver.CflSubstep(c, 0f, 1f),
                Positions = new NativeArray<float3>(n, Allocator.Persistent),
                Velocities = new NativeArray<float3>(n, Allocator.Persistent),
                Ages = new NativeArray<float>(n, Allocator.Persistent),
                Lifetimes = new NativeArray<float>(n, Allocator.Persistent),
                Attributes = new NativeArray<float>(n, Allocator.Persistent),
                Ids = new NativeArray<int>(n, Allocator.Persistent),
                ScratchInts = new NativeArray<int>(FluidScratch.FlatInts(n, c.Grid.CellCount), Allocator.Persistent),
                ScratchFloats = new NativeArray<float>(FluidScratch.FlatFloats(n), Allocator.Persistent),
                ScratchVectors = new NativeArray<float3>(FluidScratch.FlatVectors(n), Allocator.Persistent),
                Status = new NativeArray<FluidStatus>(1, Allocator.Persistent),
                Report = new NativeArray<FluidStepReport>(1, Allocator.Persistent),
            };
            try
            {
                StepCycleMeasure.Steps(() => job.Run(), () =>
                    {
                        for (int i = 0; i < n; i++)
                        {
                            job.Positions[i] = lattice[i];
                            job.Velocities[i] = float3.zero;
                            job.Lifetimes[i] = 0f;
                            job.Ids[i] = i;
                        }
                        job.Status[0] = new FluidStatus { Count = n, NextId = n, Spawned = n };
                    },
                    60, $"Fluid WCSPH substep x{n} Burst job", 5, 20);
                Assert.AreEqual(1, job.Report[0].Substeps, "one substep per step");
                Assert.AreEqual(n, job.Report[0].Count, "no particle lost");
            }
            finally
            {
                lattice.Dispose();
                job.Positions.Dispose();
                job.Velocities.Dispose();
                job.Ages.Dispose();
                job.Lifetimes.Dispose();
                job.Attributes.Dispose();
                job.Ids.Dispose();
                job.ScratchInts.Dispose();
                job.ScratchFloats.Dispose();
                job.ScratchVectors.Dispose();
                job.Status.Dispose();
                job.Report.Dispose();
            }
        }

        [Test, Performance]
        public void Fluid_Substep_BurstJobChain([Values(22, 46)] int side)
        {
            FluidParameters p = Scenarios.FluidThroughputScenario.CubeParameters(side);
            var c = new FluidConstants(p);
            int n = side * side * side;
            float dt = 0.9f * FluidSolver.CflSubstep(c, 0f, 1f);
            int batches = FluidJobChain.BatchCount(n);
            var colliders = new NativeArray<ColliderShape>(0, Allocator.Persistent);
            var lattice = new NativeArray<float3>(n, Allocator.Persistent);
            for (int z = 0, i = 0; z < side; z++)
            for (int y = 0; y < side; y++)
            for (int x = 0; x < side; x++, i++)
                lattice[i] = (new float3(x, y, z) + 0.5f) * p.ParticleSpacing;
            var job = new FluidPassJob
            {
                Constants = c,
                Batches = batches,
                Colliders = colliders,
                Positions = new NativeArray<float3>(n, Allocator.Persistent),
                Velocities = new NativeArray<float3>(n, Allocator.Persistent),
                Ages = new NativeArray<float>(n, Allocator.Persistent),
                Lifetimes = new NativeArray<float>(n, Allocator.Persistent),
                Attributes = new NativeArray<float>(n, Allocator.Persistent),
                Ids = new NativeArray<int>(n, Allocator.Persistent),
                ScratchInts = new NativeArray<int>(FluidScratch.FlatInts(n, c.Grid.CellCount), Allocator.Persistent),
                ScratchFloats = new NativeArray<float>(FluidScratch.FlatFloats(n), Allocator.Persistent),
                ScratchVectors = new NativeArray<float3>(FluidScratch.FlatVectors(n), Allocator.Persistent),
                Count = new NativeArray<int>(1, Allocator.Persistent),
                Counters = new NativeArray<FluidPassCounters>(batches, Allocator.Persistent),
            };
            var status = new FluidStatus();
            try
            {
                StepCycleMeasure.Steps(() =>
                    {
                        var particles = new FluidParticles(job.Positions.AsSpan(), job.Velocities.AsSpan(), job.Ages.AsSpan(),
                            job.Lifetimes.AsSpan(), job.Attributes.AsSpan(), job.Ids.AsSpan());
                        FluidSolver.Plan plan = FluidSolver.Begin(c, dt, particles, ref status);
                        job.Count[0] = status.Count;
                        FluidJobChain.Schedule(job, plan, default).Complete();
                        status = default;
                        status.Count = job.Count[0];
                    }, () =>
                    {
                        for (int i = 0; i < n; i++)
                        {
                            job.Positions[i] = lattice[i];
                            job.Velocities[i] = float3.zero;
                            job.Lifetimes[i] = 0f;
                            job.Ids[i] = i;
                        }
                        status = new FluidStatus { Count = n, NextId = n, Spawned = n };
                    },
                    60, $"Fluid WCSPH substep x{n} Burst job chain, {batches} batches", 5, 20);
                Assert.AreEqual(n, job.Count[0], "no particle lost");
            }
            finally
            {
                colliders.Dispose();
                lattice.Dispose();
                job.Positions.Dispose();
                job.Velocities.Dispose();
                job.Ages.Dispose();
                job.Lifetimes.Dispose();
                job.Attributes.Dispose();
                job.Ids.Dispose();
                job.ScratchInts.Dispose();
                job.ScratchFloats.Dispose();
                job.ScratchVectors.Dispose();
                job.Count.Dispose();
                job.Counters.Dispose();
            }
        }
    }
}
#endif
