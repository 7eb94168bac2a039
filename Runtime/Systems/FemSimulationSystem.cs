using SoftBodyDynamics.Solvers;
using Unity.Burst;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;
using Unity.Transforms;
using UnityEngine;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Places and steps every finite-element body once per fixed step. Runs only while some entity has a
    /// <see cref="FemShape"/> (a scene of shape-matching or mass-spring bodies pays nothing for it). Per update, three
    /// Burst jobs, one body per job index: bodies with <see cref="SoftBodyUninitialized"/> enabled get their buffers
    /// sized (nodes, <see cref="FemWarmStart"/>s and <see cref="FemElementRotation"/>s) and the rest shape placed at their <see cref="LocalTransform"/> (<see cref="FemSolver.Initialize"/>);
    /// pending <see cref="SoftBodyImpulse"/>s are applied; then <see cref="FemSolver.Step"/>, the same function
    /// the .NET tests call, advances every body against the step's collider world (<see cref="ColliderWorldShape"/>). A
    /// <see cref="ParticleWorldSettings"/> singleton replaces each body's gravity and raises its substeps, as for shape
    /// matching. The entity's <see cref="LocalTransform"/> follows the body and <see cref="ParticleBodyState"/> holds the
    /// shared report and <see cref="FemDiagnostics"/> the FEM specifics; a NaN-guard reset logs a warning naming the entity and the particle.
    /// </summary>
    [UpdateInGroup(typeof(ParticleSimulationSystemGroup))]
    [BurstCompile]
    public partial struct FemSimulationSystem : ISystem
    {
        [BurstCompile]
        public void OnCreate(ref SystemState state)
        {
            state.RequireForUpdate<FemShape>();
            state.RequireForUpdate<ColliderWorldShape>();
        }

        [BurstCompile]
        public void OnUpdate(ref SystemState state)
        {
            bool hasWorld = SystemAPI.TryGetSingleton(out ParticleWorldSettings world);
            NativeArray<ColliderShape> colliders = SystemAPI.GetSingletonBuffer<ColliderWorldShape>(true).Reinterpret<ColliderShape>().AsNativeArray();
            new InitializeJob().ScheduleParallel();
            new ApplyImpulseJob().ScheduleParallel();
            new StepJob
            {
                Colliders = colliders,
                DeltaTime = SystemAPI.Time.DeltaTime,
                HasWorldSettings = hasWorld,
                World = world,
            }.ScheduleParallel();
        }

        static System.Span<float3> AsSpan(DynamicBuffer<FemWarmStart> buffer) =>
            buffer.Reinterpret<float3>().AsNativeArray().AsSpan();

        static System.Span<quaternion> AsSpan(DynamicBuffer<FemElementRotation> buffer) =>
            buffer.Reinterpret<quaternion>().AsNativeArray().AsSpan();

        /// <summary>Sizes the buffers and places the rest shape at the entity's transform (mesh origin; scale reset to 1), at rest.</summary>
        [BurstCompile]
        partial struct InitializeJob : IJobEntity
        {
            void Execute(in FemShape shape, ref LocalTransform transform, ref ParticleBodyState body,
                DynamicBuffer<SoftBodyPosition> positions, DynamicBuffer<SoftBodyVelocity> velocities,
                DynamicBuffer<FemElementRotation> rotations, DynamicBuffer<FemWarmStart> warmStart,
                EnabledRefRW<SoftBodyUninitialized> uninitialized)
            {
                ref FemShapeBlob blob = ref shape.Blob.Value;
                positions.ResizeUninitialized(blob.ParticleCount);
                velocities.ResizeUninitialized(blob.ParticleCount);
                rotations.ResizeUninitialized(blob.PointCount);
                warmStart.ResizeUninitialized(blob.ParticleCount);
                // Placing the rest shape needs no scratch (see FemState); it clears the warm start.
                var solverState = new FemState(SoftBodyBuffers.AsSpan(positions), SoftBodyBuffers.AsSpan(velocities),
                    AsSpan(rotations), default, default, default, default, default, default, default, AsSpan(warmStart));
                quaternion rotation = math.normalizesafe(transform.Rotation);
                transform = LocalTransform.FromPositionRotation(transform.Position, rotation);
                FemSolver.Initialize(blob.AsModel(), solverState, SoftBodyPlacement.CenterOfMass(transform, blob.RestCenter),
                    rotation, float3.zero, out body.Status);
                body.LastReport = ParticleBodyState.Unstepped.LastReport;
                uninitialized.ValueRW = false;
            }
        }

        /// <summary>Adds each enabled <see cref="SoftBodyImpulse"/> of a finite-element body, wakes it and disables the impulse.</summary>
        [BurstCompile]
        [WithNone(typeof(SoftBodyUninitialized))]
        partial struct ApplyImpulseJob : IJobEntity
        {
            void Execute(in FemShape shape, ref ParticleBodyState body, in DynamicBuffer<SoftBodyPosition> positions,
                DynamicBuffer<SoftBodyVelocity> velocities, in SoftBodyImpulse impulse, EnabledRefRW<SoftBodyImpulse> pending)
            {
                // The shape is the filter: only this method's bodies (the mass-spring system handles its own).
                ParticleBodyImpulse.Apply(ref body.Status, positions, velocities, impulse);
                pending.ValueRW = false;
            }
        }

        [BurstCompile]
        [WithNone(typeof(SoftBodyUninitialized))]
        partial struct StepJob : IJobEntity
        {
            /// <summary>The step's collider world (<see cref="ColliderWorldSystem"/>).</summary>
            [ReadOnly] public NativeArray<ColliderShape> Colliders;
            /// <summary>Fixed time step (s).</summary>
            public float DeltaTime;
            /// <summary>True when a <see cref="ParticleWorldSettings"/> singleton exists.</summary>
            public bool HasWorldSettings;
            /// <summary>The world's settings (when <see cref="HasWorldSettings"/>).</summary>
            public ParticleWorldSettings World;

            void Execute(Entity entity, in FemShape shape, in FemSettings settings, ref ParticleBodyState body,
                ref FemDiagnostics diagnostics, ref LocalTransform transform, DynamicBuffer<SoftBodyPosition> positions,
                DynamicBuffer<SoftBodyVelocity> velocities, DynamicBuffer<FemElementRotation> rotations, DynamicBuffer<FemWarmStart> warmStart)
            {
                ref FemShapeBlob blob = ref shape.Blob.Value;
                int n = blob.ParticleCount;
                // Buffers are sized by the initialization job; anything else is not a body this job can step.
                if (positions.Length != n || velocities.Length != n || rotations.Length != blob.PointCount || warmStart.Length != n)
                    return;
                var scratch = new NativeArray<float3>(FemState.ScratchPerParticle * n, Allocator.Temp,
                    NativeArrayOptions.UninitializedMemory);
                var elementScratch = new NativeArray<float3>(FemState.ScratchPerElement * blob.PointCount, Allocator.Temp,
                    NativeArrayOptions.UninitializedMemory);
                var solverState = FemState.FromScratch(SoftBodyBuffers.AsSpan(positions), SoftBodyBuffers.AsSpan(velocities),
                    AsSpan(rotations), scratch.AsSpan(), elementScratch.AsSpan(), AsSpan(warmStart));
                FemParameters parameters = settings.Value;
                if (HasWorldSettings)
                    parameters.Body = World.Apply(parameters.Body);
                FemStepReport full = FemSolver.Step(blob.AsModel(), parameters,
                    Colliders.AsReadOnlySpan(), DeltaTime, solverState, ref body.Status);
                scratch.Dispose();
                elementScratch.Dispose();

                diagnostics.LastReport = full;
                ParticleStepReport report = full.Step;
                body.LastReport = report;
                if (report.Reset)
                    Debug.LogWarning($"FEM body Entity({entity.Index}:{entity.Version}) was reset to its rest shape by the NaN guard: particle {report.BadParticle} had a non-finite or excessive position or velocity.");
                transform = SoftBodyPlacement.ToLocalTransform(body.Status, blob.RestCenter);
            }
        }
    }
}
