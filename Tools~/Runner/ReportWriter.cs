using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using System.Text;
using SoftBodyDynamics.Benchmarks.Scenarios;

namespace SoftBodyDynamics.Runner
{
    /// <summary>Writes report.md, results.csv and, with gnuplot, one accuracy-versus-cost and one scaling figure per suite.</summary>
    static class ReportWriter
    {
        /// <summary>Errors of exactly 0 are drawn at this floor on log axes (and said so in the caption).</summary>
        const double k_LogFloor = 1e-12;
        /// <summary>gnuplot point types cycled through the series: filled circle, square, triangles, diamond, pentagon.</summary>
        static readonly int[] k_PointTypes = { 7, 5, 9, 11, 13, 15 };

        public static string Write(RunOptions options, List<SuiteResult> suites)
        {
            string dir = Path.GetFullPath(options.OutDir);
            var md = new StringBuilder();
            md.AppendLine("# Soft Body Dynamics — headless scenario report");
            md.AppendLine();
            md.AppendLine($"- Date (UTC): {DateTime.UtcNow:yyyy-MM-dd HH:mm}");
            md.AppendLine($"- Machine: {Environment.ProcessorCount} logical cores, {RuntimeInformation.OSDescription}, {RuntimeInformation.ProcessArchitecture}, {CpuName()}");
            md.AppendLine($"- Runtime: {RuntimeInformation.FrameworkDescription} (managed C#, single thread — not Burst; Burst numbers come from the Unity Performance tests)");
            md.AppendLine($"- Timing: median of {options.Repeats} timed steps after a warm-up of at least {ScenarioTimer.WarmupSeconds} s and 3 steps that goes on (up to {ScenarioTimer.MaxWarmupSeconds} s) while the fastest step still improves{(options.Quick ? "; quick run (reduced sizes)" : "")}");
            md.AppendLine();

            var csv = new StringBuilder("suite,scenario,method,size,size_unit,median_ms,min_ms,max_ms,ns_per_item,items_per_s,metric,value\n");
            bool gnuplot = HasGnuplot();
            foreach (SuiteResult s in suites)
            {
                md.AppendLine($"## {s.Suite.Name}");
                md.AppendLine();
                md.AppendLine(s.Suite.Description);
                md.AppendLine();
                var metricNames = s.Rows.SelectMany(r => r.Metrics.Select(m => m.Name)).Distinct().ToList();
                md.AppendLine("| method | size | ms/step | ns/item | items/s | " + string.Join(" | ", metricNames.Select(Cell)) + " |");
                md.AppendLine("|---|---:|---:|---:|---:|" + string.Concat(metricNames.Select(_ => "---:|")));
                foreach (ScenarioResult r in s.Rows)
                {
                    md.Append($"| {Cell(r.Method)} | {r.Size} {r.SizeUnit} | {r.MedianMs:F3} | {r.NsPerItem:F1} | {Format.Rate(r.ItemsPerSecond)} |");
                    // A metric the row does not report (NaN) is an empty cell, not "NaN".
                    foreach (string n in metricNames) md.Append(double.IsNaN(r.MetricValue(n)) ? " – |" : $" {Format.Value(r.MetricValue(n))} |");
                    md.AppendLine();
                    foreach (var m in r.Metrics)
                        csv.AppendLine(string.Join(",", s.Suite.Name, r.Name, Quote(r.Method), r.Size, r.SizeUnit,
                            F(r.MedianMs), F(r.MinMs), F(r.MaxMs), F(r.NsPerItem), F(r.ItemsPerSecond), Quote(m.Name), F(m.Value)));
                }
                md.AppendLine();
                if (!string.IsNullOrEmpty(s.Summary))
                    md.AppendLine(s.Summary.TrimEnd()).AppendLine();
                foreach (ScenarioResult r in s.Rows.Where(r => r.AllocatedBytesPerStep > 0))
                    md.AppendLine($"- **Warning:** `{r.Method}` (N = {r.Size}) allocated {r.AllocatedBytesPerStep:F0} bytes per Step.");
                if (s.Rows.Any(r => r.AllocatedBytesPerStep > 0))
                    md.AppendLine();

                if (gnuplot)
                {
                    string pareto = PlotAccuracyVersusCost(dir, s);
                    string cost = s.Suite is IScenarioSuiteFigure figure ? figure.CostLabel : "ns per item";
                    if (pareto != null)
                        md.AppendLine($"![{s.Suite.Name}: {s.Suite.ErrorMetricForPlot} against {cost}]({pareto})").AppendLine()
                          .AppendLine($"*{s.Suite.ErrorMetricForPlot} (lower is better) against {cost} (left is cheaper); an error of exactly 0 is drawn at {k_LogFloor:E0}.*").AppendLine();
                    string scaling = PlotScaling(dir, s);
                    if (scaling != null)
                        md.AppendLine($"![{s.Suite.Name}: time per item against size]({scaling})").AppendLine()
                          .AppendLine("*Time per item against problem size (log–log): flat means cost linear in N.*").AppendLine();
                }
                else
                {
                    md.AppendLine("*Figures skipped: gnuplot not found (the setup script installs Debian's gnuplot-nox).*").AppendLine();
                }
            }

            File.WriteAllText(Path.Combine(dir, "results.csv"), csv.ToString());
            string path = Path.Combine(dir, "report.md");
            File.WriteAllText(path, md.ToString());
            return path;
        }

