using System.Collections.Generic;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>The method study's lines in the report's summary: what accuracy costs on each scene, and the hard cases per method.</summary>
    public static class MethodStudyFindings
    {
        /// <summary>Unit of the summary's cost: one 1/60 s step of the whole body, all substeps and iterations.</summary>
        public const string CostUnit = "ms/frame";

        /// <summary>Per threshold (20, 5, 1 %), the cheapest method and knob whose worst relative error is within it.</summary>
        public static AccuracyFinding Accuracy(string scene, IReadOnlyList<ScenarioOutcome> rows) =>
            AccuracyFinding.FromRows(scene, "worst of the scene's relative errors", StudyScene.Error, rows, AccuracyFinding.RelativeThresholds,
                r => 1e-3 * MethodStudyRanking.MicrosecondsPerStep(r), r => r.Method, CostUnit);

        /// <summary>
        /// One line per method of the stability suite: a hard case passes when the body recovers its rest shape, or when the NaN
        /// guard resets it once and it then stays at rest (the guard's designed answer to an absurd state); a body left deformed
        /// (bounded) or diverged fails.
        /// </summary>
        public static IEnumerable<Finding> HardCases(IReadOnlyList<ScenarioOutcome> rows)
        {
            foreach (ScenarioOutcome r in rows)
            {
                int passed = 0, total = 0;
                var failed = new List<string>();
                foreach (HardCase c in Scenarios.HardCases.All)
                {
                    string label = Scenarios.HardCases.Label(c);
                    double code = r.Value(label);
                    if (double.IsNaN(code))
                        continue;
                    total++;
                    var outcome = (HardCaseOutcome)(int)code;
                    if (Passes(outcome))
                        passed++;
                    else
                        failed.Add($"{label}: {HardCaseRun.Label(outcome)}");
                }
                yield return new HardCaseFinding
                {
                    Group = "Soft bodies", Criterion = Criterion, Method = MethodStudyRanking.Family(r.Method), Passed = passed, Total = total, Failed = failed,
                };
            }
        }

        /// <summary>The pass rule, as the summary states it.</summary>
        public const string Criterion = "a case passes when the body recovers its rest shape, or when the NaN guard resets it once and it then stays at rest";

        /// <summary>Recovered, or reset once by the guard and then at rest.</summary>
        public static bool Passes(HardCaseOutcome outcome) => outcome == HardCaseOutcome.Recovers || outcome == HardCaseOutcome.Reset;
    }
}
