using SoftBodyDynamics.Solvers;
using Unity.Burst;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;
using Unity.Transforms;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Places new soft bodies: for every body with <see cref="SoftBodyUninitialized"/> enabled it sizes the
    /// particle and cluster buffers, puts the rest shape at the entity's <see cref="LocalTransform"/> (mesh
    /// origin; scale reset to 1) at rest with <see cref="ShapeMatchingSolver.Initialize"/>, and disables the
    /// tag. Runs first in the fixed step, so prefabs instantiated at any time start where they were placed.
    /// </summary>
    [UpdateInGroup(typeof(ParticleSimulationSystemGroup))]
    [UpdateBefore(typeof(ShapeMatchingSimulationSystem))]
    [BurstCompile]
    public partial struct ShapeMatchingInitializationSystem : ISystem
    {
        [BurstCompile]
        public void OnCreate(ref SystemState state)
        {
            state.RequireForUpdate<SoftBodyUninitialized>();
        }

        [BurstCompile]
        public void OnUpdate(ref SystemState state)
        {
            new InitializeJob { QuadraticInverse = SystemAPI.GetBufferLookup<ShapeMatchingQuadraticInverse>() }.ScheduleParallel();
        }

        [BurstCompile]
        partial struct InitializeJob : IJobEntity
        {
            /// <summary>Optional per-instance quadratic inverses; each job index touches only its own entity's buffer.</summary>
            [NativeDisableParallelForRestriction] public BufferLookup<ShapeMatchingQuadraticInverse> QuadraticInverse;

            void Execute(Entity entity, in ShapeMatchingShape shape, ref LocalTransform transform, ref ParticleBodyState body,
                ref ShapeMatchingDiagnostics diagnostics,
                DynamicBuffer<SoftBodyPosition> positions, DynamicBuffer<SoftBodyVelocity> velocities,
                DynamicBuffer<ShapeMatchingCluster> clusters, EnabledRefRW<SoftBodyUninitialized> uninitialized)
            {
                ref ShapeMatchingShapeBlob blob = ref shape.Blob.Value;
                int n = blob.ParticleCount;
                positions.ResizeUninitialized(n);
                velocities.ResizeUninitialized(n);
                clusters.ResizeUninitialized(blob.ClusterCount);
                var quadratic = default(System.Span<float3x3>);
                if (QuadraticInverse.TryGetBuffer(entity, out DynamicBuffer<ShapeMatchingQuadraticInverse> perInstance))
                {
                    perInstance.ResizeUninitialized(blob.QuadraticInverse.Length);
                    quadratic = SoftBodyBuffers.AsSpan(perInstance);
                }

                // Placing the rest shape needs no scratch (see ShapeMatchingState): none is allocated.
                var solverState = new ShapeMatchingState(SoftBodyBuffers.AsSpan(positions), SoftBodyBuffers.AsSpan(velocities),
                    SoftBodyBuffers.AsSpan(clusters), quadratic, default, default, default);
                quaternion rotation = math.normalizesafe(transform.Rotation);
                transform = LocalTransform.FromPositionRotation(transform.Position, rotation);
                ShapeMatchingSolver.Initialize(blob.AsModel(), solverState,
                    SoftBodyPlacement.CenterOfMass(transform, blob.BodyRest.RestCenter), rotation, float3.zero, out body.Status);
                body.LastReport = ParticleBodyState.Unstepped.LastReport;
                diagnostics = ShapeMatchingDiagnostics.Unstepped;
                uninitialized.ValueRW = false;
            }
        }
    }
}