        static string PlotAccuracyVersusCost(string dir, SuiteResult s)
        {
            string metric = s.Suite.ErrorMetricForPlot;
            // A suite without an error reference (pure throughput) names no metric and gets no accuracy figure.
            if (string.IsNullOrEmpty(metric)) return null;
            // Rows with a finite error only: a diverged point has no place on a log axis (the tables list it).
            var rows = s.Rows.Where(r => r.Metrics.Any(m => m.Name == metric) && double.IsFinite(r.MetricValue(metric))).ToList();
            if (rows.Count == 0) return null;
            string name = $"{s.Suite.Name}-accuracy-vs-cost";
            var figure = s.Suite as IScenarioSuiteFigure;
            ScenarioOutcome Outcome(ScenarioResult r) => new ScenarioOutcome(r.Method, r.NsPerItem, r.Metrics, r.Size, r.ItemsPerStep);
            // One series per method family (the text before the first comma, or the suite's own series), labelled by the rest.
            var families = figure != null
                ? rows.GroupBy(r => figure.Series(Outcome(r))).ToList()
                : rows.GroupBy(r => r.Method.Split(',')[0].Trim()).ToList();
            double Cost(ScenarioResult r) => figure != null ? figure.Cost(Outcome(r)) : r.NsPerItem;
            var dat = new StringBuilder();
            var plots = new List<string>();
            int index = 0;
            foreach (var f in families)
            {
                // A suite with its own figure plots one point per label in a series (rows that ran the same setting, such
                // as requested substep counts below what the step needs, would repeat it); the first row in suite order stays.
                var ordered = (figure != null
                    ? f.GroupBy(r => figure.PointLabel(Outcome(r))).Select(g => g.First())
                    : f).OrderBy(Cost).ToList();
                for (int k = 0; k < ordered.Count; k++)
                {
                    ScenarioResult r = ordered[k];
                    string rest = figure != null
                        ? (k == 0 || k == ordered.Count - 1 ? figure.PointLabel(Outcome(r)) : "")
                        : r.Method.Contains(',') ? r.Method.Substring(r.Method.IndexOf(',') + 1).Trim() + $" N={r.Size}" : $"N={r.Size}";
                    dat.AppendLine($"{F(Cost(r))} {F(Math.Max(k_LogFloor, r.MetricValue(metric)))} \"{rest.Replace("\"", "")}\"");
                }
                dat.AppendLine().AppendLine();
                // Explicit line type per family: the label plots would otherwise use up the colour cycle.
                string style = $"lt {index + 1} pt {k_PointTypes[index % k_PointTypes.Length]}";
                string with = figure != null ? "linespoints" : "points";
                plots.Add($"'{name}.dat' index {index} using 1:2 with {with} {style} ps 1.3 title '{f.Key.Replace("'", "")}'");
                plots.Add($"'{name}.dat' index {index} using 1:2:3 with labels offset 0.8,0.5 left rotate by 20 font ',7' tc lt {index + 1} notitle");
                index++;
            }
            string costLabel = figure != null ? figure.CostLabel : $"ns per item, median ({rows[0].SizeUnit})";
            File.WriteAllText(Path.Combine(dir, name + ".dat"), dat.ToString());
            string gp = $@"set terminal pngcairo size 960,600 font ',10'
set output '{name}.png'
set title '{s.Suite.Name}: accuracy against cost'
set xlabel '{costLabel.Replace("'", "")}'
set ylabel '{metric}'
set logscale xy
set format y '%.0e'
set grid
set key outside right top
set offsets graph 0.02, graph 0.3, graph 0.05, graph 0.05
plot {string.Join(", ", plots)}
";
            return RunGnuplot(dir, name, gp);
        }

