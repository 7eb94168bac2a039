using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>What a body did with a hard case (<see cref="HardCaseRun"/>), best first.</summary>
    public enum HardCaseOutcome
    {
        /// <summary>No guard reset, finite, and back within <see cref="HardCaseRun.RecoveredDeviation"/> of its rest shape.</summary>
        Recovers = 0,
        /// <summary>The guard reset it once (the state it was given or its first step was absurd) and it then stayed finite at its rest shape.</summary>
        Reset = 1,
        /// <summary>Finite, at most one reset, within <see cref="HardCaseRun.DivergedDeviation"/> but not back at its rest shape.</summary>
        Bounded = 2,
        /// <summary>Reset more than once, or deformed beyond <see cref="HardCaseRun.DivergedDeviation"/>.</summary>
        Diverged = 3,
    }

    /// <summary>A hard case run for a while and its outcome.</summary>
    public readonly struct HardCaseResult
    {
        public readonly HardCaseOutcome Outcome;
        /// <summary>Shape deviation at the end over the body size (<see cref="ShapeDeviation"/>; dimensionless).</summary>
        public readonly double Deviation;
        /// <summary>Guard resets during the run.</summary>
        public readonly int Resets;

        public HardCaseResult(HardCaseOutcome outcome, double deviation, int resets)
        {
            Outcome = outcome;
            Deviation = deviation;
            Resets = resets;
        }
    }

    /// <summary>Runs a hard case (<see cref="HardCases"/>) on a body and classifies what it did.</summary>
    public static class HardCaseRun
    {
        /// <summary>Recovered: the shape deviation is at most this fraction of the body size.</summary>
        public const double RecoveredDeviation = 0.05;
        /// <summary>Diverged: the shape deviation exceeds this many body sizes (the bound of the stable-step runs too).</summary>
        public const double DivergedDeviation = 2.0;

        /// <summary>
        /// Places <paramref name="body"/>, writes the case, steps it for <paramref name="duration"/> (s) of steps of
        /// <see cref="HardCases.StepLength"/>(<paramref name="frame"/>) under <paramref name="gravity"/> without colliders, and classifies.
        /// </summary>
        public static HardCaseResult Run(IMethodBody body, HardCase c, float frame, float duration, float3 gravity)
        {
            body.Place();
            HardCases.Apply(body, c);
            float dt = HardCases.StepLength(c, frame);
            int steps = Math.Max(1, (int)Math.Ceiling(duration / dt - 1e-6));
            for (int k = 0; k < steps; k++)
                body.Step(dt, gravity, ReadOnlySpan<ColliderShape>.Empty);
            quaternion rotation = quaternion.identity;
            double deviation = ShapeDeviation.Max(body, ref rotation) / ShapeDeviation.Size(body);
            return new HardCaseResult(Classify(deviation, body.Resets), deviation, body.Resets);
        }

        /// <summary>The outcome of a run that ended <paramref name="deviation"/> body sizes from its rest shape after <paramref name="resets"/> guard resets.</summary>
        public static HardCaseOutcome Classify(double deviation, int resets)
        {
            if (resets > 1 || !(deviation <= DivergedDeviation))
                return HardCaseOutcome.Diverged;
            if (deviation <= RecoveredDeviation)
                return resets == 0 ? HardCaseOutcome.Recovers : HardCaseOutcome.Reset;
            return HardCaseOutcome.Bounded;
        }

        /// <summary>"recovers", "reset", "bounded", "diverged".</summary>
        public static string Label(HardCaseOutcome o) => o.ToString().ToLowerInvariant();
    }
}
