using System.Collections.Generic;
using SoftBodyDynamics.Compute;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;
using UnityEngine;
using UnityEngine.Rendering;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Runs on the GPU the packed fluids whose <see cref="FluidSettings.Backend"/> asks for it and whose device allows it
    /// (<see cref="FluidBackendChoice"/>; the reason for a fallback is logged once per fluid, and such a fluid stays with
    /// <see cref="FluidSimulationSystem"/>). A fluid it takes gets <see cref="FluidOnGpu"/>, a <see cref="FluidComputeSolver"/>
    /// holding its particles (uploaded once from the entity buffers), and each fixed step: its colliders and drains, the
    /// taps' spawns (placed by the CPU emitter from the tap schedule, then appended on the GPU), the drains, the taps' spawns and the step's dispatches.
    /// The live count and removal totals come back asynchronously; the particles come back into the entity buffers as
    /// <see cref="FluidSettings.Readback"/> says, never stalling the frame. Runs only while a fluid has a compute shader.
    /// </summary>
    [UpdateInGroup(typeof(ParticleSimulationSystemGroup))]
    [UpdateAfter(typeof(ShapeMatchingSimulationSystem))]
    [UpdateAfter(typeof(MassSpringSimulationSystem))]
    [UpdateAfter(typeof(FemSimulationSystem))]
    [UpdateBefore(typeof(FluidSimulationSystem))]
    public partial class FluidComputeSystem : SystemBase
    {
        sealed class Run
        {
            public FluidComputeSolver Solver;
            public FluidComputeSpawns Spawns;
            public FluidConstants Constants;
            public FluidStatus Base;
            public int Frame;
            public readonly GpuReadback<float4> Positions = new GpuReadback<float4>(), Velocities = new GpuReadback<float4>();
            public readonly GpuReadback<FluidComputeExtras> Extras = new GpuReadback<FluidComputeExtras>();

            public void Dispose()
            {
                Solver.Dispose();
                Spawns.Dispose();
                Positions.Dispose();
                Velocities.Dispose();
                Extras.Dispose();
            }
        }

        readonly Dictionary<Entity, Run> m_Runs = new Dictionary<Entity, Run>();
        readonly HashSet<Entity> m_Declined = new HashSet<Entity>();
        readonly List<Entity> m_Gone = new List<Entity>();
        EntityQuery m_Fluids, m_Taps, m_Drains;
        FluidRenderSources m_Sources;

        protected override void OnCreate()
        {
            // The world's renderer hand-off, held by its surface source system (created here if the world lacks it).
            m_Sources = World.GetOrCreateSystemManaged<FluidSurfaceSourceSystem>().Sources;
            RequireForUpdate<FluidComputeShader>();
            m_Fluids = SystemAPI.QueryBuilder().WithAll<FluidSettings, FluidRuntime, FluidComputeShader>().Build();
            RequireForUpdate<ColliderWorldShape>();
            m_Taps = SystemAPI.QueryBuilder().WithAll<FluidTap>().Build();
            m_Drains = SystemAPI.QueryBuilder().WithAll<FluidDrainVolume>().Build();
        }

        protected override void OnUpdate()
        {
            CompleteDependency();
            float dt = SystemAPI.Time.DeltaTime;
            EntityManager m = EntityManager;
            NativeArray<Entity> fluids = m_Fluids.ToEntityArray(Allocator.Temp);
            var inputs = FluidFrameInputs.Gather(SystemAPI.GetSingletonBuffer<ColliderWorldShape>(true), m_Taps, m_Drains);
            ReleaseRemoved(m);
            bool hasWorld = SystemAPI.TryGetSingleton(out ParticleWorldSettings world);
            for (int f = 0; f < fluids.Length; f++)
            {
                Entity fluid = fluids[f];
                // The world's gravity is part of the constants a fluid is taken onto the GPU with.
                FluidSettings settings = FluidSystemFrame.InWorld(m.GetComponentData<FluidSettings>(fluid), hasWorld, world);
                if (!m_Runs.TryGetValue(fluid, out Run run) && !TryTake(m, fluid, settings, out run))
                    continue;
                FluidRuntime runtime = m.GetComponentData<FluidRuntime>(fluid);
                StepOnGpu(m, fluid, settings, ref runtime, run, inputs, m_Sources, dt);
                m.SetComponentData(fluid, runtime);
            }
            fluids.Dispose();
            inputs.Dispose();
        }

        /// <summary>Takes a fluid onto the GPU when its settings and the device allow it; says once why not.</summary>
        bool TryTake(EntityManager m, Entity fluid, in FluidSettings settings, out Run run)
        {
            run = null;
            if (settings.Backend == FluidBackend.Cpu || m_Declined.Contains(fluid))
                return false;
            ComputeShader shader = m.GetComponentData<FluidComputeShader>(fluid).Shader.Value;
            string reason;
            if (settings.Storage != FluidStorage.Packed)
                reason = "Entities storage runs on the CPU";
            else if (shader == null)
                reason = "no compute shader is assigned";
            else
                FluidBackendChoice.UseGpu(settings.Backend, SystemInfo.supportsComputeShaders, SystemInfo.supportsAsyncGPUReadback,
                    SystemInfo.maxComputeWorkGroupSize, SystemInfo.maxComputeBufferInputsCompute, out reason);
            if (reason != null)
            {
                m_Declined.Add(fluid);
                string message = $"Fluid Entity({fluid.Index}:{fluid.Version}) runs on the CPU: {reason}.";
                if (settings.Backend == FluidBackend.Gpu)
                    Debug.LogWarning(message);
                else
                    Debug.Log(message);
                return false;
            }
            FluidRuntime runtime = m.GetComponentData<FluidRuntime>(fluid);
            FluidEntityArrays a = FluidSimulationSystem.Arrays(m, fluid);
            if (!FluidSystemFrame.Prepare(settings, ref runtime, a, out FluidConstants constants))
                return false;
            int budget = math.max(1, settings.Budget);
            run = new Run
            {
                Solver = new FluidComputeSolver(shader, constants, budget),
                Spawns = new FluidComputeSpawns(budget, constants.Grid.CellCount),
                Constants = constants,
                Base = runtime.Status,
            };
            int count = math.clamp(runtime.Status.Count, 0, a.Positions.Length);
            var positions = new NativeArray<float4>(math.max(count, 1), Allocator.Temp);
            var velocities = new NativeArray<float4>(math.max(count, 1), Allocator.Temp);
            var extras = new NativeArray<FluidComputeExtras>(math.max(count, 1), Allocator.Temp);
            FluidComputeStep.Pack(FluidSystemFrame.Particles(a), count, positions.AsSpan(), velocities.AsSpan(), extras.AsSpan());
            run.Solver.Upload(positions, velocities, extras, count);
            m.SetComponentData(fluid, runtime);
            m.AddComponent<FluidOnGpu>(fluid);
            m_Runs[fluid] = run;
            return true;
        }

        /// <summary>Colliders and drains, the taps' spawns, the step, then the read-backs the settings ask for.</summary>
        static void StepOnGpu(EntityManager m, Entity fluid, in FluidSettings settings, ref FluidRuntime runtime, Run run,
            in FluidFrameInputs inputs, FluidRenderSources sources, float dt)
        {
            FluidComputeSolver solver = run.Solver;
            var drains = new NativeArray<FluidDrain>(inputs.Drains.Length, Allocator.Temp);
            int drainCount = FluidSystemFrame.DrainsOf(fluid, inputs.Drains, drains);
            solver.SetShapes(inputs.Colliders, drains.GetSubArray(0, drainCount));
            // As on the CPU (FluidFrame.DrainAndEmit): drains mark first, then the taps spawn, then the step.
            solver.Drain();
            FluidFrameReport frame = run.Spawns.Emit(m, fluid, run.Constants, ref runtime, solver, inputs.Taps, inputs.TapEntities,
                math.max(1, settings.Budget), dt);
            frame.Step.Substeps = solver.Step(dt);
            runtime.LastFrame = frame;
            if (m.HasComponent<FluidSurface>(fluid))
                RegisterForRenderer(fluid, settings, m.GetComponentData<FluidSurface>(fluid), solver, sources);
            ReadBack(m, fluid, settings, ref runtime, run);
            drains.Dispose();
        }

        /// <summary>
        /// The renderer's buffer (<see cref="FluidComputeSolver.PackRender"/>: every slot, NaN beyond the live particles,
        /// so no live count is needed on the CPU) and the fluid's domain as its bounds.
        /// </summary>
        static void RegisterForRenderer(Entity fluid, in FluidSettings settings, in FluidSurface surface, FluidComputeSolver solver,
            FluidRenderSources sources)
        {
            solver.PackRender();
            FluidRenderSource source = sources.Get(fluid) ?? new FluidRenderSource();
            source.Particles = solver.Buffer(FluidComputeBuffer.RenderParticles);
            source.Count = solver.Capacity;
            source.WorldBounds = FluidRenderSource.SphereBounds(settings.Parameters.DomainMin, settings.Parameters.DomainMax, surface.ParticleRadius);
            source.ParticleRadius = surface.ParticleRadius;
            source.Look = surface.Look;
            sources.Set(fluid, source);
        }

        /// <summary>
        /// Counters every step (when the last request has arrived); particles into the entity buffers every step or
        /// every N steps. A request is polled on later steps, never waited for.
        /// </summary>
        static void ReadBack(EntityManager m, Entity fluid, in FluidSettings settings, ref FluidRuntime runtime, Run run)
        {
            FluidComputeSolver solver = run.Solver;
            System.ReadOnlySpan<uint> stats = solver.LastStats;
            runtime.Status.Count = (int)stats[FluidComputeLayout.StatLive];
            runtime.Status.Killed = run.Base.Killed + (int)stats[FluidComputeLayout.StatTotalKilled];
            runtime.Status.Expired = run.Base.Expired + (int)stats[FluidComputeLayout.StatTotalExpired];
            runtime.Status.Invalid = run.Base.Invalid + (int)stats[FluidComputeLayout.StatTotalInvalid];
            run.Frame++;
            // The three requests go out together; their data is kept (GpuReadback) until all three have arrived.
            if (run.Positions.Pending || run.Velocities.Pending || run.Extras.Pending)
                return;
            if (run.Positions.Arrived && run.Velocities.Arrived && run.Extras.Arrived)
                CopyParticles(m, fluid, run);
            bool due = settings.Readback == FluidReadback.EveryFrame
                || (settings.Readback == FluidReadback.EveryNFrames && run.Frame % math.max(1, settings.ReadbackInterval) == 0);
            if (!due)
                return;
            run.Positions.Request(solver.Buffer(FluidComputeBuffer.Positions));
            run.Velocities.Request(solver.Buffer(FluidComputeBuffer.Velocities));
            run.Extras.Request(solver.Buffer(FluidComputeBuffer.Extras));
        }

        /// <summary>The read-back particles (the live count of the counters read back with them) into the fluid's buffers.</summary>
        static void CopyParticles(EntityManager m, Entity fluid, Run run)
        {
            FluidEntityArrays a = FluidSimulationSystem.Arrays(m, fluid);
            System.ReadOnlySpan<float4> positions = run.Positions.Take();
            System.ReadOnlySpan<float4> velocities = run.Velocities.Take();
            System.ReadOnlySpan<FluidComputeExtras> extras = run.Extras.Take();
            int count = math.min(run.Solver.LastKnownCount, math.min(math.min(positions.Length, velocities.Length), math.min(extras.Length, a.Positions.Length)));
            FluidComputeStep.Unpack(positions, velocities, extras, count, FluidSystemFrame.Particles(a));
        }

        /// <summary>Releases the GPU buffers of fluids that no longer exist.</summary>
        void ReleaseRemoved(EntityManager m)
        {
            m_Gone.Clear();
            foreach (var pair in m_Runs)
                if (!m.Exists(pair.Key))
                    m_Gone.Add(pair.Key);
            foreach (Entity e in m_Gone)
            {
                m_Sources.Remove(e);
                m_Runs[e].Dispose();
                m_Runs.Remove(e);
            }
        }

        protected override void OnDestroy()
        {
            foreach (var pair in m_Runs)
            {
                m_Sources.Remove(pair.Key);
                pair.Value.Dispose();
            }
            m_Runs.Clear();
        }
    }
}
