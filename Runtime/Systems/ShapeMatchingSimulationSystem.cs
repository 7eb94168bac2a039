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
    /// Steps every initialized soft body once per fixed step with <see cref="ShapeMatchingSolver.Step"/>, the
    /// same function the .NET tests call, against the step's collider world (<see cref="ColliderWorldShape"/>, built once per step). With a
    /// <see cref="ParticleWorldSettings"/> singleton, every body uses the world's gravity and at least its substeps
    /// (<see cref="ParticleWorldSettings.Apply"/>). One body per job
    /// index and no reductions across bodies, so results do not depend on scheduling. After the step the
    /// entity's <see cref="LocalTransform"/> follows the body (<see cref="SoftBodyPlacement.ToLocalTransform"/>),
    /// <see cref="ParticleBodyState"/> holds the shared report and <see cref="ShapeMatchingDiagnostics"/> the shape-matching
    /// specifics, and a NaN-guard reset logs a warning naming the
    /// entity and the particle. Pending <see cref="SoftBodyImpulse"/>s are applied first.
    /// </summary>
    [UpdateInGroup(typeof(ParticleSimulationSystemGroup))]
    [BurstCompile]
    public partial struct ShapeMatchingSimulationSystem : ISystem
    {
        [BurstCompile]
        public void OnCreate(ref SystemState state)
        {
            state.RequireForUpdate<ShapeMatchingShape>();
            state.RequireForUpdate<ColliderWorldShape>();
        }

        [BurstCompile]
        public void OnUpdate(ref SystemState state)
        {
            float dt = SystemAPI.Time.DeltaTime;
            bool hasWorld = SystemAPI.TryGetSingleton(out ParticleWorldSettings world);
            NativeArray<ColliderShape> colliders = SystemAPI.GetSingletonBuffer<ColliderWorldShape>(true).Reinterpret<ColliderShape>().AsNativeArray();

            new ApplyImpulseJob().ScheduleParallel();
            new StepJob
            {
                Colliders = colliders,
                DeltaTime = dt,
                HasWorldSettings = hasWorld,
                World = world,
                QuadraticInverse = SystemAPI.GetBufferLookup<ShapeMatchingQuadraticInverse>(),
            }.ScheduleParallel();
        }

        /// <summary>Adds each enabled <see cref="SoftBodyImpulse"/> of a shape-matching body, wakes it and disables the impulse.</summary>
        [BurstCompile]
        [WithNone(typeof(SoftBodyUninitialized))]
        partial struct ApplyImpulseJob : IJobEntity
        {
            void Execute(in ShapeMatchingShape shape, ref ParticleBodyState body, in DynamicBuffer<SoftBodyPosition> positions,
                DynamicBuffer<SoftBodyVelocity> velocities, in SoftBodyImpulse impulse, EnabledRefRW<SoftBodyImpulse> pending)
            {
                // The shape is the filter: only this method's bodies (the mass-spring and FEM systems handle their own).
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
            /// <summary>Optional per-instance quadratic inverses; each job index touches only its own entity's buffer.</summary>
            [NativeDisableParallelForRestriction] public BufferLookup<ShapeMatchingQuadraticInverse> QuadraticInverse;

            void Execute(Entity entity, in ShapeMatchingShape shape, in ShapeMatchingSettings settings, ref ParticleBodyState body,
                ref ShapeMatchingDiagnostics diagnostics,
                ref LocalTransform transform, DynamicBuffer<SoftBodyPosition> positions, DynamicBuffer<SoftBodyVelocity> velocities,
                DynamicBuffer<ShapeMatchingCluster> clusters)
            {
                ref ShapeMatchingShapeBlob blob = ref shape.Blob.Value;
                int n = blob.ParticleCount;
                // Buffers are sized by the initialization system; anything else is not a body this job can step.
                if (positions.Length != n || velocities.Length != n || clusters.Length != blob.ClusterCount)
                    return;
                var quadratic = default(System.Span<float3x3>);
                if (QuadraticInverse.TryGetBuffer(entity, out DynamicBuffer<ShapeMatchingQuadraticInverse> perInstance)
                    && perInstance.Length == blob.QuadraticInverse.Length)
                    quadratic = SoftBodyBuffers.AsSpan(perInstance);

                var scratch = new NativeArray<float3>(ShapeMatchingState.ScratchPerParticle * n, Allocator.Temp,
                    NativeArrayOptions.UninitializedMemory);
                var solverState = SoftBodyBuffers.State(positions, velocities, clusters, quadratic, scratch);
                ShapeMatchingParameters parameters = settings.Value;
                if (HasWorldSettings)
                    parameters.Body = World.Apply(parameters.Body);
                ShapeMatchingStepReport report = ShapeMatchingSolver.Step(blob.AsModel(), parameters,
                    Colliders.AsReadOnlySpan(), DeltaTime, solverState, ref body.Status);
                scratch.Dispose();

                diagnostics.LastReport = report;
                body.LastReport = report.Step;
                if (report.Reset)
                    Debug.LogWarning($"Soft body Entity({entity.Index}:{entity.Version}) was reset to its rest shape by the NaN guard: particle {report.BadParticle} had a non-finite or excessive position or velocity.");
                transform = SoftBodyPlacement.ToLocalTransform(body.Status, blob.BodyRest.RestCenter);
            }
        }
    }
}
