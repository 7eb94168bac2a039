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
    /// <summary>With gnuplot: one accuracy-versus-cost and one scaling figure per suite, as PNG files beside the report.</summary>
    static class Figures
    {
        /// <summary>Errors of exactly 0 are drawn at this floor on log axes (and said so in the caption).</summary>
        public const double LogFloor = 1e-12;
        /// <summary>gnuplot point types cycled through the series: filled circle, square, triangles, diamond, pentagon.</summary>
        static readonly int[] k_PointTypes = { 7, 5, 9, 11, 13, 15 };

        /// <summary>The suite's error metric against its cost, one series per method family; the PNG's file name, or null.</summary>
        public static string PlotAccuracyVersusCost(string dir, SuiteResult s)
        {
            string metric = s.Suite.ErrorMetricForPlot;
            // A suite without an error reference (pure throughput) names no metric and gets no accuracy figure.
            if (string.IsNullOrEmpty(metric)) return null;
            // Rows with a finite error only: a diverged point has no place on a log axis (the tables list it).
            var rows = s.Rows.Where(r => r.Metrics.Any(m => m.Name == metric) && double.IsFinite(r.MetricValue(metric))).ToList();
            if (rows.Count == 0) return null;
            string name = $"{s.Suite.Name}-accuracy-vs-cost";
            // Relative errors are fractions; the figure, like the tables, shows them in percent.
            bool percent = rows[0].MetricUnit(metric) == MetricUnit.Fraction;
            double Shown(double v) => percent ? 100.0 * v : v;
            var figure = s.Suite as IScenarioSuiteFigure;
            // One series per method family (the text before the first comma, or the suite's own series), labelled by the rest.
            var families = figure != null
                ? rows.GroupBy(r => figure.Series(r.Outcome())).ToList()
                : rows.GroupBy(r => r.Method.Split(',')[0].Trim()).ToList();
            double Cost(ScenarioResult r) => figure != null ? figure.Cost(r.Outcome()) : r.NsPerItem;
            var dat = new StringBuilder();
            var plots = new List<string>();
            int index = 0;
            foreach (var f in families)
            {
                // A suite with its own figure plots one point per label in a series (rows that ran the same setting, such
                // as requested substep counts below what the step needs, would repeat it); the first row in suite order stays.
                var ordered = (figure != null
                    ? f.GroupBy(r => figure.PointLabel(r.Outcome())).Select(g => g.First())
                    : f).OrderBy(Cost).ToList();
                for (int k = 0; k < ordered.Count; k++)
                {
                    ScenarioResult r = ordered[k];
                    string rest = figure != null
                        ? (k == 0 || k == ordered.Count - 1 ? figure.PointLabel(r.Outcome()) : "")
                        : r.Method.Contains(',') ? r.Method.Substring(r.Method.IndexOf(',') + 1).Trim() + $" N={r.Size}" : $"N={r.Size}";
                    dat.AppendLine($"{F(Cost(r))} {F(Math.Max(LogFloor, Shown(r.MetricValue(metric))))} \"{rest.Replace("\"", "")}\"");
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
set ylabel '{metric}{(percent ? " (%)" : "")}'
set logscale xy
set format y '{(percent ? "%g" : "%.0e")}'
set grid
set key outside right top
set offsets graph 0.02, graph 0.3, graph 0.05, graph 0.05
plot {string.Join(", ", plots)}
";
            return RunGnuplot(dir, name, gp);
        }

        /// <summary>Time per item against N for methods run at several sizes; the PNG's file name, or null.</summary>
        public static string PlotScaling(string dir, SuiteResult s)
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

        /// <summary>True when gnuplot is on the PATH (looked up once: the report asks after every scenario).</summary>
        public static bool HasGnuplot() => s_HasGnuplot.Value;

        static readonly Lazy<bool> s_HasGnuplot = new Lazy<bool>(() =>
            (Environment.GetEnvironmentVariable("PATH") ?? "").Split(':').Any(d => File.Exists(Path.Combine(d, "gnuplot"))));

        static string F(double v) => v.ToString("R", CultureInfo.InvariantCulture);
    }
}
