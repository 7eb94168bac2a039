using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Text;
using SoftBodyDynamics.Benchmarks.Scenarios;

namespace SoftBodyDynamics.Runner
{
    /// <summary>
    /// The report's first section: the three promises answered from the findings of the finished suites — what accuracy
    /// costs in time, which hard cases pass, what each effect costs per frame ("none yet" where nothing measured it).
    /// </summary>
    static class SummaryWriter
    {
        /// <summary>Effects a scene can call for, in summary order; an effect no suite measured reads "none yet".</summary>
        public static readonly string[] Effects =
        {
            EffectNames.ShapeMatchingBody, EffectNames.MassSpringBody, EffectNames.FemBody, EffectNames.Fluid,
            EffectNames.FlockingCohesion, EffectNames.AkinciCohesion, EffectNames.FluidViscosity, EffectNames.FluidColliders, EffectNames.FluidCollidersOutOfReach,
            EffectNames.SoftBodyCollisions, EffectNames.Plasticity, EffectNames.FluidSoftBodyCoupling, EffectNames.SoftSoftContacts,
            EffectNames.FluidRenderer, EffectNames.RendererSmoothing, EffectNames.RendererThickness, EffectNames.RendererNormals,
            EffectNames.RendererFullResolution,
        };

        public static void Write(StringBuilder md, IReadOnlyList<SuiteResult> suites, IReadOnlyList<PartResult> parts, RunScope scope = RunScope.Full)
        {
            md.AppendLine("## Summary");
            md.AppendLine();
            if (scope == RunScope.Standard)
                md.AppendLine("*Default run: every suite, with its sweep cut to the cheaper points; each suite's definition says what `--full` adds.*").AppendLine();
            else if (scope == RunScope.Quick)
                md.AppendLine("*Quick run: a few points of each suite, a smoke test; the numbers below are not the study's.*").AppendLine();
            var accuracy = new List<(AccuracyFinding Finding, SuiteResult Suite)>();
            var hard = new List<(HardCaseFinding Finding, SuiteResult Suite)>();
            var effects = new Dictionary<string, (EffectFinding Finding, SuiteResult Suite)>();
            foreach (SuiteResult s in suites)
            foreach (Finding f in s.Findings)
            {
                if (f is AccuracyFinding a) accuracy.Add((a, s));
                else if (f is HardCaseFinding h) hard.Add((h, s));
                else if (f is EffectFinding e && !effects.ContainsKey(e.Effect)) effects[e.Effect] = (e, s);
            }
            WriteAccuracy(md, accuracy);
            WriteHardCases(md, hard);
            WriteEffects(md, effects, parts);
        }

        static void WriteAccuracy(StringBuilder md, List<(AccuracyFinding Finding, SuiteResult Suite)> findings)
        {
            md.AppendLine("**What accuracy costs in time** — per scene, the cheapest setting whose error is within each threshold (managed .NET, one thread):");
            md.AppendLine();
            if (findings.Count == 0)
            {
                md.AppendLine("- No accuracy suite ran.").AppendLine();
                return;
            }
            md.AppendLine("| scene | error | ≤ 20 % | ≤ 5 % | ≤ 1 % | best | figure |");
            md.AppendLine("|---|---|---|---|---|---|---|");
            foreach (var (f, s) in findings)
            {
                md.Append($"| [{Report.Cell(f.Scene)}](#{Report.Slug(s.Suite.Name)}) | {Report.Cell(f.Error)} |");
                foreach (ThresholdReach r in f.Reaches)
                    md.Append(r.Reached ? $" {Report.Cell(r.Setting)}: **{Cost(r.Cost)} {f.CostUnit}** |" : " not reached |");
                md.Append(double.IsNaN(f.BestError) ? " every setting diverged |" : $" {Error(f.BestError, f.ErrorUnit)} ({Report.Cell(f.BestSetting)}) |");
                string figure = f.Metric == s.Suite.ErrorMetricForPlot ? s.AccuracyFigure : null;
                md.AppendLine(figure != null ? $" [figure]({figure}) |" : " – |");
            }
            md.AppendLine();
            if (findings.Any(f => f.Finding.ErrorUnit != MetricUnit.Fraction))
                md.AppendLine("Scenes whose error is not relative state their own thresholds in the error column.").AppendLine();
        }

        static void WriteHardCases(StringBuilder md, List<(HardCaseFinding Finding, SuiteResult Suite)> findings)
        {
            md.AppendLine("**Hard cases** — cases passed of those run, per method and solver:");
            md.AppendLine();
            if (findings.Count == 0)
            {
                md.AppendLine("- No hard-case suite ran.").AppendLine();
                return;
            }
            foreach (var group in findings.GroupBy(f => f.Finding.Group))
            {
                int all = group.Count(g => g.Finding.Passed == g.Finding.Total);
                string suite = group.First().Suite.Suite.Name;
                string criterion = group.First().Finding.Criterion;
                md.Append($"- [{group.Key}](#{Report.Slug(suite)}): {all} of {group.Count()} pass every case{(string.IsNullOrEmpty(criterion) ? "" : $" ({criterion})")}. ");
                md.AppendLine(string.Join("; ", group.Select(g => $"{g.Finding.Method} {g.Finding.Passed}/{g.Finding.Total}" +
                    (g.Finding.Failed != null && g.Finding.Failed.Count > 0 ? $" ({string.Join(", ", g.Finding.Failed)})" : ""))) + ".");
            }
            md.AppendLine();
        }

        static void WriteEffects(StringBuilder md, Dictionary<string, (EffectFinding Finding, SuiteResult Suite)> effects, IReadOnlyList<PartResult> parts)
        {
            md.AppendLine("**Effects** — what each effect a scene can call for costs per frame, measured with and without it:");
            md.AppendLine();
            foreach (string effect in Effects)
            {
                if (effects.TryGetValue(effect, out var e))
                    md.AppendLine($"- {effect}: {e.Finding.Cost} ([{e.Suite.Suite.Name}](#{Report.Slug(e.Suite.Suite.Name)}))");
                else
                    md.AppendLine($"- {effect}: none yet");
            }
            foreach (var extra in effects.Keys.Where(k => !Effects.Contains(k)))
                md.AppendLine($"- {extra}: {effects[extra].Finding.Cost} ([{effects[extra].Suite.Suite.Name}](#{Report.Slug(effects[extra].Suite.Suite.Name)}))");
            PartResult renderer = parts.FirstOrDefault(p => p.Part.Name == "LavapipeGpuFluidRenderer" && p.Succeeded);
            if (renderer != null)
                md.AppendLine($"  (The renderer's counted traffic per pass and its lavapipe times: [{renderer.Part.Title}](#{Report.Slug(renderer.Part.Title)}); no GPU timing.)");
            md.AppendLine();
        }

        /// <summary>A cost in ms: two significant digits below 10, whole numbers above.</summary>
        public static string Cost(double ms) =>
            ms >= 100 ? ms.ToString("0", CultureInfo.InvariantCulture)
            : ms >= 10 ? ms.ToString("0.#", CultureInfo.InvariantCulture)
            : ms >= 1 ? ms.ToString("0.0#", CultureInfo.InvariantCulture)
            : ms.ToString("0.0##", CultureInfo.InvariantCulture);

        /// <summary>An error as the summary prints it: fractions in percent, other units with their symbol.</summary>
        public static string Error(double value, MetricUnit unit) =>
            unit == MetricUnit.Fraction
                ? MethodStudyRanking.Percent(value)
                : value.ToString("0.###", CultureInfo.InvariantCulture) + MetricUnits.Suffix(unit);
    }
}
