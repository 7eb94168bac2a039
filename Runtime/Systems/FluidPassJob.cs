using SoftBodyDynamics.Solvers;
using Unity.Burst;
using Unity.Collections;
using Unity.Jobs;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// One pass of one fluid's substep over batch <c>index</c> of <see cref="Batches"/> equal ranges of the live particles
    /// (the live count is read from <see cref="Count"/>, which the sort pass writes), calling the same range function as
    /// the single-threaded <see cref="FluidSolver"/> step. The passes are written so that any split gives the same bits
    /// (tested in .NET), so the result does not depend on the worker count. The sort is one batch (index 0 only).
    /// Counters go to the batch's own slot of <see cref="Counters"/> and are summed in order on the main thread.
    /// </summary>
    [BurstCompile]
    public struct FluidPassJob : IJobParallelFor
    {
        public FluidConstants Constants;
        public FluidPass Pass;
        /// <summary>Substep length (s).</summary>
        public float H;
        /// <summary>Number of batches the live particles are split into.</summary>
        public int Batches;
        /// <summary>The colliders; with <see cref="ColliderCount"/> set, only its first <c>ColliderCount[0]</c> are read.</summary>
        [ReadOnly] public NativeArray<ColliderShape> Colliders;
        /// <summary>The substep's collider count (one element, written by <see cref="FluidColliderCullJob"/>), or unset for all of <see cref="Colliders"/>.</summary>
        [ReadOnly] public NativeArray<int> ColliderCount;
        [NativeDisableParallelForRestriction] public NativeArray<float3> Positions, Velocities;
        [NativeDisableParallelForRestriction] public NativeArray<float> Ages, Lifetimes, Attributes;
        [NativeDisableParallelForRestriction] public NativeArray<int> Ids;
        [NativeDisableParallelForRestriction] public NativeArray<int> ScratchInts;
        [NativeDisableParallelForRestriction] public NativeArray<float> ScratchFloats;
        [NativeDisableParallelForRestriction] public NativeArray<float3> ScratchVectors;
        /// <summary>The live count (one element): read by every pass, written by the sort.</summary>
        [NativeDisableParallelForRestriction] public NativeArray<int> Count;
        /// <summary>One counter slot per batch.</summary>
        [NativeDisableParallelForRestriction] public NativeArray<FluidPassCounters> Counters;

        public void Execute(int index)
        {
            int capacity = Positions.Length;
            var p = new FluidParticles(Positions.AsSpan(), Velocities.AsSpan(), Ages.AsSpan(), Lifetimes.AsSpan(), Attributes.AsSpan(), Ids.AsSpan());
            FluidScratch s = FluidScratch.FromFlat(ScratchInts.AsSpan(), ScratchFloats.AsSpan(), ScratchVectors.AsSpan(), capacity, Constants.Grid.CellCount);
            FluidPassCounters counters = Counters[index];
            int count = Count[0];
            System.ReadOnlySpan<ColliderShape> colliders = Colliders.AsReadOnlySpan();
            if (ColliderCount.IsCreated)
                colliders = colliders.Slice(0, math.clamp(ColliderCount[0], 0, colliders.Length));
            FluidPasses.Run(Pass, Constants, colliders, p, s, index, Batches, ref count, H, ref counters);
            // Only the sort changes the count, and it runs as a single batch.
            if (Pass == FluidPass.Sort || Pass == FluidPass.SortWithPrevious)
                Count[0] = count;
            Counters[index] = counters;
        }
    }
}
