using System.Collections.Generic;
using System.Linq;
using System.Text;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// The method study's summary over all its scenes run before it: for every method, the cost to reach 1 %, 5 % and
    /// 20 % error on every scene at once (the largest of the per-scene costs), and the per-scene cost to reach 5 %.
    /// Runs no scenario of its own.
    /// </summary>
    public sealed class MethodStudyRankingSuite : IScenarioSuite, IScenarioSuiteSummary
    {
        public string Name => "MethodStudyRanking";

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "Which method reaches an error of 1 %, 5 % and 20 % on every method-study scene at once, and at what cost.",
            Body = "None of its own: the rows of the method-study scenes that ran before it in this run (body, material and load: see each scene).",
            Reference = "Each scene's own reference.",
            Metric = "The cost to reach an error on all scenes is the largest of the method's per-scene costs to reach it: µs per 1/60 s step of the whole body " +
                     "at the cheapest setting that gets there; 'not reached' when some scene never does at the knob values swept.",
            Details = "choosing-a-method.md#one-full-run-rankings-per-scene-and-over-all-scenes",
        };

        public string ErrorMetricForPlot => null;

        public IEnumerable<IScenario> Scenarios(RunScope scope) => Enumerable.Empty<IScenario>();

        public string Summary(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            var scenes = MethodStudyRanking.SceneOrder.ToList();
            if (scenes.Count == 0)
                return "No method-study scene ran (filter).";
            var families = scenes.SelectMany(s => MethodStudyRanking.Rows(s).Select(r => MethodStudyRanking.Family(r.Method))).Distinct().ToList();
            var table = new List<(string Family, double[] All, double[] PerScene)>();
            foreach (string f in families)
            {
                var perSceneCosts = scenes.Select(s => MethodStudyRanking.Rows(s).Where(r => MethodStudyRanking.Family(r.Method) == f).ToList()).ToList();
                double[] all = MethodStudyRanking.Thresholds.Select(t => perSceneCosts.Where(g => g.Count > 0)
                    .Select(g => MethodStudyRanking.CostToReach(g, t)).DefaultIfEmpty(double.PositiveInfinity).Max()).ToArray();
                double[] per = perSceneCosts.Select(g => g.Count > 0 ? MethodStudyRanking.CostToReach(g, 0.05) : double.NaN).ToArray();
                table.Add((f, all, per));
            }
            table = table.OrderBy(t => t.All[1]).ThenBy(t => t.All[2]).ThenBy(t => t.PerScene.Count(c => double.IsPositiveInfinity(c))).ToList();
            var md = new StringBuilder();
            md.AppendLine("Cost (µs per step of the whole body) to reach an error on every scene at once, and per scene to reach 5 %:");
            md.AppendLine();
            md.Append("| rank | method | all scenes ≤ 1 % | ≤ 5 % | ≤ 20 % |");
            foreach (string s in scenes)
                md.Append($" {s} ≤ 5 % |");
            md.AppendLine();
            md.Append("|---:|---|---:|---:|---:|");
            foreach (string _ in scenes)
                md.Append("---:|");
            md.AppendLine();
            int rank = 1;
            foreach (var t in table)
            {
                md.Append($"| {rank++} | {t.Family} | {C(t.All[0])} | {C(t.All[1])} | {C(t.All[2])} |");
                foreach (double c in t.PerScene)
                    md.Append($" {C(c)} |");
                md.AppendLine();
            }
            return md.ToString();
        }

        static string C(double us) => double.IsNaN(us) ? "–" : double.IsPositiveInfinity(us) ? "not reached" : us.ToString(us < 100 ? "0.0" : "0");
    }
}
