using System.Collections.Generic;
using System.Linq;
using System.Text;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// One scene of the method study as a suite: every method of <see cref="MethodCatalog"/> at every knob value, one
    /// table, one error-against-cost figure (one curve per method) and a ranking by the cost to reach 1 %, 5 % and 20 %.
    /// </summary>
    public sealed class MethodStudySuite : IScenarioSuite, IScenarioSuiteSummary, IScenarioSuiteFigure, IScenarioSuiteFindings, IScenarioSuiteIndependent, IScenarioSuiteStoredReference
    {
        readonly StudyScene m_Scene;

        public MethodStudySuite(StudyScene scene) { m_Scene = scene; }

        public string Name => m_Scene.Name;

        /// <summary>The scene's definition, with how cost is counted: what one item is in its metric line, the rest as its first note.</summary>
        public SuiteDefinition Definition
        {
            get
            {
                SuiteDefinition d = m_Scene.Definition;
                d.Metric = MethodStudyRanking.ItemNote + " " + d.Metric;
                var notes = new List<string> { MethodStudyRanking.CostNote, DefaultRunNote() };
                if (d.Notes != null)
                    notes.AddRange(d.Notes);
                d.Notes = notes.ToArray();
                return d;
            }
        }

        public string ErrorMetricForPlot => StudyScene.Error;

        /// <summary>What the default run leaves out of this scene (the points only --full runs), by method.</summary>
        string DefaultRunNote()
        {
            var standard = new HashSet<string>(Scenarios(RunScope.Standard).Select(s => s.Method));
            var left = Scenarios(RunScope.Full).Select(s => s.Method).Where(m => !standard.Contains(m))
                .GroupBy(MethodStudyRanking.Family)
                .Select(g => $"{g.Key} ({string.Join(" / ", g.Select(MethodStudyRanking.Knob))})").ToList();
            return left.Count == 0 ? "The default run runs every point of the full study." : "The default run leaves out (--full runs them): " + string.Join("; ", left) + ".";
        }

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            foreach (MethodVariant v in MethodCatalog.Variants)
            foreach (int resolution in v.ResolutionsOf(scope, m_Scene.MaxResolution, m_Scene.StandardMaxResolution(v)))
            foreach (int knob in scope == RunScope.Quick ? v.QuickKnobs : scope == RunScope.Standard ? m_Scene.StandardKnobs(v) : m_Scene.FullKnobs(v, resolution))
                yield return new MethodStudyScenario(m_Scene, v, knob, resolution);
        }

        public string Series(ScenarioOutcome row) => MethodStudyRanking.Family(row.Method);
        public string PointLabel(ScenarioOutcome row) => MethodStudyRanking.Knob(row.Method);
        public string CostLabel => "µs per 1/60 s step of the whole body (all substeps and iterations), median";
        public double Cost(ScenarioOutcome row) => MethodStudyRanking.MicrosecondsPerStep(row);

        /// <summary>The scene's float64 reference.</summary>
        public void Prepare() => m_Scene.PrepareReference();

        public System.Type ReferenceType => m_Scene.ReferenceType;
        public object Reference() => m_Scene.Reference();
        public void UseReference(object values) => m_Scene.UseReference(values);

        public IEnumerable<Finding> Findings(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            yield return MethodStudyFindings.Accuracy(Name.Replace("MethodStudy", "").Replace("Csm3", "CSM3"), rows);
        }

        public string Summary(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            MethodStudyRanking.Record(Name, rows);
            var md = new StringBuilder();
            md.AppendLine($"Cheapest setting of each method that reaches an error ('{StudyScene.Error}') of 1 %, 5 % and 20 % " +
                          "(µs per step of the whole body; ranked by the cost to reach 5 %, then 20 %, then the best error; methods that only diverged last):");
            md.AppendLine();
            md.Append(MethodStudyRanking.Table(rows));
            return md.ToString();
        }
    }

    /// <summary>The ranking tables of the method study: per scene, and over all scenes (<see cref="MethodStudyRankingSuite"/>).</summary>
    public static class MethodStudyRanking
    {
        /// <summary>Error thresholds of the ranking (fractions).</summary>
        public static readonly double[] Thresholds = { 0.01, 0.05, 0.20 };

        /// <summary>What one item of a method-study row is, for the definitions' metric line.</summary>
        public const string ItemNote =
            "One item is one particle through one 1/60 s step of the scene (all substeps and iterations): ns/item is the cost per particle per step.";

        /// <summary>How cost is counted, for the definitions' notes.</summary>
        public const string CostNote =
            "Cost in the figure and the ranking: µs per step of the whole body (ns/item × '" + StudyScene.Particles + "'), so finer meshes cost more; " +
            "an error of – (NaN) means the method diverged or the guard reset it.";

        static readonly Dictionary<string, IReadOnlyList<ScenarioOutcome>> s_Scenes = new Dictionary<string, IReadOnlyList<ScenarioOutcome>>();

        /// <summary>Scenes recorded so far in this run, in run order.</summary>
        public static readonly List<string> SceneOrder = new List<string>();

        public static void Record(string scene, IReadOnlyList<ScenarioOutcome> rows)
        {
            if (!s_Scenes.ContainsKey(scene))
                SceneOrder.Add(scene);
            s_Scenes[scene] = rows;
        }

        public static IReadOnlyList<ScenarioOutcome> Rows(string scene) => s_Scenes.TryGetValue(scene, out var r) ? r : null;

        public static string Family(string method) => method.Split(';')[0].Trim();
        public static string Knob(string method) => method.Contains(";") ? method.Substring(method.IndexOf(';') + 1).Trim() : "";

        /// <summary>Cost of a row: µs per 1/60 s step of the whole body (ns per particle-step × the row's particle count).</summary>
        public static double MicrosecondsPerStep(ScenarioOutcome row) => row.NsPerItem * row.Value(StudyScene.Particles) * 1e-3;

        /// <summary>Cheapest cost (µs per step of the body) among rows with error ≤ <paramref name="threshold"/>, or +∞.</summary>
        public static double CostToReach(IEnumerable<ScenarioOutcome> rows, double threshold)
        {
            double best = double.PositiveInfinity;
            foreach (ScenarioOutcome r in rows)
            {
                double e = r.Value(StudyScene.Error);
                if (e <= threshold && MicrosecondsPerStep(r) < best)
                    best = MicrosecondsPerStep(r);
            }
            return best;
        }

        /// <summary>Markdown table: one row per method, the cost to reach each threshold and the best error seen.</summary>
        public static string Table(IReadOnlyList<ScenarioOutcome> rows)
        {
            var families = rows.GroupBy(r => Family(r.Method))
                .Select(g => (Family: g.Key, Costs: Thresholds.Select(t => CostToReach(g, t)).ToArray(),
                    Best: g.Select(r => r.Value(StudyScene.Error)).Where(double.IsFinite).DefaultIfEmpty(double.NaN).Min()))
                .OrderBy(f => f.Costs[1]).ThenBy(f => f.Costs[2]).ThenBy(f => double.IsNaN(f.Best)).ThenBy(f => f.Best).ToList();
            var md = new StringBuilder();
            md.AppendLine("| rank | method | to 1 % | to 5 % | to 20 % | best error |");
            md.AppendLine("|---:|---|---:|---:|---:|---:|");
            int rank = 1;
            foreach (var f in families)
                md.AppendLine($"| {rank++} | {f.Family} | {Cost(f.Costs[0])} | {Cost(f.Costs[1])} | {Cost(f.Costs[2])} | {Percent(f.Best)} |");
            return md.ToString();
        }

        static string Cost(double us) => double.IsPositiveInfinity(us) ? "not reached" : us < 100 ? us.ToString("0.0") + " µs" : us.ToString("0") + " µs";

        public static string Percent(double e) => double.IsNaN(e) ? "diverged" : (100 * e).ToString(e < 0.001 ? "0.000" : e < 0.1 ? "0.00" : "0.0") + " %";
    }
}
