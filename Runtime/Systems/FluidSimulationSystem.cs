using SoftBodyDynamics.Solvers;
using Unity.Burst;
using Unity.Collections;
using Unity.Entities;
using Unity.Jobs;
using Unity.Mathematics;
using Unity.Transforms;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Steps every fluid the GPU does not run (<see cref="FluidOnGpu"/>, <see cref="FluidComputeSystem"/>) once per fixed step, with its drains and taps (<see cref="FluidFrame.Advance"/>, the same function
    /// the .NET tests call, through <see cref="FluidSystemFrame"/>). Runs only while some entity has
    /// <see cref="FluidSettings"/>: a scene without a fluid pays nothing for it.
    /// <list type="bullet">
    /// <item>Packed storage: drains and taps on the main thread, then the step's substeps as a chain of parallel Burst pass
    /// jobs over the fluid entity's buffers (<see cref="FluidJobChain"/>, <see cref="FluidPassJob"/>: about 1024 particles per
    /// batch, the same bits for any worker count), one fluid after the other; the system waits for each chain (the main
    /// thread helps run it).</item>
    /// <item>Entities storage: on the main thread (Burst), per fluid: the particle entities are gathered into the fluid's
    /// buffers (entities destroyed by gameplay since the last step are gone and counted as killed), the frame runs,
    /// every surviving entity gets its <see cref="FluidParticle"/> and <see cref="LocalTransform"/> back in one
    /// query-wide copy, removed particles' entities are destroyed in one batch and new ones instantiated from the prefab
    /// in one batch.</item>
    /// </list>
    /// </summary>
    [UpdateInGroup(typeof(ParticleSimulationSystemGroup))]
    [BurstCompile]
    public partial struct FluidSimulationSystem : ISystem
    {
        EntityQuery m_Taps;
        EntityQuery m_Drains;
        EntityQuery m_Fluids;
        EntityQuery m_Particles;

        [BurstCompile]
        public void OnCreate(ref SystemState state)
        {
            state.RequireForUpdate<FluidSettings>();
            state.RequireForUpdate<ColliderWorldShape>();
            m_Taps = SystemAPI.QueryBuilder().WithAll<FluidTap>().Build();
            m_Drains = SystemAPI.QueryBuilder().WithAll<FluidDrainVolume>().Build();
            m_Fluids = SystemAPI.QueryBuilder().WithAll<FluidSettings, FluidRuntime>().WithNone<FluidOnGpu>().Build();
            m_Particles = SystemAPI.QueryBuilder().WithAll<FluidParticle, LocalTransform>().Build();
        }

        [BurstCompile]
        public void OnUpdate(ref SystemState state)
        {
            float dt = SystemAPI.Time.DeltaTime;
            state.CompleteDependency();
            var inputs = FluidFrameInputs.Gather(SystemAPI.GetSingletonBuffer<ColliderWorldShape>(true), m_Taps, m_Drains);
            NativeArray<ColliderShape> colliders = inputs.Colliders;
            NativeArray<FluidTap> taps = inputs.Taps;
            NativeArray<Entity> tapEntities = inputs.TapEntities;
            NativeArray<FluidDrainVolume> drains = inputs.Drains;
            NativeArray<Entity> fluids = m_Fluids.ToEntityArray(Allocator.Temp);

            bool hasWorld = SystemAPI.TryGetSingleton(out ParticleWorldSettings world);

            // Entities storage first, on the main thread: it changes the world's structure.
            for (int f = 0; f < fluids.Length; f++)
            {
                FluidSettings settings = FluidSystemFrame.InWorld(state.EntityManager.GetComponentData<FluidSettings>(fluids[f]), hasWorld, world);
                if (settings.Storage == FluidStorage.Entities)
                    StepEntityFluid(ref state, fluids[f], settings, colliders, taps, tapEntities, drains, dt);
            }

            // Packed storage, one fluid at a time: drains and taps on the main thread, then the step's substeps as a chain
            // of parallel pass jobs, completed before the next fluid (the main thread helps run them while it waits).
            EntityManager m = state.EntityManager;
            for (int f = 0; f < fluids.Length; f++)
            {
                Entity fluid = fluids[f];
                FluidSettings settings = FluidSystemFrame.InWorld(m.GetComponentData<FluidSettings>(fluid), hasWorld, world);
                if (settings.Storage != FluidStorage.Packed)
                    continue;
                FluidRuntime runtime = m.GetComponentData<FluidRuntime>(fluid);
                FluidEntityArrays a = Arrays(m, fluid);
                if (FluidSystemFrame.Prepare(settings, ref runtime, a, out FluidConstants constants))
                    StepPackedFluid(fluid, settings, constants, ref runtime, Arrays(m, fluid), colliders, taps, tapEntities, drains, dt);
                m.SetComponentData(fluid, runtime);
            }
            fluids.Dispose();
            inputs.Dispose();
        }

        /// <summary>Drains, taps, then the substeps as a job chain (<see cref="FluidJobChain"/>), completed here.</summary>
        static void StepPackedFluid(Entity fluid, in FluidSettings settings, in FluidConstants constants, ref FluidRuntime runtime,
            FluidEntityArrays a, NativeArray<ColliderShape> colliders, NativeArray<FluidTap> taps, NativeArray<Entity> tapEntities,
            NativeArray<FluidDrainVolume> drains, float dt)
        {
            FluidFrameReport frame = FluidSystemFrame.DrainAndEmit(fluid, settings, constants, ref runtime, a, colliders, taps, tapEntities, drains, dt);
            FluidSolver.Plan plan = FluidSolver.Begin(constants, dt, FluidSystemFrame.Particles(a), ref runtime.Status);
            int batches = FluidJobChain.BatchCount(settings.Budget);
            var count = new NativeArray<int>(1, Allocator.TempJob);
            count[0] = runtime.Status.Count;
            var counters = new NativeArray<FluidPassCounters>(batches, Allocator.TempJob);
            var job = new FluidPassJob
            {
                Constants = constants,
                Batches = batches,
                Colliders = colliders,
                Positions = a.Positions.Reinterpret<float3>().AsNativeArray(),
                Velocities = a.Velocities.Reinterpret<float3>().AsNativeArray(),
                Ages = a.Ages.Reinterpret<float>().AsNativeArray(),
                Lifetimes = a.Lifetimes.Reinterpret<float>().AsNativeArray(),
                Attributes = a.Attributes.Reinterpret<float>().AsNativeArray(),
                Ids = a.Ids.Reinterpret<int>().AsNativeArray(),
                ScratchInts = a.ScratchInts.Reinterpret<int>().AsNativeArray(),
                ScratchFloats = a.ScratchFloats.Reinterpret<float>().AsNativeArray(),
                ScratchVectors = a.ScratchVectors.Reinterpret<float3>().AsNativeArray(),
                Count = count,
                Counters = counters,
            };
            FluidJobChain.Schedule(job, plan, default).Complete();
            frame.Step = FluidSolver.Finish(plan, FluidJobChain.Sum(counters), dt, count[0], ref runtime.Status);
            FluidSystemFrame.Close(fluid, ref runtime, frame);
            count.Dispose();
            counters.Dispose();
        }

        internal static FluidEntityArrays Arrays(EntityManager m, Entity fluid) => new FluidEntityArrays
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
        void StepEntityFluid(ref SystemState state, Entity fluid, FluidSettings settings, NativeArray<ColliderShape> colliders,
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
    }
}
