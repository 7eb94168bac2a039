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
    public sealed class ShapeMatchingConvergenceSuite : IScenarioSuite, IScenarioSuiteSummary, IScenarioSuiteFigure
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

        public SuiteDefinition Definition => new SuiteDefinition { Notes = new[] { LegacyDescription } };

        string LegacyDescription =>
            $"A {ConvergenceStudy.BodySize} m cube of {ConvergenceStudy.Edge}³ = {ConvergenceStudy.Edge * ConvergenceStudy.Edge * ConvergenceStudy.Edge} particles " +
            $"({ShapeMatchingBenchmarkBody.Frequency} Hz, ζ = {ShapeMatchingBenchmarkBody.DampingRatio}, β = {ShapeMatchingBenchmarkBody.Beta}, no gravity), " +
            "as one cluster or as 8 overlapping 4³ clusters, squashed to 0.8 of its height (x, z stretched to keep the volume), twisted by 0.3 rad " +
            "and jittered by ±5 % of the spacing, released at rest and followed for 1 s at 1/60 s steps with 1, 2, 4, 8, 16 and 32 substeps " +
            "(exactly: the substep phase limit is lifted; quick run: 1, 4, 16 for two families). " +
            $"'{TrajectoryError}' is the RMS over particles and over the 60 frames of |x_solver − x_ref| over the body size, where x_ref is a " +
            "float64 classical RK4 integration of the continuous model the solver discretises, ẍᵢ = ω² P(g(x) − x)ᵢ − 2ζω (ẋᵢ − uᵢ) " +
            "(goals g of the current positions in the same mode and layout, P the momentum- and torque-free projection, u the body's rigid velocity), " +
            "from the same float32 start: the error is the discretisation error of the substep, and it must fall as the cost grows. " +
            $"'{Order}' is the observed order against the previous substep count, ln(e_prev/e)/ln(n/n_prev): the substep is first order " +
            "(its velocity lags half a substep and the goals are taken at the start of the substep), so it tends to 1 as ωh → 0. " +
            $"'{ReferenceChange}' is how much the reference moves when its RK4 step (1/{60 * 2 * ConvergenceStudy.ReferenceStepsPerFrame} s) is halved, " +
            "an upper bound of its own error (Richardson: ≈ 15× its error for a 4th-order method): it must be far below every solver error. " +
            $"'{Phase}' is ωh per substep. '{FrequencyError}' and '{DampingError}' come from a separate free oscillation (no gravity) of the body's " +
            "fully resisted mode: every particle displaced along x by 2 % of the size times a pattern of its x plane that no cluster's goals can follow, " +
            "so the continuous model is exactly ÿ = −ω²y − 2ζωẏ; frequency and damping ratio are fitted from the sampled amplitude by linear prediction " +
            "(Prony, exact for a damped oscillation) and compared with the parameters. The solver's substep has the oscillator's exact eigenvalues, " +
            "so these must be float32 round-off (≈ 1e-6) at every substep count. Quadratic goals on 4-plane overlapping clusters follow every such " +
            "pattern (no fully resisted mode of that form exists), so that family has no frequency columns. One item is one particle-step " +
            "(a particle through a whole step, all substeps included), so ns/item grows with the substep count.";

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
            int[] counts = quick ? QuickSubstepCounts : SubstepCounts;
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
            int[] counts = quick ? QuickSubstepCounts : SubstepCounts;
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
