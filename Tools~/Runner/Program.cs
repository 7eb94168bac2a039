using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Collections.Concurrent;
using System.Threading.Tasks;
using SoftBodyDynamics.Benchmarks.Scenarios;

namespace SoftBodyDynamics.Runner
{
    /// <summary>
    /// Headless scenario runner, the README's main job: runs the suites of <see cref="ScenarioCatalog"/> and the report parts
    /// of <see cref="ReportParts"/>, prints one table per suite and a progress line per scenario, and rewrites report.md
    /// (summary first), results.csv and timings.csv after every scenario. See <see cref="RunOptions.Usage"/>.
    /// </summary>
    static class Program
    {
        static int Main(string[] args)
        {
            CultureInfo.DefaultThreadCurrentCulture = CultureInfo.InvariantCulture;
            CultureInfo.CurrentCulture = CultureInfo.InvariantCulture;
            RunOptions options = RunOptions.Parse(args, out string error);
            if (options == null)
            {
                Console.Error.WriteLine(error);
                Console.Error.WriteLine(RunOptions.Usage);
                return 2;
            }
            if (options.Help)
            {
                Console.WriteLine(RunOptions.Usage);
                return 0;
            }

            return Run(options, ScenarioCatalog.Suites, ReportParts.All, Console.Out, Console.Error);
        }

