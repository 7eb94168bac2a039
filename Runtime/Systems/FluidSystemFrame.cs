using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics
{
    /// <summary>The buffers of one fluid entity, as the frame function takes them.</summary>
    struct FluidEntityArrays
    {
        public DynamicBuffer<FluidPosition> Positions;
        public DynamicBuffer<FluidVelocity> Velocities;
        public DynamicBuffer<FluidAge> Ages;
        public DynamicBuffer<FluidLifetime> Lifetimes;
        public DynamicBuffer<FluidAttribute> Attributes;
        public DynamicBuffer<FluidId> Ids;
        public DynamicBuffer<FluidScratchInt> ScratchInts;
        public DynamicBuffer<FluidScratchFloat> ScratchFloats;
        public DynamicBuffer<FluidScratchVector> ScratchVectors;
        public DynamicBuffer<FluidTapRuntime> Taps;
    }

    /// <summary>
    /// The step's collider world (copied: an Entities-storage fluid's structural changes would invalidate the buffer), the
    /// scene's taps and drains, gathered once per update of a fluid system.
    /// </summary>
    struct FluidFrameInputs : System.IDisposable
    {
        /// <summary>For the pass jobs too (TempJob).</summary>
        public NativeArray<ColliderShape> Colliders;
        public NativeArray<FluidTap> Taps;
        public NativeArray<Entity> TapEntities;
        public NativeArray<FluidDrainVolume> Drains;

        public static FluidFrameInputs Gather(DynamicBuffer<ColliderWorldShape> colliders, EntityQuery taps, EntityQuery drains) => new FluidFrameInputs
        {
            Colliders = colliders.Reinterpret<ColliderShape>().ToNativeArray(Allocator.TempJob),
            Taps = taps.ToComponentDataArray<FluidTap>(Allocator.Temp),
            TapEntities = taps.ToEntityArray(Allocator.Temp),
            Drains = drains.ToComponentDataArray<FluidDrainVolume>(Allocator.Temp),
        };

        public void Dispose()
        {
            Colliders.Dispose();
            Taps.Dispose();
            TapEntities.Dispose();
            Drains.Dispose();
        }
    }

    /// <summary>One fluid's taps for a frame: their settings, bursts and states (from the fluid's tap buffer), written back by <see cref="Store"/>.</summary>
    struct FluidTapSet : System.IDisposable
    {
        NativeArray<FluidTapInstance> m_Instances;
        NativeArray<FluidTapBurst> m_Bursts;
        NativeArray<int> m_Owners;
        int m_TapCount, m_BurstCount;

        public System.Span<FluidTapInstance> Instances => m_Instances.AsSpan().Slice(0, m_TapCount);
        public System.ReadOnlySpan<FluidTapBurst> Bursts => m_Bursts.AsReadOnlySpan().Slice(0, m_BurstCount);

        /// <summary>The taps of <paramref name="entity"/> among <paramref name="taps"/>, with their states from <paramref name="tapStates"/>.</summary>
        public static FluidTapSet Collect(Entity entity, DynamicBuffer<FluidTapRuntime> tapStates, NativeArray<FluidTap> taps, NativeArray<Entity> tapEntities)
        {
            var set = new FluidTapSet
            {
                m_Instances = new NativeArray<FluidTapInstance>(taps.Length, Allocator.Temp),
                m_Bursts = new NativeArray<FluidTapBurst>(taps.Length * FluidTap.MaxBursts, Allocator.Temp),
                m_Owners = new NativeArray<int>(taps.Length, Allocator.Temp),
            };
            for (int t = 0; t < taps.Length; t++)
            {
                if (taps[t].Fluid != entity)
                    continue;
                FluidTap tap = taps[t];
                int slot = FluidEntityBuffers.TapSlot(tapStates, tapEntities[t]);
                int count = math.clamp(tap.BurstCount, 0, FluidTap.MaxBursts);
                for (int b = 0; b < count; b++)
                    set.m_Bursts[set.m_BurstCount + b] = tap.Burst(b);
                set.m_Instances[set.m_TapCount] = new FluidTapInstance
                    { Settings = tap.Settings, State = tapStates[slot].State, BurstStart = set.m_BurstCount, BurstCount = count };
                set.m_Owners[set.m_TapCount++] = slot;
                set.m_BurstCount += count;
            }
            return set;
        }

        /// <summary>Writes the taps' advanced states back to the fluid's tap buffer.</summary>
        public void Store(DynamicBuffer<FluidTapRuntime> tapStates)
        {
            for (int t = 0; t < m_TapCount; t++)
            {
                FluidTapRuntime r = tapStates[m_Owners[t]];
                r.State = m_Instances[t].State;
                tapStates[m_Owners[t]] = r;
            }
        }

        public void Dispose()
        {
            m_Instances.Dispose();
            m_Bursts.Dispose();
            m_Owners.Dispose();
        }
    }

    /// <summary>
    /// One fluid's frame on ECS data, shared by the packed-storage job chain and the entity-storage path: sizes the
    /// buffers on first use, runs this fluid's drains and taps (prewarm once), then the solver step (single-threaded for
    /// Entities storage, <see cref="FluidJobChain"/> for Packed), and logs what went out of bounds.
    /// </summary>
    static class FluidSystemFrame
    {
        /// <summary><paramref name="settings"/> as the world steps the fluid: its gravity and minimum substeps when a <see cref="ParticleWorldSettings"/> exists.</summary>
        public static FluidSettings InWorld(FluidSettings settings, bool hasWorld, in ParticleWorldSettings world)
        {
            if (hasWorld)
                settings.Parameters = world.Apply(settings.Parameters);
            return settings;
        }

        /// <summary>Sizes the buffers to the budget if needed; false when they cannot hold it.</summary>
        public static bool Prepare(in FluidSettings settings, ref FluidRuntime runtime, FluidEntityArrays a, out FluidConstants constants)
        {
            constants = new FluidConstants(settings.Parameters);
            int budget = math.max(1, settings.Budget);
            if (!runtime.Initialized)
            {
                FluidEntityBuffers.Resize(budget, constants.Grid.CellCount, a.Positions, a.Velocities, a.Ages, a.Lifetimes, a.Attributes, a.Ids,
                    a.ScratchInts, a.ScratchFloats, a.ScratchVectors);
                runtime.Initialized = true;
            }
            return a.Positions.Length >= budget;
        }

        public static FluidParticles Particles(FluidEntityArrays a) =>
            FluidEntityBuffers.Particles(a.Positions, a.Velocities, a.Ages, a.Lifetimes, a.Attributes, a.Ids);

        /// <summary>
        /// The frame up to the solver step: this fluid's taps (state from the fluid's tap buffer) and drains; the taps'
        /// prewarm once (a whole single-threaded frame per prewarm frame); drains mark and taps spawn; tap states are
        /// written back. Returns the frame report without its step.
        /// </summary>
        public static FluidFrameReport DrainAndEmit(Entity entity, in FluidSettings settings, in FluidConstants constants, ref FluidRuntime runtime,
            FluidEntityArrays a, NativeArray<ColliderShape> colliders, NativeArray<FluidTap> taps, NativeArray<Entity> tapEntities,
            NativeArray<FluidDrainVolume> drainVolumes, float dt)
        {
            int budget = math.max(1, settings.Budget);
            FluidParticles particles = Particles(a);
            FluidScratch scratch = FluidEntityBuffers.Scratch(a.ScratchInts, a.ScratchFloats, a.ScratchVectors, budget, constants.Grid.CellCount);
            var tapSet = FluidTapSet.Collect(entity, a.Taps, taps, tapEntities);
            var drains = new NativeArray<FluidDrain>(drainVolumes.Length, Allocator.Temp);
            int drainCount = DrainsOf(entity, drainVolumes, drains);
            var drainSpan = drains.AsReadOnlySpan().Slice(0, drainCount);
            if (!runtime.Prewarmed)
            {
                FluidFrame.Prewarm(constants, colliders.AsReadOnlySpan(), drainSpan, tapSet.Instances, tapSet.Bursts,
                    budget, dt, particles, scratch, ref runtime.Status);
                runtime.Prewarmed = true;
            }
            FluidFrameReport report = FluidFrame.DrainAndEmit(constants, drainSpan, tapSet.Instances, tapSet.Bursts, budget, dt, particles, scratch,
                ref runtime.Status);
            tapSet.Store(a.Taps);
            tapSet.Dispose();
            drains.Dispose();
            return report;
        }

        /// <summary>Writes the drains of <paramref name="fluid"/> among <paramref name="volumes"/> to <paramref name="drains"/>; returns how many.</summary>
        public static int DrainsOf(Entity fluid, NativeArray<FluidDrainVolume> volumes, NativeArray<FluidDrain> drains)
        {
            int count = 0;
            for (int d = 0; d < volumes.Length; d++)
                if (volumes[d].Fluid == fluid)
                    drains[count++] = volumes[d].Drain;
            return count;
        }

        /// <summary>Stores the frame report and logs what went out of bounds, naming the fluid.</summary>
        public static void Close(Entity entity, ref FluidRuntime runtime, in FluidFrameReport report)
        {
            runtime.LastFrame = report;
            if (report.Step.Invalid > 0)
                Debug.LogWarning($"Fluid Entity({entity.Index}:{entity.Version}): the NaN guard removed {report.Step.Invalid} particle(s) with a non-finite position or velocity.");
            if (report.Step.SubstepsWanted > report.Step.Substeps)
                Debug.LogWarning($"Fluid Entity({entity.Index}:{entity.Version}): the substep limit (CFL; position-based also the depth rule) asked for {report.Step.SubstepsWanted} substeps, capped at {report.Step.Substeps}, so the fluid ran {report.Step.SimulatedTime:0.####} s of this frame (slow motion); lower the speed of sound (weakly compressible), raise the iterations (position-based) or raise the substep cap.");
        }

        /// <summary>A whole frame single-threaded (drains, taps, <see cref="FluidSolver.Step"/>), for Entities storage.</summary>
        public static void Run(Entity entity, in FluidSettings settings, in FluidConstants constants, ref FluidRuntime runtime, FluidEntityArrays a,
            NativeArray<ColliderShape> colliders, NativeArray<FluidTap> taps, NativeArray<Entity> tapEntities,
            NativeArray<FluidDrainVolume> drainVolumes, float dt)
        {
            FluidFrameReport report = DrainAndEmit(entity, settings, constants, ref runtime, a, colliders, taps, tapEntities, drainVolumes, dt);
            int budget = math.max(1, settings.Budget);
            FluidScratch scratch = FluidEntityBuffers.Scratch(a.ScratchInts, a.ScratchFloats, a.ScratchVectors, budget, constants.Grid.CellCount);
            report.Step = FluidSolver.Step(constants, colliders.AsReadOnlySpan(), dt, Particles(a), scratch, ref runtime.Status);
            Close(entity, ref runtime, report);
        }
    }
}
