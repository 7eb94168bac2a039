using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>A tap of a frame: its settings, its bursts (a range of a shared burst list) and its state.</summary>
    public struct FluidTapInstance
    {
        public FluidTapSettings Settings;
        public FluidTapState State;
        /// <summary>First of this tap's bursts in the shared burst list.</summary>
        public int BurstStart;
        /// <summary>Number of this tap's bursts.</summary>
        public int BurstCount;
    }

    /// <summary>What one <see cref="FluidFrame.Advance"/> did.</summary>
    public struct FluidFrameReport
    {
        public FluidStepReport Step;
        /// <summary>Particles the drains marked this frame (removed and counted by the step).</summary>
        public int Drained;
        /// <summary>Particles the taps placed this frame.</summary>
        public int Spawned;
        /// <summary>Particles due but held back by all taps.</summary>
        public int HeldBack;
        /// <summary>Particles shed by blocked taps.</summary>
        public int Dropped;
        /// <summary>A tap hit the fluid's budget this frame.</summary>
        public bool OverBudget;
    }

    /// <summary>
    /// One frame of a fluid with its taps and drains, in the order the ECS system runs it: drains mark, taps spawn
    /// (each tap sees the particles of the taps before it), then the solver step removes the marked particles and
    /// advances the rest. The accounting identity holds after every frame:
    /// Count = Spawned − Killed − Expired − Invalid (<see cref="FluidStatus"/>).
    /// </summary>
    public static class FluidFrame
    {
        public static FluidFrameReport Advance(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, ReadOnlySpan<FluidDrain> drains,
            Span<FluidTapInstance> taps, ReadOnlySpan<FluidTapBurst> bursts, int budget, float dt, FluidParticles p, FluidScratch s,
            ref FluidStatus status)
        {
            FluidFrameReport report = DrainAndEmit(c, drains, taps, bursts, budget, dt, p, s, ref status);
            report.Step = FluidSolver.Step(c, colliders, dt, p, s, ref status);
            return report;
        }

        /// <summary>The part of <see cref="Advance"/> before the solver step: drains mark, taps spawn (report without <see cref="FluidFrameReport.Step"/>).</summary>
        public static FluidFrameReport DrainAndEmit(in FluidConstants c, ReadOnlySpan<FluidDrain> drains, Span<FluidTapInstance> taps,
            ReadOnlySpan<FluidTapBurst> bursts, int budget, float dt, FluidParticles p, FluidScratch s, ref FluidStatus status)
        {
            var report = new FluidFrameReport();
            report.Drained = FluidDrain.Apply(drains, p, math.min(status.Count, p.Capacity));
            for (int t = 0; t < taps.Length; t++)
            {
                ref FluidTapInstance tap = ref taps[t];
                ReadOnlySpan<FluidTapBurst> own = tap.BurstCount > 0 ? bursts.Slice(tap.BurstStart, tap.BurstCount) : default;
                FluidEmitReport e = FluidTapEmitter.Emit(tap.Settings, own, ref tap.State, dt, c, budget, p, s, ref status);
                report.Spawned += e.Spawned;
                report.HeldBack += e.HeldBack;
                report.Dropped += e.Dropped;
                report.OverBudget |= e.OverBudget;
            }
            return report;
        }

        /// <summary>
        /// Prewarm: runs <see cref="Advance"/> in frames of <paramref name="frame"/> seconds for the longest
        /// <see cref="FluidTapSettings.Prewarm"/> of the taps, so the scene starts with its flow established. Returns the frames run.
        /// </summary>
        public static int Prewarm(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, ReadOnlySpan<FluidDrain> drains,
            Span<FluidTapInstance> taps, ReadOnlySpan<FluidTapBurst> bursts, int budget, float frame, FluidParticles p, FluidScratch s,
            ref FluidStatus status)
        {
            float prewarm = 0f;
            for (int t = 0; t < taps.Length; t++)
                prewarm = math.max(prewarm, taps[t].Settings.Sanitized().Prewarm);
            if (!(frame > 0f) || prewarm <= 0f)
                return 0;
            int frames = (int)math.ceil(prewarm / frame);
            for (int f = 0; f < frames; f++)
                Advance(c, colliders, drains, taps, bursts, budget, frame, p, s, ref status);
            return frames;
        }
    }
}
