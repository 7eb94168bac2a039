using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using System.Text;
using SoftBodyDynamics.Benchmarks.Scenarios;

namespace SoftBodyDynamics.Runner
{
    /// <summary>
    /// report.md and results.csv of a run, rewritten after every step so that an interrupted run leaves a valid report of
    /// what finished. The report opens with the summary (<see cref="SummaryWriter"/>), then the machine, a table of contents,
    /// and one section per suite: its question, its table, its own summary, its figures, then its definition.
    /// </summary>
    sealed class Report
    {
        readonly RunOptions m_Options;
        readonly string m_Dir;
        readonly int m_Planned;
        readonly DateTime m_Started = DateTime.UtcNow;
        public readonly List<SuiteResult> Suites = new List<SuiteResult>();
        public readonly List<PartResult> Parts = new List<PartResult>();
        /// <summary>Steps finished so far.</summary>
        public int Finished;
        public bool Complete;
        /// <summary>Where the float64 references of the run come from (<see cref="ReferenceStore"/>); null when it has none.</summary>
        public string ReferenceNote;

        public Report(RunOptions options, string dir, int planned)
        {
            m_Options = options;
            m_Dir = dir;
            m_Planned = planned;
            m_Docs = Path.GetRelativePath(dir, Path.Combine(Path.GetFullPath(options.Root), "Documentation~")).Replace('\\', '/');
        }

        /// <summary>The manual's folder relative to the report folder, for links.</summary>
        readonly string m_Docs;

        /// <summary>Writes report.md, results.csv and timings.csv; returns the report's path.</summary>
        public string Write(RunTimings timings)
        {
            ReportFiles.WriteAtomically(Path.Combine(m_Dir, "results.csv"), Csv(Suites));
            string path = Path.Combine(m_Dir, "report.md");
            ReportFiles.WriteAtomically(path, Markdown());
            timings.Save(m_Dir);
            return path;
        }

        public const string CsvHeader = "suite,scenario,method,size,size_unit,median_ms,min_ms,max_ms,ns_per_item,items_per_s,metric,value,unit";

        /// <summary>One line per metric of every finished row; <c>unit</c> says what the value is in (relative errors: fraction).</summary>
        public static string Csv(IEnumerable<SuiteResult> suites)
        {
            var csv = new StringBuilder(CsvHeader).Append('\n');
            foreach (SuiteResult s in suites)
            foreach (ScenarioResult r in s.Rows)
            foreach (Metric m in r.Metrics)
                csv.Append(string.Join(",", s.Suite.Name, Quote(r.Name), Quote(r.Method), r.Size.ToString(CultureInfo.InvariantCulture), Quote(r.SizeUnit),
                    F(r.MedianMs), F(r.MinMs), F(r.MaxMs), F(r.NsPerItem), F(r.ItemsPerSecond), Quote(m.Name), F(m.Value),
                    MetricUnits.Symbol(m.Unit))).Append('\n');
            return csv.ToString();
        }

