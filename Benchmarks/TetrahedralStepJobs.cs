using SoftBodyDynamics.Solvers;
using Unity.Burst;
using Unity.Collections;
using Unity.Entities;
using Unity.Jobs;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks
{
    /// <summary>
    /// One <see cref="MassSpringSolver.Step"/> of one body as a Burst job, on the data a baked body lives in: the shape in
    /// a <see cref="MassSpringShapeBlob"/> (read through <c>AsModel()</c> as <see cref="MassSpringSimulationSystem"/> does)
    /// and the state and scratch in native arrays. Compiled synchronously so the first timed run is already Burst code.
    /// </summary>
    [BurstCompile(CompileSynchronously = true)]
    public struct MassSpringStepJob : IJob
    {
        public BlobAssetReference<MassSpringShapeBlob> Shape;
        public MassSpringParameters Parameters;
        [ReadOnly] public NativeArray<ColliderShape> Colliders;
        /// <summary>Step length (s).</summary>
        public float DeltaTime;
        public NativeArray<float3> Positions;
        public NativeArray<float3> Velocities;
        /// <summary><see cref="MassSpringState.ScratchPerParticle"/> × particles.</summary>
        public NativeArray<float3> Scratch;
        /// <summary><see cref="MassSpringState.ScratchPerSpring"/> × springs.</summary>
        public NativeArray<float3> SpringScratch;
        /// <summary>The body's status and the last report, one element each.</summary>
        public NativeArray<ParticleBodyStatus> Status;
        public NativeArray<ParticleStepReport> Report;

        public void Execute()
        {
            ref MassSpringShapeBlob shape = ref Shape.Value;
            var state = MassSpringState.FromScratch(Positions.AsSpan(), Velocities.AsSpan(), Scratch.AsSpan(), SpringScratch.AsSpan());
            ParticleBodyStatus status = Status[0];
            Report[0] = MassSpringSolver.Step(shape.AsModel(), Parameters, Colliders.AsReadOnlySpan(), DeltaTime, state, ref status);
            Status[0] = status;
        }
    }

    /// <summary>One <see cref="FemSolver.Step"/> of one body as a Burst job, on a <see cref="FemShapeBlob"/> and native state, as <see cref="FemSimulationSystem"/> runs it.</summary>
    [BurstCompile(CompileSynchronously = true)]
    public struct FemStepJob : IJob
    {
        public BlobAssetReference<FemShapeBlob> Shape;
        public FemParameters Parameters;
        [ReadOnly] public NativeArray<ColliderShape> Colliders;
        /// <summary>Step length (s).</summary>
        public float DeltaTime;
        public NativeArray<float3> Positions;
        public NativeArray<float3> Velocities;
        /// <summary>Per-element rotations (runtime state).</summary>
        public NativeArray<quaternion> Rotations;
        /// <summary><see cref="FemState.ScratchPerParticle"/> × nodes.</summary>
        public NativeArray<float3> Scratch;
        /// <summary><see cref="FemState.ScratchPerElement"/> × elements.</summary>
        public NativeArray<float3> ElementScratch;
        /// <summary>The body's status and the last report, one element each.</summary>
        public NativeArray<ParticleBodyStatus> Status;
        public NativeArray<FemStepReport> Report;

        public void Execute()
        {
            ref FemShapeBlob shape = ref Shape.Value;
            var state = FemState.FromScratch(Positions.AsSpan(), Velocities.AsSpan(), Rotations.AsSpan(), Scratch.AsSpan(), ElementScratch.AsSpan());
            ParticleBodyStatus status = Status[0];
            Report[0] = FemSolver.Step(shape.AsModel(), Parameters, Colliders.AsReadOnlySpan(), DeltaTime, state, ref status);
            Status[0] = status;
        }
    }
}
