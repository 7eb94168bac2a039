using System;
using System.Diagnostics;
using SoftBodyDynamics.Benchmarks.Scenarios;

namespace SoftBodyDynamics.Runner
{
    /// <summary>
    /// How a scenario is warmed up and how many steps are timed. Warm-up runs steps in rounds of at least
    /// <see cref="RoundSeconds"/> until <see cref="WarmupSeconds"/> and <see cref="MinWarmupSteps"/> have passed and the
    /// fastest step of a round is within 3 % of the round before's, or until <see cref="MaxWarmupSeconds"/>; with
    /// <see cref="ShortWarmups"/>, a scenario whose step is a whole run (<see cref="IScenarioShortWarmup"/>) is warmed up by a
    /// few frames of that run instead. The timed steps stop once they have taken <see cref="TimedBudget"/>, but never before
    /// <see cref="MinRepeats"/>.
    /// </summary>
    readonly struct TimingRule
    {
        public readonly double WarmupSeconds, RoundSeconds, MaxWarmupSeconds, TimedBudget;
        public readonly int MinWarmupSteps, MinRepeats;
        public readonly bool ShortWarmups;

        public TimingRule(double warmupSeconds, int minWarmupSteps, double roundSeconds, double maxWarmupSeconds, double timedBudget, int minRepeats,
            bool shortWarmups)
        {
            ShortWarmups = shortWarmups;
            WarmupSeconds = warmupSeconds;
            MinWarmupSteps = minWarmupSteps;
            RoundSeconds = roundSeconds;
            MaxWarmupSeconds = maxWarmupSeconds;
            TimedBudget = timedBudget;
            MinRepeats = minRepeats;
        }

        /// <summary>The full run: long warm-ups and every repeat asked for, whatever they cost.</summary>
        public static readonly TimingRule Full = new TimingRule(0.3, 3, 0.1, 3.0, double.PositiveInfinity, 1, false);

        /// <summary>
        /// The default and quick runs. The runner compiles every method optimised at its first call (no tiers), so a warm-up
        /// only needs the first calls and warm caches: two steps and 20 ms in rounds of 10 ms, settled, at most 0.5 s (a few frames
        /// for a step that is a whole run); then timed steps until they have taken 0.5 s, at least one.
        /// </summary>
        public static readonly TimingRule Short = new TimingRule(0.02, 2, 0.01, 0.5, 0.5, 1, true);
    }

    /// <summary>Warm-up, then the median of repeated timed steps, and the bytes those steps allocated.</summary>
    static class ScenarioTimer
    {
        /// <summary>A round whose fastest step is within this fraction of the previous round's counts as settled.</summary>
        const double k_SettledFraction = 0.03;

        /// <summary>Setup, warm-up, the timed steps, then the evaluation: one scenario start to end.</summary>
        public static ScenarioResult Run(IScenario scenario, int repeats, in TimingRule rule)
        {
            scenario.Setup();
            ScenarioResult r = Time(scenario, repeats, rule);
            r.Metrics = scenario.Evaluate();
            return r;
        }

        /// <summary>Warm-up and the timed steps (at most <paramref name="repeats"/>) of a scenario whose Setup has run; the result has no metrics yet.</summary>
        public static ScenarioResult Time(IScenario scenario, int repeats, in TimingRule rule)
        {
            if (rule.ShortWarmups && scenario is IScenarioShortWarmup shortWarmup)
                shortWarmup.WarmupFrames();
            else
                Warmup(scenario, rule);

            var ms = new double[repeats];
            int minRepeats = Math.Min(repeats, rule.MinRepeats);
            double budgetMs = rule.TimedBudget * 1000.0, spentMs = 0;
            long allocated0 = GC.GetAllocatedBytesForCurrentThread();
            int done = 0;
            while (done < repeats && (done < minRepeats || spentMs < budgetMs))
            {
                long t0 = Stopwatch.GetTimestamp();
                scenario.Step();
                ms[done] = (Stopwatch.GetTimestamp() - t0) * 1000.0 / Stopwatch.Frequency;
                spentMs += ms[done++];
            }
            long allocated = GC.GetAllocatedBytesForCurrentThread() - allocated0;
            repeats = done;
            Array.Resize(ref ms, done);
            Array.Sort(ms);
            double median = repeats % 2 == 1 ? ms[repeats / 2] : 0.5 * (ms[repeats / 2 - 1] + ms[repeats / 2]);
            return new ScenarioResult
            {
                Name = scenario.Name,
                Method = scenario.Method,
                Size = scenario.Size,
                SizeUnit = scenario.SizeUnit,
                ItemsPerStep = scenario.ItemsPerStep,
                Repeats = repeats,
                MedianMs = median,
                MinMs = ms[0],
                MaxMs = ms[repeats - 1],
                AllocatedBytesPerStep = (double)allocated / repeats,
            };
        }

        /// <summary>
        /// Runs steps in rounds until the rule's warm-up has passed and the fastest step of the last round is no more than
        /// <see cref="k_SettledFraction"/> faster than that of the round before.
        /// </summary>
        static void Warmup(IScenario scenario, in TimingRule rule)
        {
            var total = Stopwatch.StartNew();
            int steps = 0;
            double previousBest = double.PositiveInfinity;
            while (true)
            {
                double best = double.PositiveInfinity;
                long roundStart = Stopwatch.GetTimestamp();
                do
                {
                    long t0 = Stopwatch.GetTimestamp();
                    scenario.Step();
                    long t1 = Stopwatch.GetTimestamp();
                    best = Math.Min(best, (double)(t1 - t0) / Stopwatch.Frequency);
                    steps++;
                } while ((double)(Stopwatch.GetTimestamp() - roundStart) / Stopwatch.Frequency < rule.RoundSeconds);
                double elapsed = total.Elapsed.TotalSeconds;
                bool settled = best >= (1.0 - k_SettledFraction) * previousBest;
                if (elapsed >= rule.MaxWarmupSeconds || (steps >= rule.MinWarmupSteps && elapsed >= rule.WarmupSeconds && settled))
                    return;
                previousBest = best;
            }
        }
    }
}