        /// <summary>
        /// Runs the plan of <paramref name="suites"/> and <paramref name="parts"/> that <paramref name="options"/> select: tables to
        /// <paramref name="output"/>, progress lines to <paramref name="progress"/>; returns the exit code.
        /// </summary>
        public static int Run(RunOptions options, IEnumerable<IScenarioSuite> suites, IEnumerable<ReportPart> parts, TextWriter output, TextWriter progress)
        {
            string dir = Path.GetFullPath(options.OutDir);
            Directory.CreateDirectory(dir);
            RunPlan plan = RunPlan.Build(options, suites, parts);
            var timings = RunTimings.Load(dir, Path.Combine(Path.GetFullPath(options.Root), "Tools~", "Runner", ReferenceTimings));
            var estimate = new ProgressEstimate(timings, plan.Keys, plan.HasPreparation ? 0 : -1);
            var clock = RunClock.Start();
            var report = new Report(options, dir, plan.Count);
            progress.WriteLine($"Main job ({RunOptions.ScopeName(options.Scope)} run): {plan.Suites.Count} suites, {plan.Count} steps; report in {dir}");

            int index = 0;
            string root = Path.GetFullPath(options.Root);
            List<IScenarioSuiteStoredReference> storable = plan.Preparations.OfType<IScenarioSuiteStoredReference>().ToList();
            string storedPath = Path.Combine(root, "Tools~", "Runner", ReferenceStore.FileName);
            string sourceHash = storable.Count > 0 ? ReferenceStore.SourceHash(root) : null;
            bool computeReferences = storable.Count > 0 && options.Scope == RunScope.Full;
            if (storable.Count > 0 && options.Scope != RunScope.Full)
            {
                List<string> used = ReferenceStore.Use(storedPath, sourceHash, storable, out string why, out string storedBy);
                computeReferences = used.Count < storable.Count;
                report.ReferenceNote = used.Count > 0
                    ? $"the float64 reference values of {string.Join(", ", used)} are the stored ones (`Tools~/Runner/{ReferenceStore.FileName}`, " +
                      $"computed by a {storedBy} from the same reference sources, SHA-256 {sourceHash.Substring(0, 12)}…); " +
                      "`--full` computes them again and compares"
                    : $"computed by this run ({why})";
                if (computeReferences)
                    progress.WriteLine($"      references: {why}, so this run computes them and writes {ReferenceStore.FileName} to its report folder (to store in Tools~/Runner)");
            }
            if (plan.HasPreparation)
            {
                // Everything untimed that the timed steps need, at once on the worker threads: the suites' shared references,
                // then the setup of every scenario of the independent suites, each handed out longest first.
                // A setup's cost is its own time in the previous (or reference) run, under its scenario's key + " | setup".
                var work = new List<(Action Run, double Cost, string Key)>();
                foreach (IScenarioSuite s in plan.Preparations)
                    work.Add((((IScenarioSuitePreparation)s).Prepare, double.PositiveInfinity, null));
                int setups = 0;
                for (int k = 0, key = 1; k < plan.Suites.Count; k++)
                {
                    PlannedSuite ps = plan.Suites[k];
                    bool concurrent = SetUpConcurrently(ps, options);
                    foreach (PlannedScenario p in ps.Scenarios)
                    {
                        if (concurrent)
                        {
                            IScenario sc = p.Scenario;
                            string setupKey = SetupKey(plan.Keys[key]);
                            work.Add((sc.Setup, timings.Previous(setupKey) ?? 0.0, setupKey));
                            setups++;
                        }
                        key++;
                    }
                }
                progress.WriteLine(Progress(index, plan.Count, $"preparing: the references of {plan.Preparations.Count} scenes and the setup of {setups} scenarios, on {options.Threads} threads", clock, estimate));
                long t0 = Stopwatch.GetTimestamp();
                int done = 0, tenth = Math.Max(1, work.Count / 10);
                var own = new double[work.Count];
                ForEachLongestFirst(work.Count, k => work[k].Cost, options.Threads, k =>
                {
                    long start = Stopwatch.GetTimestamp();
                    work[k].Run();
                    own[k] = Seconds(start);
                    int d = System.Threading.Interlocked.Increment(ref done);
                    if (d % tenth == 0 || d == work.Count)
                        lock (progress)
                            progress.WriteLine($"      preparing: {d} of {work.Count} done — {ProgressEstimate.Clock(clock.Elapsed)} elapsed");
                });
                double seconds = Seconds(t0);
                for (int k = 0; k < work.Count; k++)
                    if (work[k].Key != null)
                        timings.Record(work[k].Key, own[k]);
                timings.Record(plan.Keys[index], seconds);
                estimate.Finished(index, seconds);
                index++;
                if (computeReferences)
                    report.ReferenceNote = WriteReferences(dir, storedPath, sourceHash, storable, options.Scope);
                Collect();
            }
            foreach (PlannedSuite planned in plan.Suites)
            {
                var suiteResult = new SuiteResult(planned.Suite);
                report.Suites.Add(suiteResult);
                output.WriteLine();
                output.WriteLine($"== {planned.Suite.Name}");
                var table = new TablePrinter(output, planned.Scenarios.Select(p => p.Scenario));
                if (planned.Scenarios.Count > 0)
                    table.PrintHeader();
                if (SetUpConcurrently(planned, options))
                    index = RunConcurrently(planned, suiteResult, options, plan, index, table, timings, estimate, clock, report, progress);
                else
                    foreach (PlannedScenario p in planned.Scenarios)
                    {
                        progress.WriteLine(Progress(index, plan.Count, What(planned, p), clock, estimate));
                        long t0 = Stopwatch.GetTimestamp();
                        ScenarioResult r = ScenarioTimer.Run(p.Scenario, Repeats(p.Scenario, options), options.Timing);
                        double seconds = Seconds(t0);
                        suiteResult.Rows.Add(r);
                        table.PrintRow(r);
                        timings.Record(plan.Keys[index], seconds);
                        estimate.Finished(index, seconds);
                        index++;
                        report.Finished = index;
                        report.Write(timings);
                    }
                // The suite's scenarios are done with: their bodies and buffers go before the next suite's timed steps.
                foreach (PlannedScenario p in planned.Scenarios)
                    p.Scenario = null;
                Collect();
                suiteResult.Finish(options.Scope, dir);
                if (!string.IsNullOrEmpty(suiteResult.Summary))
                {
                    output.WriteLine();
                    output.WriteLine(suiteResult.Summary.TrimEnd());
                }
                report.Write(timings);
            }

            foreach (ReportPart part in plan.Parts)
            {
                progress.WriteLine(Progress(index, plan.Count, part.Title, clock, estimate));
                output.WriteLine();
                output.WriteLine($"== {part.Title}");
                long t0 = Stopwatch.GetTimestamp();
                PartResult result = part.Run(options, dir);
                double seconds = Seconds(t0);
                report.Parts.Add(result);
                timings.Record(plan.Keys[index], seconds);
                estimate.Finished(index, seconds);
                index++;
                report.Finished = index;
                report.Write(timings);
            }

            report.Complete = true;
            string path = report.Write(timings);
            output.WriteLine();
            output.WriteLine($"Report written to {path}");
            progress.WriteLine($"Main job done in {ProgressEstimate.Clock(clock.Elapsed)} ({RunOptions.ScopeName(options.Scope)} run).");
            return report.Parts.Any(p => !p.Succeeded) ? 1 : 0;
        }

