using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// When a tap flows: cumulative functions of time (so a step emits Due(t₁) − Due(t₀), exactly, whatever the frame
    /// rate). The tap starts after <see cref="FluidTapSettings.StartDelay"/>, runs for <see cref="FluidTapSettings.Duration"/>
    /// (0 = forever), restarts every duration when looping, and when pulsing is open for the first
    /// DutyCycle·Period of every period.
    /// </summary>
    public static class FluidTapSchedule
    {
        /// <summary>Seconds the tap has been open (flowing) by time <paramref name="t"/> (s since creation).</summary>
        public static double OpenTime(in FluidTapSettings s, double t)
        {
            double local = t - s.StartDelay;
            if (!(local > 0))
                return 0;
            if (s.Duration > 0)
            {
                if (!s.Looping)
                    return PulseOpen(s, Math.Min(local, s.Duration));
                double loops = Math.Floor(local / s.Duration);
                return loops * PulseOpen(s, s.Duration) + PulseOpen(s, local - loops * s.Duration);
            }
            return PulseOpen(s, local);
        }

        static double PulseOpen(in FluidTapSettings s, double local)
        {
            if (!(s.PulsePeriod > 0))
                return local;
            double on = s.PulseDutyCycle * s.PulsePeriod;
            double periods = Math.Floor(local / s.PulsePeriod);
            return periods * on + Math.Min(local - periods * s.PulsePeriod, on);
        }

        /// <summary>Steady-flow particles due by time <paramref name="t"/> (fractional) for spacing <paramref name="spacing"/>.</summary>
        public static double SteadyDue(in FluidTapSettings s, float spacing, double t) => s.ParticlesPerSecond(spacing) * OpenTime(s, t);

        /// <summary>Burst particles due by time <paramref name="t"/>: every cycle whose time has come (bursts at or after the duration never fire).</summary>
        public static long BurstDue(in FluidTapSettings s, ReadOnlySpan<FluidTapBurst> bursts, double t)
        {
            double local = t - s.StartDelay;
            if (!(local >= 0) || bursts.Length == 0)
                return 0;
            if (s.Duration > 0)
            {
                if (!s.Looping)
                    return BurstsWithin(s, bursts, Math.Min(local, s.Duration));
                double loops = Math.Floor(local / s.Duration);
                return (long)loops * BurstsWithin(s, bursts, s.Duration) + BurstsWithin(s, bursts, local - loops * s.Duration);
            }
            return BurstsWithin(s, bursts, local);
        }

        /// <summary>Burst particles of cycles at times ≤ <paramref name="local"/> (and before the duration, if any).</summary>
        static long BurstsWithin(in FluidTapSettings s, ReadOnlySpan<FluidTapBurst> bursts, double local)
        {
            long due = 0;
            for (int b = 0; b < bursts.Length; b++)
            {
                FluidTapBurst burst = bursts[b];
                if (burst.Count <= 0 || burst.Cycles <= 0 || !(burst.Time >= 0) || local < burst.Time)
                    continue;
                long cycles = burst.Interval > 0 ? Math.Min(burst.Cycles, (long)Math.Floor((local - burst.Time) / burst.Interval) + 1) : 1;
                if (s.Duration > 0)
                {
                    // Only cycles that start before the end of the run (or of one loop) fire.
                    long inRun = burst.Interval > 0 ? (long)Math.Ceiling((s.Duration - burst.Time) / burst.Interval) : (burst.Time < s.Duration ? 1 : 0);
                    cycles = Math.Min(cycles, Math.Max(0, inRun));
                    if (local >= s.Duration && !(burst.Time < s.Duration))
                        cycles = 0;
                }
                due += cycles * burst.Count;
            }
            return due;
        }

        /// <summary>
        /// Alive particles the tap sustains in the steady state: flow × mean lifetime, bursts included (per loop, or per
        /// run when the tap stops). Infinity when particles live forever and the tap never stops; then only
        /// <see cref="FluidTapSettings.MaxAlive"/> or the budget bounds it. The inspector shows this beside the budget.
        /// </summary>
        public static double SteadyStateAlive(in FluidTapSettings s, ReadOnlySpan<FluidTapBurst> bursts, float spacing)
        {
            double rate = s.ParticlesPerSecond(spacing);
            double alive;
            if (s.Duration > 0)
            {
                // One run (or one loop) emits this many; a looping tap repeats it every duration.
                double perRun = rate * PulseOpen(s, s.Duration) + BurstsWithin(s, bursts, s.Duration);
                if (s.Looping)
                    alive = s.Lifetime > 0 ? perRun / s.Duration * s.Lifetime : (perRun > 0 ? double.PositiveInfinity : 0);
                else
                    alive = s.Lifetime > 0 ? Math.Min(perRun, perRun / s.Duration * s.Lifetime) : perRun;
            }
            else
            {
                double meanRate = rate * (s.PulsePeriod > 0 ? s.PulseDutyCycle : 1.0);
                long once = BurstsWithin(s, bursts, double.MaxValue);
                // One-off bursts expire in a steady flow; a tap of bursts only holds at most all of them at once.
                if (meanRate > 0)
                    alive = s.Lifetime > 0 ? meanRate * s.Lifetime : double.PositiveInfinity;
                else
                    alive = once;
            }
            return s.MaxAlive > 0 ? Math.Min(alive, s.MaxAlive) : alive;
        }
    }
}
