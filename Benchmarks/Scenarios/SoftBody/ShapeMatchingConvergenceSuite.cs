using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Text;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Shape-matching accuracy against cost: the solver's trajectory error against a float64 dt → 0 reference of the
    /// same continuous model, with the observed order of convergence, and the fitted frequency and damping ratio of a
    /// fully resisted mode against the parameters, for every mode, layout and substep count.
    /// </summary>
    public sealed class ShapeMatchingConvergenceSuite : IScenarioSuite, IScenarioSuiteSummary, IScenarioSuiteFigure, IScenarioSuiteIndependent
    {
        /// <summary>Metric: RMS over particles and frames of |x_solver − x_ref| over the body size (dimensionless).</summary>
        public const string TrajectoryError = "traj err";
        /// <summary>Metric: observed order ln(e_prev/e)/ln(n/n_prev) against the previous substep count of the sweep.</summary>
        public const string Order = "order";
        /// <summary>Metric: RMS change of the reference trajectory when its RK4 step is halved, over the size.</summary>
        public const string ReferenceChange = "ref change";
        /// <summary>Metric: ωh of one substep (rad).</summary>
        public const string Phase = "wh";
        /// <summary>Metric: fitted frequency of the fully resisted mode over the parameter, minus 1.</summary>
        public const string FrequencyError = "f/f0-1";
        /// <summary>Metric: fitted damping ratio of the fully resisted mode over the parameter, minus 1.</summary>
        public const string DampingError = "zeta/zeta0-1";
        /// <summary>Metric: NaN-guard resets (0 expected).</summary>
        public const string Resets = "resets";

        /// <summary>Substep counts per 1/60 s step of the full run (the cost axis).</summary>
        public static readonly int[] SubstepCounts = { 1, 2, 4, 8, 16, 32 };
        /// <summary>Substep counts of the quick run.</summary>
        public static readonly int[] QuickSubstepCounts = { 1, 4, 16 };
        /// <summary>RK4 steps per frame of the quick run's coarser reference.</summary>
        public const int QuickReferenceStepsPerFrame = 8;

        static readonly (ShapeMatchingMode, ShapeMatchingClusterLayout)[] s_Families =
        {
            (ShapeMatchingMode.Rigid, ShapeMatchingClusterLayout.Single),
            (ShapeMatchingMode.Linear, ShapeMatchingClusterLayout.Single),
            (ShapeMatchingMode.Quadratic, ShapeMatchingClusterLayout.Single),
            (ShapeMatchingMode.Rigid, ShapeMatchingClusterLayout.Overlapping),
            (ShapeMatchingMode.Linear, ShapeMatchingClusterLayout.Overlapping),
            (ShapeMatchingMode.Quadratic, ShapeMatchingClusterLayout.Overlapping),
        };

        /// <summary>Families of the quick run (no quadratic: its reference evaluates the slower float64 quadratic goals).</summary>
        static readonly (ShapeMatchingMode, ShapeMatchingClusterLayout)[] s_QuickFamilies =
        {
            (ShapeMatchingMode.Rigid, ShapeMatchingClusterLayout.Single),
            (ShapeMatchingMode.Linear, ShapeMatchingClusterLayout.Overlapping),
        };

        public string Name => "ShapeMatchingConvergence";

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "How far a released shape-matching body's trajectory is from the continuous model's, and how fast that error falls as substeps are added, for each mode and cluster layout.",
            Body = $"A {ConvergenceStudy.BodySize} m cube of {ConvergenceStudy.Edge}³ = {ConvergenceStudy.Edge * ConvergenceStudy.Edge * ConvergenceStudy.Edge} particles, " +
                   $"as one cluster or 8 overlapping {ShapeMatchingBenchmarkBody.ClusterEdge}³ clusters; no gravity, no contacts.",
            Material = $"{ShapeMatchingBenchmarkBody.Frequency} Hz, ζ = {ShapeMatchingBenchmarkBody.DampingRatio}, β = {ShapeMatchingBenchmarkBody.Beta}; rigid, linear or quadratic goals; " +
                       $"the substep phase limit lifted, so a row takes exactly its {string.Join(", ", SubstepCounts)} substeps per 1/60 s step.",
            Load = $"Squashed to {ConvergenceRelease.HeightFactor} of its height (volume kept), twisted by {ConvergenceRelease.Twist} rad, jittered by ±{ConvergenceRelease.JitterFraction * 100} % " +
                   $"of the spacing, released at rest and followed for {ConvergenceRelease.Frames} frames of 1/60 s.",
            Reference = "A float64 classical RK4 integration of the continuous model ẍᵢ = ω² P(g(x) − x)ᵢ − 2ζω (ẋᵢ − uᵢ) from the same float32 start, " +
                        $"at 1/{60 * 2 * ConvergenceStudy.ReferenceStepsPerFrame} s; for 'f/f0-1' and 'zeta/zeta0-1', the parameters.",
            Metric = $"One item is one particle-step (all substeps), so ns/item grows with the substep count. '{TrajectoryError}' = RMS over particles and frames of |x_solver − x_ref| / body size; " +
                     $"'{Order}' = ln(e_prev/e)/ln(n/n_prev), tending to 1; '{Phase}' = ωh per substep; '{ReferenceChange}' = the reference's change when its RK4 step is halved " +
                     "(bounds its error; must be far below every solver error).",
            Notes = new[]
            {
                $"'{FrequencyError}', '{DampingError}': frequency and damping ratio of a separate free oscillation of the fully resisted mode (fitted by Prony) over the parameters, " +
                "minus 1; exact but for float32 round-off (≈ 1e-6). Quadratic goals on 4³ clusters have no such mode, so no values.",
                $"Default run: {string.Join(", ", QuickSubstepCounts)} substeps for every family. Quick run: the same for rigid (1 cluster) and linear (4³ clusters), reference at 1/{60 * 2 * QuickReferenceStepsPerFrame} s.",
            },
            Details = "accuracy.md#convergence-error-against-cost",
        };

        public string ErrorMetricForPlot => TrajectoryError;

        public string Series(ScenarioOutcome row) => row.Method.Split(',')[0].Trim();
        public string PointLabel(ScenarioOutcome row)
        {
            string label = row.Method.Substring(row.Method.IndexOf(',') + 1).Trim();
            return label == "1 substeps" ? "1 substep" : label;
        }
        public string CostLabel => "ns per particle-step (one particle through a 1/60 s step, all substeps), median";
        public double Cost(ScenarioOutcome row) => row.NsPerItem;

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            int[] counts = quick || scope == RunScope.Standard ? QuickSubstepCounts : SubstepCounts;
            int referenceSteps = quick ? QuickReferenceStepsPerFrame : ConvergenceStudy.ReferenceStepsPerFrame;
            foreach ((ShapeMatchingMode mode, ShapeMatchingClusterLayout layout) in quick ? s_QuickFamilies : s_Families)
                for (int k = 0; k < counts.Length; k++)
                    yield return new ShapeMatchingConvergenceScenario(mode, layout, counts[k], k > 0 ? counts[k - 1] : 0, referenceSteps);
        }

        /// <summary>One table: the error per substep count with the observed order in brackets, and the reference's change.</summary>
        public string Summary(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            var families = rows.GroupBy(r => r.Method.Split(',')[0].Trim()).ToList();
            int[] counts = quick || scope == RunScope.Standard ? QuickSubstepCounts : SubstepCounts;
            var md = new StringBuilder();
            md.AppendLine("Trajectory error against the float64 reference (observed order against the previous column in brackets):");
            md.AppendLine();
            md.Append("| mode (layout) |");
            foreach (int n in counts)
                md.Append($" {n} substep{(n > 1 ? "s" : "")} |");
            md.AppendLine(" reference change at h/2 | falls as cost grows |");
            md.Append("|---|");
            foreach (int _ in counts)
                md.Append("---:|");
            md.AppendLine("---:|:---:|");
            foreach (var family in families)
            {
                md.Append($"| {family.Key} |");
                double previous = double.PositiveInfinity;
                bool falls = true;
                var ordered = family.ToList();
                foreach (ScenarioOutcome r in ordered)
                {
                    double e = r.Value(TrajectoryError), order = r.Value(Order);
                    falls &= e < previous;
                    previous = e;
                    md.Append(double.IsNaN(order) ? $" {E(e)} |" : $" {E(e)} ({order.ToString("0.00", CultureInfo.InvariantCulture)}) |");
                }
                bool cheaperFirst = ordered.Zip(ordered.Skip(1), (a, b) => a.NsPerItem < b.NsPerItem).All(x => x);
                md.AppendLine($" {E(ordered[0].Value(ReferenceChange))} | {(falls ? "yes" : "**no**")}{(cheaperFirst ? "" : " (cost not monotone)")} |");
            }
            double worstF = rows.Select(r => Math.Abs(r.Value(FrequencyError))).Where(v => !double.IsNaN(v)).DefaultIfEmpty(double.NaN).Max();
            double worstZ = rows.Select(r => Math.Abs(r.Value(DampingError))).Where(v => !double.IsNaN(v)).DefaultIfEmpty(double.NaN).Max();
            md.AppendLine();
            md.AppendLine($"Fully resisted mode at every substep count: largest |f/f0 − 1| = {E(worstF)}, largest |ζ/ζ0 − 1| = {E(worstZ)} " +
                          "(exact in exact arithmetic; float32 round-off is ≈ 1e-6 for f and ≈ 1e-5 for ζ, see Documentation~/accuracy.md).");
            return md.ToString();
        }

        static string E(double v) => double.IsNaN(v) ? "–" : v.ToString("0.00E+0", CultureInfo.InvariantCulture);
    }
}