        /// <summary>
        /// Writes the references a run computed (a full run always computes them) to its report folder and says how they
        /// compare with the stored ones.
        /// </summary>
        static string WriteReferences(string dir, string storedPath, string sourceHash, List<IScenarioSuiteStoredReference> storable, RunScope scope)
        {
            string written = Path.Combine(dir, ReferenceStore.FileName);
            ReferenceStore.Write(written, sourceHash, storable, $"{RunOptions.ScopeName(scope)} run, {DateTime.UtcNow:yyyy-MM-dd}");
            List<string> differ = ReferenceStore.Differences(storedPath, written);
            string stored = $"`Tools~/Runner/{ReferenceStore.FileName}`";
            string tail = differ == null ? $"none are stored for these sources: copy it to {stored} for the default run to use"
                : differ.Count == 0 ? $"they equal the stored values in {stored}"
                : $"they differ from the stored values of {string.Join(", ", differ)}: copy it to {stored}";
            return $"computed by this run and written to {ReferenceStore.FileName}; {tail}";
        }

        /// <summary>Timings of a reference run on the 2-core machine (Tools~/Runner), for the estimate of a first run.</summary>
        public const string ReferenceTimings = "reference-timings.csv";

        /// <summary>The timings key of a scenario's setup when it runs in the preparation step (not a step of the plan: for scheduling only).</summary>
        static string SetupKey(string scenarioKey) => scenarioKey + " | setup";

        static int Repeats(IScenario scenario, RunOptions options) =>
            scenario is IScenarioRepeatCap cap ? Math.Max(1, Math.Min(options.Repeats, cap.MaxRepeats)) : options.Repeats;

        /// <summary>True for a suite whose scenarios were set up in the preparation step and are evaluated on worker threads.</summary>
        internal static bool SetUpConcurrently(PlannedSuite planned, RunOptions options) =>
            planned.Suite is IScenarioSuiteIndependent && options.Threads > 1 && planned.Scenarios.Count > 1;

        /// <summary>
        /// A suite of independent scenarios, set up in the preparation step: each scenario's warm-up and timed steps one at a
        /// time with nothing else running, then every evaluation on <see cref="RunOptions.Threads"/> worker threads. Each
        /// scenario's time in timings.csv is its own timing plus its share of the evaluation. Returns the next step index.
        /// </summary>
        static int RunConcurrently(PlannedSuite planned, SuiteResult suiteResult, RunOptions options, RunPlan plan, int index, TablePrinter table,
            RunTimings timings, ProgressEstimate estimate, RunClock clock, Report report, TextWriter progress)
        {
            int n = planned.Scenarios.Count;
            var results = new ScenarioResult[n];
            var own = new double[n];
            for (int k = 0; k < n; k++)
            {
                PlannedScenario p = planned.Scenarios[k];
                progress.WriteLine(Progress(index + k, plan.Count, What(planned, p), clock, estimate));
                long t1 = Stopwatch.GetTimestamp();
                results[k] = ScenarioTimer.Time(p.Scenario, Repeats(p.Scenario, options), options.Timing);
                own[k] = Seconds(t1);
            }
            progress.WriteLine($"      {planned.Suite.Name}: evaluating {n} scenarios on {options.Threads} threads — {ProgressEstimate.Clock(clock.Elapsed)} elapsed");
            long t2 = Stopwatch.GetTimestamp();
            // An evaluation runs the scene's frames on the method's step, so the timed step is its cost's measure.
            ForEachLongestFirst(n, k => results[k].MedianMs, options.Threads, k => results[k].Metrics = planned.Scenarios[k].Scenario.Evaluate());
            double shared = Seconds(t2);
            for (int k = 0; k < n; k++)
            {
                suiteResult.Rows.Add(results[k]);
                table.PrintRow(results[k]);
                double seconds = own[k] + shared / n;
                timings.Record(plan.Keys[index], seconds);
                estimate.Finished(index, seconds);
                index++;
            }
            report.Finished = index;
            report.Write(timings);
            return index;
        }

        /// <summary>
        /// Runs <paramref name="body"/> for 0…n−1 on <paramref name="threads"/> threads, handing out the costliest item first
        /// (by <paramref name="cost"/>) and one item at a time, so that no thread is left with a long item at the end.
        /// </summary>
        public static void ForEachLongestFirst(int n, Func<int, double> cost, int threads, Action<int> body)
        {
            int[] order = Enumerable.Range(0, n).OrderByDescending(cost).ThenBy(k => k).ToArray();
            Parallel.ForEach(Partitioner.Create(order, EnumerablePartitionerOptions.NoBuffering),
                new ParallelOptions { MaxDegreeOfParallelism = threads }, k => body(k));
        }

        /// <summary>A full, blocking collection between suites, so that no garbage of one suite is collected during the next one's timed steps.</summary>
        static void Collect()
        {
            GC.Collect(GC.MaxGeneration, GCCollectionMode.Forced, blocking: true, compacting: true);
            GC.WaitForPendingFinalizers();
        }

