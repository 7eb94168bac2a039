using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Text;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// "The same material at any frame rate": the Jelly, Rubber and Clay presets at 30, 60 and 120 Hz steps and
    /// 1–32 requested substeps (default substep phase limit): resting height, sag and volume against the preset's
    /// dt → 0 rest, and frequency and damping ratio of a free oscillation against the preset's.
    /// </summary>
    public sealed class ShapeMatchingFrameRateSuite : IScenarioSuite, IScenarioSuiteSummary, IScenarioSuiteFigure, IScenarioSuiteIndependent
    {
        public const string Substeps = "substeps";
        public const string Phase = "wh";
        /// <summary>Resting centre height over the dt → 0 one.</summary>
        public const string HeightRatio = "height/h0";
        /// <summary>Sag (drop of the centre from its undeformed height) over the dt → 0 sag.</summary>
        public const string SagRatio = "sag/sag0";
        /// <summary>|sag/sag0 − 1|, the plotted error.</summary>
        public const string SagError = "sag err";
        /// <summary>(ωh)²/α: the sag ratio the discretisation rule predicts.</summary>
        public const string PredictedSag = "pred (wh)^2/a";
        /// <summary>(sag/sag0) / predicted − 1.</summary>
        public const string SagVersusPrediction = "sag/pred-1";
        /// <summary>det(A_pq A_qq⁻¹) of the body at rest.</summary>
        public const string Volume = "volume";
        /// <summary>Volume ratio over the dt → 0 one, minus 1.</summary>
        public const string VolumeDeviation = "vol/vol0-1";
        public const string FrequencyError = "f/f0-1";
        public const string FrequencyTolerance = "f tol";
        public const string DampingError = "zeta/zeta0-1";
        public const string DampingTolerance = "zeta tol";
        public const string PlasticUpdates = "plastic";
        public const string Resets = "resets";

        public static readonly string[] Presets = { "Jelly", "Rubber", "Clay" };
        public static readonly float[] Rates = { 30f, 60f, 120f };
        public static readonly int[] RequestedSubsteps = { 1, 2, 4, 8, 16, 32 };
        static readonly string[] s_QuickPresets = { "Rubber" };
        static readonly int[] s_QuickSubsteps = { 1, 4 };
        /// <summary>Requested substeps of the default run: the fewest, the middle and the most (the full run adds 2, 8 and 16).</summary>
        static readonly int[] s_StandardSubsteps = { 1, 4, 32 };

        public string Name => "ShapeMatchingFrameRate";

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = $"Whether each preset ({string.Join(", ", Presets)}) rests, sags and wobbles the same at every frame rate ({string.Join(", ", Rates)} Hz) " +
                      "and substep count, and what that costs.",
            Body = $"A {FrameRateStudy.BodySize} m cube of {FrameRateStudy.Edge}³ particles with overlapping {ShapeMatchingBenchmarkBody.ClusterEdge}³ clusters.",
            Material = "The ShapeMatchingMaterial presets, Clay with its plasticity; " +
                       $"{string.Join(", ", RequestedSubsteps)} substeps requested per step, and at least what the default phase limit ωh ≤ {ShapeMatchingParameters.Default.MaxSubstepPhase} rad needs.",
            Load = "Rest: from its rest shape on a floor plane, under gravity until the centre height varies by < 1e-4 of the sag within 0.5 s (2–8 s; no sleeping). " +
                   "Wobble: no gravity, released along its fully resisted mode.",
            Reference = "Rest: the solver's own dt → 0 limit (second-order Richardson from three runs at 1/120 s steps and ωh ≈ 0.2, 0.1, 0.05). " +
                        "Wobble: the preset's frequency and damping ratio.",
            Metric = $"One item is one particle-step (all substeps); the figure's cost is µs per particle per simulated second. '{Substeps}' = substeps taken, '{Phase}' = ωh of one; " +
                     $"'…0' = the dt → 0 value; sag = drop of the centre from its undeformed height; '{SagError}' = |sag/sag0 − 1| (plotted).",
            Notes = new[]
            {
                $"'{PredictedSag}': the sag ratio the discretisation rule predicts ((ωh)²/α), '{SagVersusPrediction}' the sag against it (not for plastic Clay, whose rest shape flows); " +
                $"'{Volume}' = det(A_pq A_qq⁻¹) at rest, '{VolumeDeviation}' against the dt → 0 one.",
                $"'{FrequencyError}', '{DampingError}': the fitted wobble against the preset's (aliased phase unfolded above Nyquist: Rubber at 30 Hz), within '{FrequencyTolerance}', " +
                $"'{DampingTolerance}' (float32 and fit); '{PlasticUpdates}': plastic updates of the rest run (Clay yields under its weight).",
                $"Default run: {string.Join(", ", s_StandardSubsteps)} substeps requested. Quick run: {string.Join(", ", s_QuickPresets)} at {string.Join(" and ", s_QuickSubsteps)} substeps.",
            },
            Details = "accuracy.md#frame-rate-the-same-material-at-30-60-and-120-hz",
        };

        public string ErrorMetricForPlot => SagError;

        /// <summary>"Jelly, 30 Hz": one line per preset and frame rate, through the requested substep counts.</summary>
        public string Series(ScenarioOutcome row) => row.Method.Substring(0, row.Method.LastIndexOf(','));
        public string PointLabel(ScenarioOutcome row) => row.Value(Substeps) == 1 ? "1 substep" : $"{row.Value(Substeps):0} substeps";
        public string CostLabel => "µs per particle per simulated second, median (steps of 1/rate)";
        /// <summary>ns per particle-step × steps per second: comparable across frame rates.</summary>
        public double Cost(ScenarioOutcome row) => row.NsPerItem * RateOf(row) * 1e-3;

        static double RateOf(ScenarioOutcome row)
        {
            string[] parts = row.Method.Split(',');
            return double.Parse(parts[1].Trim().Split(' ')[0], CultureInfo.InvariantCulture);
        }

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            foreach (string preset in quick ? s_QuickPresets : Presets)
            foreach (float rate in Rates)
            foreach (int n in quick ? s_QuickSubsteps : scope == RunScope.Standard ? s_StandardSubsteps : RequestedSubsteps)
                yield return new ShapeMatchingFrameRateScenario(preset, rate, n);
        }

        /// <summary>
        /// The allowed |sag/sag0 − 1| of a preset at the default phase limit: the rule's bound at ωh = 0.5
        /// (<see cref="AccuracyTolerances.SagBound"/>), widened by the small-sag allowance sag0/size of it, the reference's
        /// uncertainty and the row's float32 dead band.
        /// </summary>
        public static double SagTolerance(double zeta, double sagOverSize, double referenceUncertainty, double deadBand) =>
            AccuracyTolerances.SagBound(zeta, ShapeMatchingParameters.Default.MaxSubstepPhase) * (1 + sagOverSize) + referenceUncertainty + deadBand;

        /// <summary>
        /// The allowed |sag/pred − 1| of an elastic preset: the sag scales as 1/ω² only for a small sag, and the next order
        /// changes the ratio by about (sag0/size)·|pred − 1|; plus the reference's uncertainty and the row's float32 dead band.
        /// </summary>
        public static double PredictionTolerance(double predicted, double sagOverSize, double referenceUncertainty, double deadBand) =>
            sagOverSize * Math.Abs(predicted - 1) + referenceUncertainty + deadBand;

        /// <summary>The float32 dead band of a row (relative sag, <see cref="AccuracyTolerances.RestingDeadBand"/>) from its ωh.</summary>
        public static double DeadBand(FrameRateStudy study, double phase)
        {
            double omega = 2 * Math.PI * study.Material.Frequency;
            return AccuracyTolerances.RestingDeadBand(study.Reference.Extent, study.Material.DampingRatio, omega, RestingSag.Gravity, phase / omega);
        }

        public string Summary(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            var md = new StringBuilder();
            md.AppendLine("Frame-rate table: every row of a preset, against the stated tolerances " +
                          "(sag: the rule's bound at ωh = 0.5, (0.5)²/α(0.5) − 1, widened by sag0/size of itself, the dt → 0 reference's uncertainty and the " +
                          "row's float32 dead band; sag against the rule's prediction: (sag0/size)·|pred − 1| + the same two; f and ζ: float32 coefficient " +
                          "rounding + 5 fit standard errors at the position-rounding noise, per row; Documentation~/accuracy.md derives each term):");
            md.AppendLine();
            md.AppendLine("| preset | f, ζ, β | substeps taken | ωh | sag0 (mm, ± relative uncertainty) | sag/sag0 − 1 | sag tolerance (at the largest ωh) | max \\|sag/pred − 1\\| (its row's tolerance) | volume (dt → 0) | max \\|vol/vol0 − 1\\| | max \\|f/f0 − 1\\| (largest tolerance) | max \\|ζ/ζ0 − 1\\| (largest tolerance) | spread over 30/60/120 Hz: sag, f, ζ | meets all |");
            md.AppendLine("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|");
            foreach (var group in rows.GroupBy(r => r.Method.Split(',')[0].Trim()))
            {
                string preset = group.Key;
                FrameRateStudy study = FrameRateStudy.For(preset);
                RestingSagReference reference = study.Reference;
                double size = FrameRateStudy.BodySize;
                double sagOverSize = reference.Deflection / size, uncertainty = reference.Uncertainty;
                bool plastic = study.Material.Plasticity.Enabled;
                var list = group.ToList();
                double Min(string m) => list.Select(r => r.Value(m)).Where(v => !double.IsNaN(v)).DefaultIfEmpty(double.NaN).Min();
                double Max(string m) => list.Select(r => r.Value(m)).Where(v => !double.IsNaN(v)).DefaultIfEmpty(double.NaN).Max();
                double MaxAbs(string m) => list.Select(r => Math.Abs(r.Value(m))).Where(v => !double.IsNaN(v)).DefaultIfEmpty(double.NaN).Max();
                // The tolerance is largest at the smallest ωh (dead band): quote the one at the largest ωh, where the error is.
                double sagTolerance = SagTolerance(study.Material.DampingRatio, sagOverSize, uncertainty, DeadBand(study, Max(Phase)));
                bool sagOk = list.All(r => Math.Abs(r.Value(SagRatio) - 1)
                                           <= SagTolerance(study.Material.DampingRatio, sagOverSize, uncertainty, DeadBand(study, r.Value(Phase))));
                // The largest deviation from the rule and the tolerance of its row; the check is row by row.
                double worstPrediction = 0, predictionTolerance = 0;
                bool predictionOk = true;
                foreach (ScenarioOutcome r in list)
                {
                    double tolerance = PredictionTolerance(r.Value(PredictedSag), sagOverSize, uncertainty, DeadBand(study, r.Value(Phase)));
                    double deviation = Math.Abs(r.Value(SagVersusPrediction));
                    predictionOk &= deviation <= tolerance;
                    if (deviation >= worstPrediction)
                    {
                        worstPrediction = deviation;
                        predictionTolerance = tolerance;
                    }
                }
                bool wobbleOk = list.All(r => !(Math.Abs(r.Value(FrequencyError)) > r.Value(FrequencyTolerance))
                                             && !(Math.Abs(r.Value(DampingError)) > r.Value(DampingTolerance)))
                                && list.All(r => !double.IsNaN(r.Value(FrequencyError)));
                bool resetsOk = list.All(r => r.Value(Resets) == 0);
                // Spread over the frame rates at the same requested substep count.
                double sagSpread = 0, fSpread = 0, zSpread = 0;
                foreach (var same in list.GroupBy(r => r.Method.Substring(r.Method.LastIndexOf(',') + 1)))
                {
                    sagSpread = Math.Max(sagSpread, Spread(same, SagRatio));
                    fSpread = Math.Max(fSpread, Spread(same, FrequencyError));
                    zSpread = Math.Max(zSpread, Spread(same, DampingError));
                }
                bool all = sagOk && (plastic || predictionOk) && wobbleOk && resetsOk;
                md.AppendLine($"| {preset} | {F(study.Material.Frequency, "0.##")} Hz, {F(study.Material.DampingRatio, "0.##")}, {F(study.Material.Beta, "0.##")}{(plastic ? ", plastic" : "")} " +
                              $"| {Min(Substeps)}–{Max(Substeps)} | {F(Min(Phase), "0.000")}–{F(Max(Phase), "0.000")} " +
                              $"| {F(1e3 * reference.Deflection, "0.00")} (±{E(uncertainty)}) | {Signed(Min(SagRatio) - 1)} … {Signed(Max(SagRatio) - 1)} | {E(sagTolerance)} " +
                              $"| {(plastic ? $"{E(worstPrediction)} (n/a: plastic)" : $"{E(worstPrediction)} ({E(predictionTolerance)})")} " +
                              $"| {F(reference.VolumeRatio, "0.0000")} | {E(MaxAbs(VolumeDeviation))} " +
                              $"| {E(MaxAbs(FrequencyError))} ({E(Max(FrequencyTolerance))}) | {E(MaxAbs(DampingError))} ({E(Max(DampingTolerance))}) " +
                              $"| {E(sagSpread)}, {E(fSpread)}, {E(zSpread)} | {(all ? "yes" : "**no**")} |");
            }
            md.AppendLine();
            md.AppendLine("Bound of the sag error at the default phase limit, (0.5)²/α(0.5, ζ) − 1 = ζ·0.5 + (1/12 + ζ²/3)·0.25 + …: " +
                          string.Join(", ", Presets.Select(p => $"{p} {E(AccuracyTolerances.SagBound(FrameRateStudy.MaterialOf(p).DampingRatio, 0.5))}")) + ". " +
                          "A finer MaxSubstepPhase φ lowers it to ≈ ζφ; frequency and decay of the fully resisted modes do not depend on it.");
            return md.ToString();
        }

        static double Spread(IEnumerable<ScenarioOutcome> rows, string metric)
        {
            var values = rows.Select(r => r.Value(metric)).Where(v => !double.IsNaN(v)).ToList();
            return values.Count > 1 ? values.Max() - values.Min() : 0;
        }

        static string F(double v, string format) => double.IsNaN(v) ? "–" : v.ToString(format, CultureInfo.InvariantCulture);
        static string E(double v) => double.IsNaN(v) ? "–" : v.ToString("0.0E+0", CultureInfo.InvariantCulture);
        static string Signed(double v) => double.IsNaN(v) ? "–" : v.ToString("+0.0000;−0.0000;0", CultureInfo.InvariantCulture);
    }
}
