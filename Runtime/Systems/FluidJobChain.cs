using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Jobs;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Schedules the substeps of one fluid step as a chain of <see cref="FluidPassJob"/>s: the passes of
    /// <see cref="FluidSubstepPasses.Write"/>, the same list <see cref="FluidSolver.Step"/> runs, each pass over
    /// <see cref="FluidPassJob.Batches"/> batches in parallel (the sort as one). A .NET test checks that the batch split
    /// leaves the bits unchanged. With colliders, a <see cref="FluidColliderCullJob"/> opens each substep, as
    /// <see cref="FluidSolver.Step"/> culls them per substep.
    /// </summary>
    public static class FluidJobChain
    {
        /// <summary>Batches for a fluid of <paramref name="budget"/> particles: about 1024 particles each, 1–64.</summary>
        public static int BatchCount(int budget) => System.Math.Max(1, System.Math.Min(64, budget / 1024));

        public static JobHandle Schedule(FluidPassJob job, in FluidSolver.Plan plan, JobHandle dependsOn)
        {
            job.H = plan.H;
            var passes = new NativeArray<FluidPass>(FluidSubstepPasses.MaxPasses, Allocator.Temp);
            int passCount = FluidSubstepPasses.Write(job.Constants, plan.H, job.Colliders.Length > 0, passes.AsSpan());
            JobHandle handle = dependsOn;
            // With colliders, each substep starts with a cull job (FluidColliderReach) whose list the substep's passes read.
            var cull = new FluidColliderCullJob();
            if (job.Colliders.Length > 0 && FluidColliderReach.Culls(job.Constants))
            {
                cull = new FluidColliderCullJob
                {
                    Constants = job.Constants, H = plan.H, Colliders = job.Colliders, Positions = job.Positions, Count = job.Count,
                    Near = new NativeArray<ColliderShape>(job.Colliders.Length, Allocator.TempJob, NativeArrayOptions.UninitializedMemory),
                    NearCount = new NativeArray<int>(1, Allocator.TempJob),
                };
                job.Colliders = cull.Near;
                job.ColliderCount = cull.NearCount;
            }
            for (int k = 0; k < plan.Substeps; k++)
            {
                if (cull.Near.IsCreated)
                    handle = cull.Schedule(handle);
                for (int q = 0; q < passCount; q++)
                {
                    job.Pass = passes[q];
                    bool sort = job.Pass == FluidPass.Sort || job.Pass == FluidPass.SortWithPrevious;
                    handle = job.Schedule(sort ? 1 : job.Batches, 1, handle);
                }
            }
            passes.Dispose();
            if (cull.Near.IsCreated)
            {
                handle = cull.Near.Dispose(handle);
                handle = cull.NearCount.Dispose(handle);
            }
            return handle;
        }

        /// <summary>Sums the batches' counters in batch order (integer sums and a maximum: the same for any schedule).</summary>
        public static FluidPassCounters Sum(NativeArray<FluidPassCounters> counters)
        {
            var total = new FluidPassCounters();
            for (int b = 0; b < counters.Length; b++)
                total.Add(counters[b]);
            return total;
        }
    }
}