        static double Seconds(long t0) => (Stopwatch.GetTimestamp() - t0) / (double)Stopwatch.Frequency;

        /// <summary>"suite: method (size unit)", a scenario in a progress line.</summary>
        static string What(PlannedSuite planned, PlannedScenario p) => $"{planned.Suite.Name}: {p.Scenario.Method} ({p.Size} {p.Scenario.SizeUnit})";

        /// <summary>"[i/N] what — m:ss elapsed, about m:ss left".</summary>
        public static string Progress(int index, int count, string what, RunClock clock, ProgressEstimate estimate)
        {
            double? left = estimate.SecondsLeft(index, out int unknown);
            string tail = !left.HasValue ? "time left known after the first step"
                : unknown == 0 ? $"about {ProgressEstimate.Clock(left.Value)} left"
                : $"about {ProgressEstimate.Clock(left.Value)} left for the steps timed before, and {unknown} never timed";
            return $"[{index + 1}/{count}] {what} — {ProgressEstimate.Clock(clock.Elapsed)} elapsed, {tail}";
        }
    }

    /// <summary>Elapsed time of the main job: from the moment run.sh started (SBD_RUN_STARTED, Unix seconds) where given, so the build counts.</summary>
    sealed class RunClock
    {
        readonly DateTimeOffset m_Start;
        RunClock(DateTimeOffset start) { m_Start = start; }

        public static RunClock Start()
        {
            string started = Environment.GetEnvironmentVariable("SBD_RUN_STARTED");
            if (long.TryParse(started, NumberStyles.Integer, CultureInfo.InvariantCulture, out long unix) && unix > 0)
            {
                var s = DateTimeOffset.FromUnixTimeSeconds(unix);
                if (s <= DateTimeOffset.UtcNow)
                    return new RunClock(s);
            }
            return new RunClock(DateTimeOffset.UtcNow);
        }

        public double Elapsed => (DateTimeOffset.UtcNow - m_Start).TotalSeconds;
    }

    /// <summary>A scenario of the plan, with its size as known before Setup (the key of its timing).</summary>
    sealed class PlannedScenario
    {
        public IScenario Scenario;
        public int Size;
    }

    sealed class PlannedSuite
    {
        public IScenarioSuite Suite;
        public List<PlannedScenario> Scenarios = new List<PlannedScenario>();
    }

    /// <summary>Every step of a run, known before the first starts: the suites with their scenarios, then the report parts.</summary>
    sealed class RunPlan
    {
        public readonly List<PlannedSuite> Suites = new List<PlannedSuite>();
        public readonly List<ReportPart> Parts = new List<ReportPart>();
        /// <summary>Suites whose shared work (<see cref="IScenarioSuitePreparation"/>) runs first, all at once on worker threads.</summary>
        public readonly List<IScenarioSuite> Preparations = new List<IScenarioSuite>();
        /// <summary>True when the run starts with the preparation step (references, and the setup of independent suites).</summary>
        public bool HasPreparation;
        /// <summary>Timing key of each step, in run order.</summary>
        public readonly List<string> Keys = new List<string>();
        public int Count => Keys.Count;

        public static RunPlan Build(RunOptions options, IEnumerable<IScenarioSuite> suites, IEnumerable<ReportPart> parts)
        {
            var plan = new RunPlan();
            // The preparation step, when any suite has one, is the first step of the run.
            plan.Keys.Add(null);
            foreach (IScenarioSuite suite in suites)
            {
                if (options.Filter != null && suite.Name.IndexOf(options.Filter, StringComparison.OrdinalIgnoreCase) < 0)
                    continue;
                var scenarios = new List<IScenario>(suite.Scenarios(options.Scope));
                // A suite left with no scenario by --method is skipped (a summary-only suite, which has none, still runs).
                if (options.Method != null && scenarios.Count > 0)
                {
                    scenarios.RemoveAll(sc => sc.Method.IndexOf(options.Method, StringComparison.OrdinalIgnoreCase) < 0);
                    if (scenarios.Count == 0)
                        continue;
                }
                var planned = new PlannedSuite { Suite = suite };
                foreach (IScenario sc in scenarios)
                {
                    planned.Scenarios.Add(new PlannedScenario { Scenario = sc, Size = sc.Size });
                    plan.Keys.Add(RunTimings.Key(suite.Name, $"{sc.Name}: {sc.Method} ({sc.Size} {sc.SizeUnit}), {RunOptions.ScopeName(options.Scope)}"));
                }
                plan.Suites.Add(planned);
                if (suite is IScenarioSuitePreparation && planned.Scenarios.Count > 0)
                    plan.Preparations.Add(suite);
            }
            plan.HasPreparation = plan.Preparations.Count > 0 || plan.Suites.Any(s => Program.SetUpConcurrently(s, options));
            if (plan.HasPreparation)
                plan.Keys[0] = RunTimings.Key("preparing", string.Join(", ", plan.Suites.Where(s => plan.Preparations.Contains(s.Suite) || Program.SetUpConcurrently(s, options))
                    .Select(s => s.Suite.Name)) + ", " + RunOptions.ScopeName(options.Scope));
            else
                plan.Keys.RemoveAt(0);
            // The report parts run only when no --method narrows the run, and with --filter only when it names them.
            if (options.Method == null)
                foreach (ReportPart part in parts)
                    if (options.Filter == null || part.Name.IndexOf(options.Filter, StringComparison.OrdinalIgnoreCase) >= 0)
                    {
                        plan.Parts.Add(part);
                        plan.Keys.Add(RunTimings.Key(part.Name, RunOptions.ScopeName(options.Scope)));
                    }
            return plan;
        }
    }

