using SoftBodyDynamics.Solvers;
using Unity.Burst;
using Unity.Collections;
using Unity.Jobs;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// At the start of a substep of the job chain, writes the colliders that substep can touch into <see cref="Near"/>
    /// and their count into <see cref="NearCount"/> (<see cref="FluidColliderReach.Near"/>, the function the
    /// single-threaded <see cref="FluidSolver.Step"/> calls), for the substep's pass jobs to read.
    /// </summary>
    [BurstCompile]
    public struct FluidColliderCullJob : IJob
    {
        public FluidConstants Constants;
        /// <summary>Substep length (s).</summary>
        public float H;
        /// <summary>Every collider of the step.</summary>
        [ReadOnly] public NativeArray<ColliderShape> Colliders;
        [ReadOnly] public NativeArray<float3> Positions;
        /// <summary>The live count (one element).</summary>
        [ReadOnly] public NativeArray<int> Count;
        /// <summary>The substep's colliders (as long as <see cref="Colliders"/>); the first <see cref="NearCount"/> are valid.</summary>
        public NativeArray<ColliderShape> Near;
        public NativeArray<int> NearCount;

        public void Execute()
        {
            int count = math.clamp(Count[0], 0, Positions.Length);
            NearCount[0] = FluidColliderReach.Near(Constants, Colliders.AsReadOnlySpan(), Positions.AsReadOnlySpan().Slice(0, count), H,
                Near.AsSpan());
        }
    }
}
