using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// The summary of a fluid resolution sweep whose step is one 1/60 s frame: per row its series and resolution (the
    /// method's text around its last comma), particles, µs per frame, the error (± its spread over an ensemble's members,
    /// when the row has one), one more metric, and the observed order
    /// log(e₁/e₂)/log(Δx₁/Δx₂) against the previous row of the same series (from the "spacing" metric).
    /// </summary>
    public static class FluidSweepTable
    {
        /// <summary>The cost axis of the sweeps' figures.</summary>
        public const string CostLabel = "µs per 1/60 s frame (whole scene, all substeps), median";

        /// <summary>µs per 1/60 s frame of the whole scene: ns per item × items per step (one step is one frame).</summary>
        public static double Cost(ScenarioOutcome row) => row.NsPerItem * row.ItemsPerStep * 1e-3;

        /// <summary>The markdown table: <paramref name="error"/> is a fraction metric shown in per cent under <paramref name="errorHeader"/>.</summary>
        public static string Write(IReadOnlyList<ScenarioOutcome> rows, string error, string errorHeader, string secondHeader, Func<ScenarioOutcome, string> second)
        {
            var md = new StringBuilder();
            md.AppendLine($"| series | resolution | particles | µs/frame | {errorHeader} | {secondHeader} | observed order |");
            md.AppendLine("|---|---|---:|---:|---:|---:|---:|");
            ScenarioOutcome previous = default;
            bool havePrevious = false;
            foreach (ScenarioOutcome r in rows)
            {
                string series = FluidScene.SeriesOf(r.Method);
                double e1 = r.Value(error);
                string order = "";
                if (havePrevious && FluidScene.SeriesOf(previous.Method) == series)
                {
                    double e0 = previous.Value(error), d0 = previous.Value("spacing"), d1 = r.Value("spacing");
                    if (e0 > 0 && e1 > 0 && d0 > d1)
                        order = F("{0:0.00}", Math.Log(e0 / e1) / Math.Log(d0 / d1));
                }
                double spread = r.Value(error + " spread");
                string shown = double.IsNaN(spread) ? F("{0:0.00} %", 100 * e1) : F("{0:0.00} % ± {1:0.00}", 100 * e1, 100 * spread);
                md.AppendLine(F("| {0} | {1} | {2} | {3:0} | {4} | {5} | {6} |", series, FluidScene.PointOf(r.Method), r.Size,
                    Cost(r), shown, second(r), order));
                previous = r;
                havePrevious = true;
            }
            return md.ToString();
        }

        /// <summary>
        /// The summary's line for a sweep: per relative threshold (20, 5, 1 %) the cheapest row whose <paramref name="metric"/>
        /// is within it, in ms per 1/60 s frame.
        /// </summary>
        public static AccuracyFinding Finding(string scene, string errorText, string metric, IReadOnlyList<ScenarioOutcome> rows) =>
            AccuracyFinding.FromRows(scene, errorText, metric, rows, AccuracyFinding.RelativeThresholds, r => Cost(r) * 1e-3, r => r.Method, "ms/frame");

        /// <summary>Invariant-culture formatting.</summary>
        public static string F(string format, params object[] args) => string.Format(CultureInfo.InvariantCulture, format, args);
    }
}
