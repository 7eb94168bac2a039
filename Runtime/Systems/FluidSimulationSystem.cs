using SoftBodyDynamics.Solvers;
using Unity.Burst;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;
using Unity.Transforms;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Steps every fluid once per fixed step, with its drains and taps (<see cref="FluidFrame.Advance"/>, the same function
    /// the .NET tests call, through <see cref="FluidSystemFrame"/>). Runs only while some entity has
    /// <see cref="FluidSettings"/>: a scene without a fluid pays nothing for it.
    /// <list type="bullet">
    /// <item>Packed storage: one Burst job per fluid (fluids in parallel; inside a fluid the passes run single-threaded in
    /// this version) over the fluid entity's buffers.</item>
    /// <item>Entities storage: on the main thread (Burst), per fluid: the particle entities are gathered into the fluid's
    /// buffers (entities destroyed by gameplay since the last step are gone and counted as killed), the frame runs,
    /// every surviving entity gets its <see cref="FluidParticle"/> and <see cref="LocalTransform"/> back in one
    /// query-wide copy, removed particles' entities are destroyed in one batch and new ones instantiated from the prefab
    /// in one batch.</item>
    /// </list>
    /// </summary>
    [UpdateInGroup(typeof(FixedStepSimulationSystemGroup))]
    [BurstCompile]
    public partial struct FluidSimulationSystem : ISystem
    {
        EntityQuery m_Colliders;
        EntityQuery m_Taps;
        EntityQuery m_Drains;
        EntityQuery m_Fluids;
        EntityQuery m_Particles;

        [BurstCompile]
        public void OnCreate(ref SystemState state)
        {
            state.RequireForUpdate<FluidSettings>();
            m_Colliders = SystemAPI.QueryBuilder().WithAll<SoftBodyCollider>().Build();
            m_Taps = SystemAPI.QueryBuilder().WithAll<FluidTap>().Build();
            m_Drains = SystemAPI.QueryBuilder().WithAll<FluidDrainVolume>().Build();
            m_Fluids = SystemAPI.QueryBuilder().WithAll<FluidSettings, FluidRuntime>().Build();
            m_Particles = SystemAPI.QueryBuilder().WithAll<FluidParticle, LocalTransform>().Build();
        }

        [BurstCompile]
        public void OnUpdate(ref SystemState state)
        {
            float dt = SystemAPI.Time.DeltaTime;
            NativeArray<SoftBodyCollider> colliders = m_Colliders.ToComponentDataArray<SoftBodyCollider>(Allocator.TempJob);
            NativeArray<FluidTap> taps = m_Taps.ToComponentDataArray<FluidTap>(Allocator.TempJob);
            NativeArray<Entity> tapEntities = m_Taps.ToEntityArray(Allocator.TempJob);
            NativeArray<FluidDrainVolume> drains = m_Drains.ToComponentDataArray<FluidDrainVolume>(Allocator.TempJob);

            // Entity storage first, on the main thread: it changes the world's structure.
            state.CompleteDependency();
            NativeArray<Entity> fluids = m_Fluids.ToEntityArray(Allocator.Temp);
            for (int f = 0; f < fluids.Length; f++)
            {
                FluidSettings settings = state.EntityManager.GetComponentData<FluidSettings>(fluids[f]);
                if (settings.Storage == FluidStorage.Entities)
                    StepEntityFluid(ref state, fluids[f], settings, colliders, taps, tapEntities, drains, dt);
            }
            fluids.Dispose();

            new PackedStepJob { Colliders = colliders, Taps = taps, TapEntities = tapEntities, Drains = drains, DeltaTime = dt }.ScheduleParallel();
            colliders.Dispose(state.Dependency);
            taps.Dispose(state.Dependency);
            tapEntities.Dispose(state.Dependency);
            drains.Dispose(state.Dependency);
        }

        static FluidEntityArrays Arrays(EntityManager m, Entity fluid) => new FluidEntityArrays
        {
            Positions = m.GetBuffer<FluidPosition>(fluid),
            Velocities = m.GetBuffer<FluidVelocity>(fluid),
            Ages = m.GetBuffer<FluidAge>(fluid),
            Lifetimes = m.GetBuffer<FluidLifetime>(fluid),
            Attributes = m.GetBuffer<FluidAttribute>(fluid),
            Ids = m.GetBuffer<FluidId>(fluid),
            ScratchInts = m.GetBuffer<FluidScratchInt>(fluid),
            ScratchFloats = m.GetBuffer<FluidScratchFloat>(fluid),
            ScratchVectors = m.GetBuffer<FluidScratchVector>(fluid),
            Taps = m.GetBuffer<FluidTapRuntime>(fluid),
        };

        /// <summary>Gather → frame → write back, destroy and instantiate in batches (see the class comment).</summary>
        void StepEntityFluid(ref SystemState state, Entity fluid, FluidSettings settings, NativeArray<SoftBodyCollider> colliders,
            NativeArray<FluidTap> taps, NativeArray<Entity> tapEntities, NativeArray<FluidDrainVolume> drains, float dt)
        {
            EntityManager m = state.EntityManager;
            FluidRuntime runtime = m.GetComponentData<FluidRuntime>(fluid);
            FluidEntityArrays a = Arrays(m, fluid);
            if (!FluidSystemFrame.Prepare(settings, ref runtime, a, out FluidConstants constants))
            {
                m.SetComponentData(fluid, runtime);
                return;
            }
            a = Arrays(m, fluid);
            FluidParticles p = FluidSystemFrame.Particles(a);
            NativeArray<FluidParticle> data = m_Particles.ToComponentDataArray<FluidParticle>(Allocator.Temp);
            NativeArray<LocalTransform> transforms = m_Particles.ToComponentDataArray<LocalTransform>(Allocator.Temp);
            NativeArray<Entity> entities = m_Particles.ToEntityArray(Allocator.Temp);
            EntityParticleGather gather = EntityParticleGather.Pack(fluid, data, p, ref runtime.Status, Allocator.Temp);

            FluidSystemFrame.Run(fluid, settings, constants, ref runtime, a, colliders, taps, tapEntities, drains, dt);

            p = FluidSystemFrame.Particles(Arrays(m, fluid));
            NativeArray<Entity> dead = gather.Unpack(fluid, p, ref runtime.Status, data, transforms, entities, Allocator.Temp,
                out NativeArray<int> newSlots, out int created);
            m_Particles.CopyFromComponentDataArray(data);
            m_Particles.CopyFromComponentDataArray(transforms);
            if (dead.Length > 0)
                m.DestroyEntity(dead);
            if (created > 0 && settings.ParticlePrefab != Entity.Null)
            {
                var spawned = new NativeArray<Entity>(created, Allocator.Temp);
                m.Instantiate(settings.ParticlePrefab, spawned);
                p = FluidSystemFrame.Particles(Arrays(m, fluid));
                for (int k = 0; k < created; k++)
                {
                    int s = newSlots[k];
                    m.SetComponentData(spawned[k], EntityParticleGather.ToComponent(p, s, fluid));
                    LocalTransform t = m.GetComponentData<LocalTransform>(spawned[k]);
                    t.Position = p.Positions[s];
                    m.SetComponentData(spawned[k], t);
                }
                spawned.Dispose();
            }
            newSlots.Dispose();
            m.SetComponentData(fluid, runtime);
            gather.Dispose();
            dead.Dispose();
            data.Dispose();
            transforms.Dispose();
            entities.Dispose();
        }

        [BurstCompile]
        partial struct PackedStepJob : IJobEntity
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
                if (settings.Storage != FluidStorage.Packed)
                    return;
                var a = new FluidEntityArrays
                {
                    Positions = positions, Velocities = velocities, Ages = ages, Lifetimes = lifetimes, Attributes = attributes, Ids = ids,
                    ScratchInts = scratchInts, ScratchFloats = scratchFloats, ScratchVectors = scratchVectors, Taps = tapRuntime,
                };
                if (FluidSystemFrame.Prepare(settings, ref runtime, a, out FluidConstants constants))
                    FluidSystemFrame.Run(entity, settings, constants, ref runtime, a, Colliders, Taps, TapEntities, Drains, DeltaTime);
            }
        }
    }
}
