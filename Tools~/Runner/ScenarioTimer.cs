using System;
using System.Diagnostics;
using SoftBodyDynamics.Benchmarks.Scenarios;

namespace SoftBodyDynamics.Runner
{
    /// <summary>Warm-up, then the median of repeated timed steps.</summary>
    static class ScenarioTimer
    {
        /// <summary>Warm-up lasts at least this long (JIT tiering settles) and at least 3 steps.</summary>
        const double k_WarmupSeconds = 0.3;

        public static ScenarioResult Run(IScenario scenario, int repeats)
        {
            scenario.Setup();
            var sw = Stopwatch.StartNew();
            int warm = 0;
            while (warm < 3 || sw.Elapsed.TotalSeconds < k_WarmupSeconds)
            {
                scenario.Step();
                warm++;
            }

            var ms = new double[repeats];
            for (int i = 0; i < repeats; i++)
            {
                long t0 = Stopwatch.GetTimestamp();
                scenario.Step();
                ms[i] = (Stopwatch.GetTimestamp() - t0) * 1000.0 / Stopwatch.Frequency;
            }
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
                Metrics = scenario.Evaluate(),
            };
        }
    }
}
