using SoftBodyDynamics.Solvers;
using Unity.Burst;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Steps every fluid once per fixed step, with its drains and taps (<see cref="FluidFrame.Advance"/>, the same function
    /// the .NET tests call). Runs only while some entity has <see cref="FluidSettings"/>: a scene without a fluid pays
    /// nothing for it. One Burst job per fluid (fluids in parallel); inside a fluid the passes run single-threaded in
    /// this version. The particles live in the fluid entity's buffers (packed storage), sized to the budget on the first
    /// update, when the taps' prewarm also runs. A frame that removed non-finite particles, hit the substep cap or the
    /// budget logs a warning naming the fluid.
    /// </summary>
    [UpdateInGroup(typeof(FixedStepSimulationSystemGroup))]
    [BurstCompile]
    public partial struct FluidSimulationSystem : ISystem
    {
        EntityQuery m_Colliders;
        EntityQuery m_Taps;
        EntityQuery m_Drains;

        [BurstCompile]
        public void OnCreate(ref SystemState state)
        {
            state.RequireForUpdate<FluidSettings>();
            m_Colliders = SystemAPI.QueryBuilder().WithAll<SoftBodyCollider>().Build();
            m_Taps = SystemAPI.QueryBuilder().WithAll<FluidTap>().Build();
            m_Drains = SystemAPI.QueryBuilder().WithAll<FluidDrainVolume>().Build();
        }

        [BurstCompile]
        public void OnUpdate(ref SystemState state)
        {
            NativeArray<SoftBodyCollider> colliders = m_Colliders.ToComponentDataArray<SoftBodyCollider>(Allocator.TempJob);
            NativeArray<FluidTap> taps = m_Taps.ToComponentDataArray<FluidTap>(Allocator.TempJob);
            NativeArray<Entity> tapEntities = m_Taps.ToEntityArray(Allocator.TempJob);
            NativeArray<FluidDrainVolume> drains = m_Drains.ToComponentDataArray<FluidDrainVolume>(Allocator.TempJob);
            new StepJob
            {
                Colliders = colliders,
                Taps = taps,
                TapEntities = tapEntities,
                Drains = drains,
                DeltaTime = SystemAPI.Time.DeltaTime,
            }.ScheduleParallel();
            colliders.Dispose(state.Dependency);
            taps.Dispose(state.Dependency);
            tapEntities.Dispose(state.Dependency);
            drains.Dispose(state.Dependency);
        }

        [BurstCompile]
        partial struct StepJob : IJobEntity
        {
            [ReadOnly] public NativeArray<SoftBodyCollider> Colliders;
            [ReadOnly] public NativeArray<FluidTap> Taps;
            [ReadOnly] public NativeArray<Entity> TapEntities;
            [ReadOnly] public NativeArray<FluidDrainVolume> Drains;
            /// <summary>Fixed time step (s).</summary>
            public float DeltaTime;

            void Execute(Entity entity, in FluidSettings settings, ref FluidRuntime runtime,
                DynamicBuffer<FluidPosition> positions, DynamicBuffer<FluidVelocity> velocities, DynamicBuffer<FluidAge> ages,
                DynamicBuffer<FluidLifetime> lifetimes, DynamicBuffer<FluidAttribute> attributes, DynamicBuffer<FluidId> ids,
                DynamicBuffer<FluidScratchInt> scratchInts, DynamicBuffer<FluidScratchFloat> scratchFloats,
                DynamicBuffer<FluidScratchVector> scratchVectors, DynamicBuffer<FluidTapRuntime> tapRuntime)
            {
                var constants = new FluidConstants(settings.Parameters);
                int budget = math.max(1, settings.Budget);
                if (!runtime.Initialized)
                {
                    FluidEntityBuffers.Resize(budget, constants.Grid.CellCount, positions, velocities, ages, lifetimes, attributes, ids,
                        scratchInts, scratchFloats, scratchVectors);
                    runtime.Initialized = true;
                }
                if (positions.Length < budget)
                    return;
                FluidParticles particles = FluidEntityBuffers.Particles(positions, velocities, ages, lifetimes, attributes, ids);
                FluidScratch scratch = FluidEntityBuffers.Scratch(scratchInts, scratchFloats, scratchVectors, budget, constants.Grid.CellCount);

                // This fluid's taps (with their state from the fluid's own buffer) and drains.
                var instances = new NativeArray<FluidTapInstance>(Taps.Length, Allocator.Temp);
                var bursts = new NativeArray<FluidTapBurst>(Taps.Length * FluidTap.MaxBursts, Allocator.Temp);
                var owners = new NativeArray<int>(Taps.Length, Allocator.Temp);
                int tapCount = 0, burstCount = 0;
                for (int t = 0; t < Taps.Length; t++)
                {
                    if (Taps[t].Fluid != entity)
                        continue;
                    FluidTap tap = Taps[t];
                    int slot = FluidEntityBuffers.TapSlot(tapRuntime, TapEntities[t]);
                    int count = math.clamp(tap.BurstCount, 0, FluidTap.MaxBursts);
                    for (int b = 0; b < count; b++)
                        bursts[burstCount + b] = tap.Burst(b);
                    instances[tapCount] = new FluidTapInstance
                    {
                        Settings = tap.Settings,
                        State = tapRuntime[slot].State,
                        BurstStart = burstCount,
                        BurstCount = count,
                    };
                    owners[tapCount++] = slot;
                    burstCount += count;
                }
                var drains = new NativeArray<FluidDrain>(Drains.Length, Allocator.Temp);
                int drainCount = 0;
                for (int d = 0; d < Drains.Length; d++)
                    if (Drains[d].Fluid == entity)
                        drains[drainCount++] = Drains[d].Drain;

                var colliderSpan = Colliders.Reinterpret<ColliderShape>().AsReadOnlySpan();
                var tapSpan = instances.AsSpan().Slice(0, tapCount);
                var burstSpan = bursts.AsReadOnlySpan().Slice(0, burstCount);
                var drainSpan = drains.AsReadOnlySpan().Slice(0, drainCount);
                if (!runtime.Prewarmed)
                {
                    FluidFrame.Prewarm(constants, colliderSpan, drainSpan, tapSpan, burstSpan, budget, DeltaTime, particles, scratch, ref runtime.Status);
                    runtime.Prewarmed = true;
                }
                FluidFrameReport report = FluidFrame.Advance(constants, colliderSpan, drainSpan, tapSpan, burstSpan, budget, DeltaTime,
                    particles, scratch, ref runtime.Status);
                for (int t = 0; t < tapCount; t++)
                {
                    FluidTapRuntime r = tapRuntime[owners[t]];
                    r.State = instances[t].State;
                    tapRuntime[owners[t]] = r;
                }
                runtime.LastFrame = report;
                instances.Dispose();
                bursts.Dispose();
                owners.Dispose();
                drains.Dispose();

                if (report.Step.Invalid > 0)
                    Debug.LogWarning($"Fluid Entity({entity.Index}:{entity.Version}): the NaN guard removed {report.Step.Invalid} particle(s) with a non-finite position or velocity.");
                if (report.Step.SubstepsWanted > report.Step.Substeps)
                    Debug.LogWarning($"Fluid Entity({entity.Index}:{entity.Version}): the CFL limit asked for {report.Step.SubstepsWanted} substeps, capped at {report.Step.Substeps}; lower the speed of sound or raise the substep cap.");
            }
        }
    }
}
