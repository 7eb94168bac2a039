using System;
using System.Diagnostics;
using SoftBodyDynamics.Benchmarks.Scenarios;

namespace SoftBodyDynamics.Runner
{
    /// <summary>Warm-up, then the median of repeated timed steps, and the bytes those steps allocated.</summary>
    static class ScenarioTimer
    {
        /// <summary>Warm-up lasts at least this long (JIT tiering settles) and at least 3 steps.</summary>
        public const double WarmupSeconds = 0.3;
        /// <summary>Warm-up goes on in rounds of at least this long (s) while the fastest step of a round still improves.</summary>
        const double k_RoundSeconds = 0.1;
        /// <summary>A round whose fastest step is within this fraction of the previous round's counts as settled.</summary>
        const double k_SettledFraction = 0.03;
        /// <summary>Warm-up never lasts longer than this (s) in the full run.</summary>
        public const double MaxWarmupSeconds = 3.0;
        /// <summary>Warm-up never lasts longer than this (s) outside the full run: a step of a second or more has tiered up by its end.</summary>
        public const double ShortMaxWarmupSeconds = 1.0;

        /// <summary>Setup, warm-up, the timed steps, then the evaluation: one scenario start to end.</summary>
        public static ScenarioResult Run(IScenario scenario, int repeats, double timedBudget = double.PositiveInfinity, double maxWarmup = MaxWarmupSeconds)
        {
            scenario.Setup();
            ScenarioResult r = Time(scenario, repeats, timedBudget, maxWarmup);
            r.Metrics = scenario.Evaluate();
            return r;
        }

        /// <summary>Fewest timed steps when a time budget cuts their number: the median of three.</summary>
        public const int MinRepeats = 3;

        /// <summary>
        /// Warm-up and the timed steps of a scenario whose Setup has run; the result has no metrics yet. With a finite
        /// <paramref name="timedBudget"/> (s), the timed steps are cut to what fits it at the warm-up's fastest step, but never
        /// below <see cref="MinRepeats"/>.
        /// </summary>
        public static ScenarioResult Time(IScenario scenario, int repeats, double timedBudget = double.PositiveInfinity, double maxWarmup = MaxWarmupSeconds)
        {
            double fastest = Warmup(scenario, maxWarmup);
            if (fastest > 0 && timedBudget < double.PositiveInfinity)
                repeats = Math.Max(Math.Min(repeats, MinRepeats), Math.Min(repeats, (int)(timedBudget / fastest)));

            var ms = new double[repeats];
            long allocated0 = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < repeats; i++)
            {
                long t0 = Stopwatch.GetTimestamp();
                scenario.Step();
                ms[i] = (Stopwatch.GetTimestamp() - t0) * 1000.0 / Stopwatch.Frequency;
            }
            long allocated = GC.GetAllocatedBytesForCurrentThread() - allocated0;
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
        /// Returns the fastest step seen (s).
        /// Runs steps in rounds of at least <see cref="k_RoundSeconds"/> until at least <see cref="WarmupSeconds"/>
        /// and 3 steps have passed and the fastest step of the last round is no more than
        /// <see cref="k_SettledFraction"/> faster than that of the round before: the JIT tiers a method up
        /// (tier 0, instrumented, optimised) some time after its first calls, so the first scenario that runs new
        /// code needs longer than the others. Stops after <paramref name="maxWarmup"/> seconds in any case.
        /// </summary>
        static double Warmup(IScenario scenario, double maxWarmup)
        {
            double fastest = double.PositiveInfinity;
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
                } while ((double)(Stopwatch.GetTimestamp() - roundStart) / Stopwatch.Frequency < k_RoundSeconds);
                double elapsed = total.Elapsed.TotalSeconds;
                fastest = Math.Min(fastest, best);
                bool settled = best >= (1.0 - k_SettledFraction) * previousBest;
                if (elapsed >= maxWarmup || (steps >= 3 && elapsed >= WarmupSeconds && settled))
                    return fastest;
                previousBest = best;
            }
        }
    }
}