        public string Markdown()
        {
            var md = new StringBuilder();
            md.AppendLine("# Soft Body Dynamics — headless scenario report");
            md.AppendLine();
            if (!Complete)
                md.AppendLine($"> **Partial report:** {Finished} of {m_Planned} steps finished (the run is going on, or was interrupted). Sections below are complete for the steps listed.").AppendLine();

            var finished = Suites.Where(s => s.Finished).ToList();
            SummaryWriter.Write(md, finished, Parts, m_Options.Scope);

            md.AppendLine("## Machine and method");
            md.AppendLine();
            md.AppendLine($"- Run: {RunOptions.ScopeName(m_Options.Scope)} (`bash Tools~/run.sh{ScopeFlag()}`), started {m_Started:yyyy-MM-dd HH:mm} UTC{(m_Options.Filter != null ? $", --filter {m_Options.Filter}" : "")}{(m_Options.Method != null ? $", --method \"{m_Options.Method}\"" : "")}");
            md.AppendLine($"- Machine: {Environment.ProcessorCount} logical cores, {RuntimeInformation.OSDescription}, {RuntimeInformation.ProcessArchitecture}, {CpuName()}");
            md.AppendLine($"- Runtime: {RuntimeInformation.FrameworkDescription} (managed C#, single thread, every method JIT-optimised at its first call: no tiers, no dynamic PGO — not Burst; Burst numbers come from the Unity Performance tests)");
            TimingRule t = m_Options.Timing;
            md.AppendLine($"- Timing: median of {m_Options.Repeats} timed steps (fewer for scenarios whose step is a whole run" +
                          (double.IsPositiveInfinity(t.TimedBudget) ? "" : $", and no more once they have taken {t.TimedBudget:0.#} s, at least {t.MinRepeats}") +
                          $") after a warm-up of at least {t.WarmupSeconds} s and {t.MinWarmupSteps} steps that goes on (up to {t.MaxWarmupSeconds} s) while the fastest step still improves" +
                          (t.ShortWarmups ? "; a step that is a whole run (dam break, droplet) is warmed up by the run's first few frames" : ""));
            md.AppendLine($"- Threads: every timed step runs alone on one thread; suites of independent scenarios (the method study and its stability suite, the fluid accuracy suite, the shape-matching convergence and frame-rate studies) set up and evaluate them on {m_Options.Threads} worker threads, which changes no result");
            if (ReferenceNote != null)
                md.AppendLine($"- References: {ReferenceNote}");
            md.AppendLine("- Units: relative errors are fractions in results.csv (column `unit`) and percent in these tables.");
            md.AppendLine();

            md.AppendLine("## Contents");
            md.AppendLine();
            foreach (SuiteResult s in Suites)
                md.AppendLine($"- [{s.Suite.Name}](#{Slug(s.Suite.Name)}) — {s.Definition?.Purpose ?? ""}{(s.Finished ? "" : " *(unfinished)*")}");
            foreach (PartResult p in Parts)
                md.AppendLine($"- [{p.Part.Title}](#{Slug(p.Part.Title)})");
            md.AppendLine();

            foreach (SuiteResult s in Suites)
                WriteSuite(md, s, m_Docs);
            foreach (PartResult p in Parts)
            {
                md.AppendLine($"## {p.Part.Title}").AppendLine();
                md.AppendLine(p.Succeeded ? p.Markdown.TrimEnd() : $"*Not written: {p.Failure}.*").AppendLine();
            }
            return md.ToString();
        }

        string ScopeFlag() => m_Options.Scope == RunScope.Full ? " --full" : m_Options.Scope == RunScope.Quick ? " --quick" : "";

        static void WriteSuite(StringBuilder md, SuiteResult s, string docs)
        {
            md.AppendLine($"## {s.Suite.Name}");
            md.AppendLine();
            SuiteDefinition d = s.Definition;
            if (!string.IsNullOrEmpty(d?.Purpose))
                md.AppendLine($"*{d.Purpose}*").AppendLine();
            if (s.Rows.Count > 0)
            {
                var metricNames = s.Rows.SelectMany(r => r.Metrics.Select(m => m.Name)).Distinct().ToList();
                var units = metricNames.ToDictionary(n => n, n => s.Rows.First(r => r.Metrics.Any(m => m.Name == n)).MetricUnit(n));
                md.AppendLine("| method | size | ms/step | ns/item | items/s | " + string.Join(" | ", metricNames.Select(n => Cell(n) + HeaderUnit(units[n]))) + " |");
                md.AppendLine("|---|---:|---:|---:|---:|" + string.Concat(metricNames.Select(_ => "---:|")));
                foreach (ScenarioResult r in s.Rows)
                {
                    md.Append($"| {Cell(r.Method)} | {r.Size} {r.SizeUnit} | {r.MedianMs:F3} | {r.NsPerItem:F1} | {Format.Rate(r.ItemsPerSecond)} |");
                    // A metric the row does not report (NaN) is an empty cell, not "NaN".
                    foreach (string n in metricNames)
                    {
                        double v = r.MetricValue(n);
                        md.Append(double.IsNaN(v) ? " – |" : $" {Format.Value(MetricUnits.Displayed(v, units[n]))} |");
                    }
                    md.AppendLine();
                }
                md.AppendLine();
            }
            if (!s.Finished)
            {
                md.AppendLine("*Unfinished: the rows above are the scenarios that finished.*").AppendLine();
                return;
            }
            if (!string.IsNullOrEmpty(s.Summary))
                md.AppendLine(s.Summary.TrimEnd()).AppendLine();
            foreach (ScenarioResult r in s.Rows.Where(r => r.AllocatedBytesPerStep > 0))
                md.AppendLine($"- **Warning:** `{r.Method}` (N = {r.Size}) allocated {r.AllocatedBytesPerStep:F0} bytes per Step.");
            if (s.Rows.Any(r => r.AllocatedBytesPerStep > 0))
                md.AppendLine();
            foreach (var f in s.Figures)
                md.AppendLine($"![{f.Alt}]({f.File})").AppendLine().AppendLine($"*{f.Caption}*").AppendLine();
            if (!Figures.HasGnuplot() && s.Rows.Count > 0)
                md.AppendLine("*Figures skipped: gnuplot not found (the setup script installs Debian's gnuplot-nox).*").AppendLine();
            WriteDefinition(md, d, docs);
        }