        static string PlotScaling(string dir, SuiteResult s)
        {
            var groups = s.Rows.GroupBy(r => r.Method).Where(g => g.Select(r => r.Size).Distinct().Count() > 1).ToList();
            if (groups.Count == 0) return null;
            string name = $"{s.Suite.Name}-scaling";
            var dat = new StringBuilder();
            var plots = new List<string>();
            int index = 0;
            foreach (var g in groups)
            {
                foreach (var r in g.OrderBy(r => r.Size)) dat.AppendLine($"{r.Size} {F(r.NsPerItem)}");
                dat.AppendLine().AppendLine();
                plots.Add($"'{name}.dat' index {index} using 1:2 with linespoints lt {index + 1} pt {k_PointTypes[index % k_PointTypes.Length]} title '{g.Key.Replace("'", "")}'");
                index++;
            }
            File.WriteAllText(Path.Combine(dir, name + ".dat"), dat.ToString());
            string unit = groups[0].First().SizeUnit;
            string gp = $@"set terminal pngcairo size 960,600 font ',10'
set output '{name}.png'
set title '{s.Suite.Name}: time per item against N'
set xlabel 'N ({unit})'
set ylabel 'ns per item (median)'
set logscale xy
set grid
set key outside right top
set offsets graph 0.05, graph 0.05, 0, 0
plot {string.Join(", ", plots)}
";
            return RunGnuplot(dir, name, gp);
        }

        static string RunGnuplot(string dir, string name, string script)
        {
            string gpPath = Path.Combine(dir, name + ".gp");
            File.WriteAllText(gpPath, script);
            var psi = new ProcessStartInfo("gnuplot", name + ".gp")
            {
                WorkingDirectory = dir,
                RedirectStandardError = true,
                RedirectStandardOutput = true,
                UseShellExecute = false,
            };
            using var p = Process.Start(psi);
            string err = p.StandardError.ReadToEnd();
            p.WaitForExit();
            if (p.ExitCode != 0 || !File.Exists(Path.Combine(dir, name + ".png")))
            {
                Console.Error.WriteLine($"gnuplot failed for {name}: {err}");
                return null;
            }
            return name + ".png";
        }

        static bool HasGnuplot()
        {
            string path = Environment.GetEnvironmentVariable("PATH") ?? "";
            return path.Split(':').Any(d => File.Exists(Path.Combine(d, "gnuplot")));
        }

        static string CpuName()
        {
            try
            {
                string line = File.ReadLines("/proc/cpuinfo").FirstOrDefault(l => l.StartsWith("model name"));
                return line?.Split(':', 2)[1].Trim() ?? "unknown CPU";
            }
            catch (IOException) { return "unknown CPU"; }
        }

        static string F(double v) => v.ToString("R", CultureInfo.InvariantCulture);
        /// <summary>Text for a Markdown table cell: a literal '|' (as in "max |det R - 1|") would end the cell.</summary>
        static string Cell(string s) => s.Replace("|", "\\|");
        static string Quote(string s) => "\"" + s.Replace("\"", "\"\"") + "\"";
    }
}
