using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Tap spawns for a fluid whose particles live on the GPU: the CPU emitter (<see cref="FluidTapEmitter"/>: schedule,
    /// lattice, jitter, lifetimes, ids) places them in a staging area that starts empty every frame, and the caller
    /// appends them on the GPU (<see cref="FluidComputeStep.RecordEmit{T}"/>). The emitter's spacing check therefore
    /// sees only the spawns of the same frame, not the fluid's particles; the budget is the room the GPU had at the
    /// last read-back. Used by Unity's FluidComputeSystem and by the lavapipe tests.
    /// </summary>
    public static class FluidComputeEmission
    {
        /// <summary>
        /// Runs <paramref name="taps"/> for <paramref name="dt"/> into the first <paramref name="room"/> slots of
        /// <paramref name="staging"/> (its scratch <paramref name="stagingScratch"/> sized for the staging capacity); the
        /// fluid's <paramref name="status"/> advances its next id and spawn total. Returns the frame report (no step) and
        /// the number staged in <paramref name="spawned"/>.
        /// </summary>
        public static FluidFrameReport Stage(in FluidConstants c, Span<FluidTapInstance> taps, ReadOnlySpan<FluidTapBurst> bursts, int room,
            float dt, FluidParticles staging, FluidScratch stagingScratch, ref FluidStatus status, out int spawned)
        {
            int n = math.clamp(room, 0, staging.Capacity);
            // A view of n slots: at budget 0 (= capacity) the emitter has no room and holds back or drops, as at a full fluid.
            var view = new FluidParticles(staging.Positions.Slice(0, n), staging.Velocities.Slice(0, n), staging.Ages.Slice(0, n),
                staging.Lifetimes.Slice(0, n), staging.Attributes.Slice(0, n), staging.Ids.Slice(0, n));
            var staged = new FluidStatus { NextId = status.NextId };
            FluidFrameReport report = FluidFrame.DrainAndEmit(c, ReadOnlySpan<FluidDrain>.Empty, taps, bursts, 0, dt, view, stagingScratch, ref staged);
            spawned = staged.Count;
            status.NextId = staged.NextId;
            status.Spawned += spawned;
            return report;
        }
    }
}