        /// <summary>The suite's definition as a short list under its table.</summary>
        public static void WriteDefinition(StringBuilder md, SuiteDefinition d, string docs)
        {
            if (d == null)
                return;
            md.AppendLine("**Definition**").AppendLine();
            void Entry(string label, string text)
            {
                if (!string.IsNullOrWhiteSpace(text))
                    md.AppendLine($"- *{label}:* {text}");
            }
            Entry("Body", d.Body);
            Entry("Material", d.Material);
            Entry("Load", d.Load);
            Entry("Reference", d.Reference);
            Entry("Metric", d.Metric);
            if (d.Notes != null)
                foreach (string note in d.Notes)
                    md.AppendLine($"- {note}");
            if (!string.IsNullOrEmpty(d.Details))
                md.AppendLine($"- *More:* [Documentation~/{d.Details}]({docs}/{d.Details})");
            md.AppendLine();
        }

        /// <summary>" (%)" for fractions, " (unit)" for dimensioned values, "" otherwise: the column header's unit.</summary>
        static string HeaderUnit(MetricUnit unit)
        {
            string suffix = MetricUnits.Suffix(unit).Trim();
            return suffix.Length == 0 ? "" : $" ({suffix})";
        }

        /// <summary>GitHub's heading anchor: lower case, punctuation dropped except '-' and '_', spaces to '-'.</summary>
        public static string Slug(string heading)
        {
            var sb = new StringBuilder();
            foreach (char c in heading.Trim().ToLowerInvariant())
            {
                if (char.IsLetterOrDigit(c) || c == '-' || c == '_')
                    sb.Append(c);
                else if (c == ' ')
                    sb.Append('-');
            }
            return sb.ToString();
        }

        static string CpuName()
        {
            try
            {
                string line = File.ReadLines("/proc/cpuinfo").FirstOrDefault(l => l.StartsWith("model name"));
                return line?.Split(':', 2)[1].Trim() ?? "unknown CPU";
            }
            catch (IOException) { return "unknown CPU"; }
            catch (UnauthorizedAccessException) { return "unknown CPU"; }
        }

        static string F(double v) => v.ToString("R", CultureInfo.InvariantCulture);
        /// <summary>Text for a Markdown table cell: a literal '|' (as in "max |det R - 1|") would end the cell.</summary>
        public static string Cell(string s) => s.Replace("|", "\\|");
        static string Quote(string s) => "\"" + s.Replace("\"", "\"\"") + "\"";
    }

    static class ReportFiles
    {
        /// <summary>Writes a temporary file and renames it over <paramref name="path"/>: a reader never sees half a file.</summary>
        public static void WriteAtomically(string path, string text)
        {
            string temp = path + ".tmp";
            File.WriteAllText(temp, text);
            File.Move(temp, path, true);
        }
    }
}
