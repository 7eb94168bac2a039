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
    /// One fluid's frame on ECS data, shared by the packed-storage job chain and the entity-storage path: sizes the
    /// buffers on first use, runs this fluid's drains and taps (prewarm once), then the solver step (single-threaded for
    /// Entities storage, <see cref="FluidJobChain"/> for Packed), and logs what went out of bounds.
    /// </summary>
    static class FluidSystemFrame
    {
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
            FluidEntityArrays a, NativeArray<SoftBodyCollider> colliders, NativeArray<FluidTap> taps, NativeArray<Entity> tapEntities,
            NativeArray<FluidDrainVolume> drainVolumes, float dt)
        {
            int budget = math.max(1, settings.Budget);
            FluidScratch scratch = FluidEntityBuffers.Scratch(a.ScratchInts, a.ScratchFloats, a.ScratchVectors, budget, constants.Grid.CellCount);
            return DrainAndEmit(entity, constants, ref runtime.Status, ref runtime.Prewarmed, a.Taps, Particles(a), scratch, budget, colliders, taps,
                tapEntities, drainVolumes, dt);
        }

        /// <summary>
        /// The same on given particle arrays and tap states (the GPU path spawns into a staging area with its own status):
        /// <paramref name="prewarmed"/> false runs the taps' prewarm first and sets it.
        /// </summary>
        public static FluidFrameReport DrainAndEmit(Entity entity, in FluidConstants constants, ref FluidStatus status, ref bool prewarmed,
            DynamicBuffer<FluidTapRuntime> tapStates, FluidParticles particles, FluidScratch scratch, int budget,
            NativeArray<SoftBodyCollider> colliders, NativeArray<FluidTap> taps, NativeArray<Entity> tapEntities,
            NativeArray<FluidDrainVolume> drainVolumes, float dt)
        {
            var instances = new NativeArray<FluidTapInstance>(taps.Length, Allocator.Temp);
            var bursts = new NativeArray<FluidTapBurst>(taps.Length * FluidTap.MaxBursts, Allocator.Temp);
            var owners = new NativeArray<int>(taps.Length, Allocator.Temp);
            int tapCount = 0, burstCount = 0;
            for (int t = 0; t < taps.Length; t++)
            {
                if (taps[t].Fluid != entity)
                    continue;
                FluidTap tap = taps[t];
                int slot = FluidEntityBuffers.TapSlot(tapStates, tapEntities[t]);
                int count = math.clamp(tap.BurstCount, 0, FluidTap.MaxBursts);
                for (int b = 0; b < count; b++)
                    bursts[burstCount + b] = tap.Burst(b);
                instances[tapCount] = new FluidTapInstance { Settings = tap.Settings, State = tapStates[slot].State, BurstStart = burstCount, BurstCount = count };
                owners[tapCount++] = slot;
                burstCount += count;
            }
            var drains = new NativeArray<FluidDrain>(drainVolumes.Length, Allocator.Temp);
            int drainCount = 0;
            for (int d = 0; d < drainVolumes.Length; d++)
                if (drainVolumes[d].Fluid == entity)
                    drains[drainCount++] = drainVolumes[d].Drain;

            var tapSpan = instances.AsSpan().Slice(0, tapCount);
            var burstSpan = bursts.AsReadOnlySpan().Slice(0, burstCount);
            var drainSpan = drains.AsReadOnlySpan().Slice(0, drainCount);
            if (!prewarmed)
            {
                FluidFrame.Prewarm(constants, colliders.Reinterpret<ColliderShape>().AsReadOnlySpan(), drainSpan, tapSpan, burstSpan, budget, dt,
                    particles, scratch, ref status);
                prewarmed = true;
            }
            FluidFrameReport report = FluidFrame.DrainAndEmit(constants, drainSpan, tapSpan, burstSpan, budget, dt, particles, scratch, ref status);
            for (int t = 0; t < tapCount; t++)
            {
                FluidTapRuntime r = tapStates[owners[t]];
                r.State = instances[t].State;
                tapStates[owners[t]] = r;
            }
            instances.Dispose();
            bursts.Dispose();
            owners.Dispose();
            drains.Dispose();
            return report;
        }

        /// <summary>Stores the frame report and logs what went out of bounds, naming the fluid.</summary>
        public static void Close(Entity entity, ref FluidRuntime runtime, in FluidFrameReport report)
        {
            runtime.LastFrame = report;
            if (report.Step.Invalid > 0)
                Debug.LogWarning($"Fluid Entity({entity.Index}:{entity.Version}): the NaN guard removed {report.Step.Invalid} particle(s) with a non-finite position or velocity.");
            if (report.Step.SubstepsWanted > report.Step.Substeps)
                Debug.LogWarning($"Fluid Entity({entity.Index}:{entity.Version}): the CFL limit asked for {report.Step.SubstepsWanted} substeps, capped at {report.Step.Substeps}; lower the speed of sound or raise the substep cap.");
        }

        /// <summary>A whole frame single-threaded (drains, taps, <see cref="FluidSolver.Step"/>), for Entities storage.</summary>
        public static void Run(Entity entity, in FluidSettings settings, in FluidConstants constants, ref FluidRuntime runtime, FluidEntityArrays a,
            NativeArray<SoftBodyCollider> colliders, NativeArray<FluidTap> taps, NativeArray<Entity> tapEntities,
            NativeArray<FluidDrainVolume> drainVolumes, float dt)
        {
            FluidFrameReport report = DrainAndEmit(entity, settings, constants, ref runtime, a, colliders, taps, tapEntities, drainVolumes, dt);
            int budget = math.max(1, settings.Budget);
            FluidScratch scratch = FluidEntityBuffers.Scratch(a.ScratchInts, a.ScratchFloats, a.ScratchVectors, budget, constants.Grid.CellCount);
            report.Step = FluidSolver.Step(constants, colliders.Reinterpret<ColliderShape>().AsReadOnlySpan(), dt, Particles(a), scratch, ref runtime.Status);
            Close(entity, ref runtime, report);
        }
    }
}
