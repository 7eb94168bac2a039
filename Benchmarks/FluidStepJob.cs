using SoftBodyDynamics.Solvers;
using Unity.Burst;
using Unity.Collections;
using Unity.Jobs;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks
{
    /// <summary>
    /// One <see cref="FluidSolver.Step"/> of one fluid as a Burst job on native arrays (the flat scratch layout of
    /// <see cref="FluidScratch.FromFlat"/>, as <see cref="FluidSimulationSystem"/> keeps it in buffers). Compiled
    /// synchronously so the first timed run is already Burst code.
    /// </summary>
    [BurstCompile(CompileSynchronously = true)]
    public struct FluidStepJob : IJob
    {
        public FluidParameters Parameters;
        /// <summary>Step length (s).</summary>
        public float DeltaTime;
        public NativeArray<float3> Positions, Velocities;
        public NativeArray<float> Ages, Lifetimes, Attributes;
        public NativeArray<int> Ids;
        public NativeArray<int> ScratchInts;
        public NativeArray<float> ScratchFloats;
        public NativeArray<float3> ScratchVectors;
        /// <summary>The fluid's status and the last report, one element each.</summary>
        public NativeArray<FluidStatus> Status;
        public NativeArray<FluidStepReport> Report;

        public void Execute()
        {
            var c = new FluidConstants(Parameters);
            var particles = new FluidParticles(Positions.AsSpan(), Velocities.AsSpan(), Ages.AsSpan(), Lifetimes.AsSpan(), Attributes.AsSpan(), Ids.AsSpan());
            FluidScratch scratch = FluidScratch.FromFlat(ScratchInts.AsSpan(), ScratchFloats.AsSpan(), ScratchVectors.AsSpan(), Positions.Length, c.Grid.CellCount);
            FluidStatus status = Status[0];
            Report[0] = FluidSolver.Step(c, default, DeltaTime, particles, scratch, ref status);
            Status[0] = status;
        }
    }
}
