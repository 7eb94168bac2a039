using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using SoftBodyDynamics.Benchmarks.Scenarios;

namespace SoftBodyDynamics.Runner
{
    /// <summary>
    /// Headless scenario runner: runs every suite of <see cref="ScenarioCatalog"/>, prints a table
    /// (scenario, method, size, ms per step, ns per item, items per second, error metrics) and writes a Markdown
    /// report with PNG figures.
    /// Usage: SoftBodyDynamics.Runner [--out DIR] [--quick] [--repeats N] [--filter TEXT] [--method TEXT]
    /// </summary>
    static class Program
    {
        static int Main(string[] args)
        {
            CultureInfo.DefaultThreadCurrentCulture = CultureInfo.InvariantCulture;
            CultureInfo.CurrentCulture = CultureInfo.InvariantCulture;
            var options = RunOptions.Parse(args);
            if (options == null)
            {
                Console.Error.WriteLine("usage: SoftBodyDynamics.Runner [--out DIR] [--quick] [--repeats N] [--filter TEXT] [--method TEXT]");
                return 2;
            }

            Directory.CreateDirectory(options.OutDir);
            var results = new List<SuiteResult>();
            foreach (IScenarioSuite suite in ScenarioCatalog.Suites)
            {
                if (options.Filter != null && suite.Name.IndexOf(options.Filter, StringComparison.OrdinalIgnoreCase) < 0)
                    continue;
                var suiteResult = new SuiteResult(suite);
                Console.WriteLine();
                Console.WriteLine($"== {suite.Name}");
                var scenarios = new List<IScenario>(suite.Scenarios(options.Quick));
                // A suite left with no scenario by --method is skipped (a summary-only suite, which has none, still runs).
                if (options.Method != null && scenarios.Count > 0)
                {
                    scenarios.RemoveAll(sc => sc.Method.IndexOf(options.Method, StringComparison.OrdinalIgnoreCase) < 0);
                    if (scenarios.Count == 0)
                        continue;
                }
                var table = new TablePrinter(Console.Out, scenarios);
                table.PrintHeader();
                foreach (IScenario scenario in scenarios)
                {
                    int repeats = scenario is IScenarioRepeatCap cap ? Math.Max(1, Math.Min(options.Repeats, cap.MaxRepeats)) : options.Repeats;
                    ScenarioResult r = ScenarioTimer.Run(scenario, repeats);
                    suiteResult.Rows.Add(r);
                    table.PrintRow(r);
                }
                if (suite is IScenarioSuiteSummary summary)
                {
                    var outcomes = suiteResult.Rows.ConvertAll(r => new ScenarioOutcome(r.Method, r.NsPerItem, r.Metrics, r.Size, r.ItemsPerStep));
                    suiteResult.Summary = summary.Summary(outcomes, options.Quick);
                    Console.WriteLine();
                    Console.WriteLine(suiteResult.Summary.TrimEnd());
                }
                results.Add(suiteResult);
            }

            string reportPath = ReportWriter.Write(options, results);
            Console.WriteLine();
            Console.WriteLine($"Report written to {reportPath}");
            return 0;
        }
    }

    sealed class RunOptions
    {
        public string OutDir = Path.Combine("Reports~", "latest");
        public bool Quick;
        public int Repeats = 15;
        public string Filter;
        /// <summary>Only scenarios whose method text contains this (case-insensitive), e.g. "Neo-Hookean implicit"; null = all.</summary>
        public string Method;

        public static RunOptions Parse(string[] args)
        {
            var o = new RunOptions();
            for (int i = 0; i < args.Length; i++)
            {
                switch (args[i])
                {
                    case "--out" when i + 1 < args.Length: o.OutDir = args[++i]; break;
                    case "--quick": o.Quick = true; break;
                    case "--repeats" when i + 1 < args.Length && int.TryParse(args[i + 1], out int n) && n > 0:
                        o.Repeats = n; i++; break;
                    case "--filter" when i + 1 < args.Length: o.Filter = args[++i]; break;
                    case "--method" when i + 1 < args.Length: o.Method = args[++i]; break;
                    default: return null;
                }
            }
            return o;
        }
    }

    sealed class SuiteResult
    {
        public readonly IScenarioSuite Suite;
        public readonly List<ScenarioResult> Rows = new List<ScenarioResult>();
        /// <summary>Markdown the suite wrote about all its rows (<see cref="IScenarioSuiteSummary"/>), or null.</summary>
        public string Summary;
        public SuiteResult(IScenarioSuite suite) { Suite = suite; }
    }

    sealed class ScenarioResult
    {
        public string Name, Method, SizeUnit;
        public int Size;
        public long ItemsPerStep;
        public int Repeats;
        public double MedianMs, MinMs, MaxMs;
        /// <summary>Managed bytes allocated per timed Step (should be 0).</summary>
        public double AllocatedBytesPerStep;
        public IReadOnlyList<Metric> Metrics;
        public double NsPerItem => MedianMs * 1e6 / Math.Max(1, ItemsPerStep);
        public double ItemsPerSecond => ItemsPerStep / (MedianMs * 1e-3);
        /// <summary>The named metric, or NaN when this scenario does not report it.</summary>
        public double MetricValue(string name)
        {
            foreach (Metric m in Metrics)
                if (m.Name == name) return m.Value;
            return double.NaN;
        }
    }
}