    sealed class SuiteResult
    {
        public readonly IScenarioSuite Suite;
        public readonly List<ScenarioResult> Rows = new List<ScenarioResult>();
        /// <summary>Markdown the suite wrote about all its rows (<see cref="IScenarioSuiteSummary"/>), or null.</summary>
        public string Summary;
        /// <summary>Lines the suite gave the report's summary.</summary>
        public readonly List<Finding> Findings = new List<Finding>();
        /// <summary>Figures drawn once the suite finished: file name and caption.</summary>
        public readonly List<(string File, string Alt, string Caption)> Figures = new List<(string, string, string)>();
        public bool Finished;

        SuiteDefinition m_Definition;

        public SuiteResult(IScenarioSuite suite) { Suite = suite; }

        /// <summary>The suite's definition, asked for once (a scene's may compute its reference values).</summary>
        public SuiteDefinition Definition => m_Definition ??= Suite.Definition;

        public IReadOnlyList<ScenarioOutcome> Outcomes() => Rows.ConvertAll(r => r.Outcome());

        /// <summary>Runs the suite's summary and findings and draws its figures.</summary>
        public void Finish(RunScope scope, string dir)
        {
            IReadOnlyList<ScenarioOutcome> outcomes = Outcomes();
            if (Suite is IScenarioSuiteSummary summary)
                Summary = summary.Summary(outcomes, scope);
            if (Suite is IScenarioSuiteFindings findings)
                Findings.AddRange(findings.Findings(outcomes, scope));
            if (SoftBodyDynamics.Runner.Figures.HasGnuplot())
            {
                string pareto = SoftBodyDynamics.Runner.Figures.PlotAccuracyVersusCost(dir, this);
                string cost = Suite is IScenarioSuiteFigure figure ? figure.CostLabel : "ns per item";
                if (pareto != null)
                    Figures.Add((pareto, $"{Suite.Name}: {Suite.ErrorMetricForPlot} against {cost}",
                        $"{Suite.ErrorMetricForPlot} (lower is better) against {cost} (left is cheaper); an error of exactly 0 is drawn at {SoftBodyDynamics.Runner.Figures.LogFloor:E0}."));
                string scaling = SoftBodyDynamics.Runner.Figures.PlotScaling(dir, this);
                if (scaling != null)
                    Figures.Add((scaling, $"{Suite.Name}: time per item against size", "Time per item against problem size (log–log): flat means cost linear in N."));
            }
            Finished = true;
        }

        /// <summary>The accuracy-versus-cost figure's file, or null.</summary>
        public string AccuracyFigure => Figures.Where(f => f.File.EndsWith("-accuracy-vs-cost.png")).Select(f => f.File).FirstOrDefault();
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

        /// <summary>The row as a suite's summary, findings and figure see it.</summary>
        public ScenarioOutcome Outcome() => new ScenarioOutcome(Method, NsPerItem, Metrics, Size, ItemsPerStep);

        /// <summary>The named metric, or NaN when this scenario does not report it.</summary>
        public double MetricValue(string name)
        {
            foreach (Metric m in Metrics)
                if (m.Name == name) return m.Value;
            return double.NaN;
        }

        /// <summary>The unit of the named metric (<see cref="Benchmarks.Scenarios.MetricUnit.Dimensionless"/> when the row does not report it).</summary>
        public MetricUnit MetricUnit(string name)
        {
            foreach (Metric m in Metrics)
                if (m.Name == name) return m.Unit;
            return Benchmarks.Scenarios.MetricUnit.Dimensionless;
        }
    }
}
