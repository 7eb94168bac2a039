using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Fluid accuracy against cost: the Martin &amp; Moyce dam break for each solver × setting × resolution (front error
    /// against ms per 1/60 s of flow, the figure), the hydrostatic column, and the droplet (flocking against Akinci
    /// cohesion).
    /// </summary>
    public sealed class FluidAccuracySuite : IScenarioSuite, IScenarioSuiteSummary, IScenarioSuiteFigure, IScenarioSuiteFindings, IScenarioSuiteIndependent
    {
        /// <summary>Dam-break resolutions (particles across the column width a) of the full run.</summary>
        public static readonly int[] Resolutions = { 10, 20, 40 };
        /// <summary>
        /// The finest resolution runs only the cheapest setting of each solver (c₀ = 5·v, 2 iterations): a run there costs
        /// eight times one at half the resolution (four times the particles, twice the substeps), about 30 s here.
        /// </summary>
        public const int FinestResolution = 40;
        /// <summary>Weakly compressible speeds of sound, as multiples of the column's √(2g·2a).</summary>
        public static readonly float[] SoundMultiples = { 5f, 10f, 20f };
        /// <summary>Position-based iteration counts.</summary>
        public static readonly int[] Iterations = { 2, 4, 8 };
        /// <summary>Position-based iteration counts of the hydrostatic rows (full run): the default, and enough for the 16-layer column to come to rest at one substep per 1/60 s frame.</summary>
        public static readonly int[] HydrostaticIterations = { 4, 16 };
        /// <summary>Columns of the default row's ensemble in the default run (8 in the full run; <see cref="HydrostaticColumnScenario"/>).</summary>
        public const int HydrostaticMembers = 4;
        /// <summary>Finest dam-break resolution of the default run, where only the cheapest setting of each solver runs (a run there takes 5–25 s).</summary>
        public const int StandardFinestResolution = 20;
        /// <summary>
        /// Seconds the hydrostatic columns settle before they are measured, in the default and the full run: after 3 s the weakly
        /// compressible column's pressure gradient is still 18 % off (8 % at 10 s), so a shorter default would misstate it.
        /// </summary>
        public const float SettleSeconds = 10f;
        /// <summary>Front error (RMS of Z) a row must reach to count in the summary: the experiment's ±0.07 band in T times the late front speed dZ/dT ≈ 1.4.</summary>
        public const double FrontTolerance = 0.1;

        public string Name => "FluidAccuracy";

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "How close each fluid solver and setting comes to a dam-break experiment, a hydrostatic column and a rounding droplet, at what cost per " +
                      "particle-substep, and whether it survives hard cases.",
            Body = $"Dam break: Martin & Moyce's n² = 2 column (a = {MartinMoyce1952.ColumnWidth} m wide, 2a high) in a 6a × 3a tank, a slab four particles deep between " +
                   $"free-slip walls, at a/{string.Join(", a/", Resolutions)}; hydrostatic column: 0.3 × 0.4 × 0.3 m at Δx = 2.5 cm; droplet: a 10 cm cube of 1000 particles; " +
                   "hard cases: 1000 particles in a 0.4 m box at Δx = 2 cm.",
            Material = $"Water. WCSPH: Tait γ = 7, artificial viscosity α = {FluidParameters.Default.ArtificialViscosity}, c₀ = {string.Join(", ", SoundMultiples)}·v, " +
                       $"v = √(2g·2a) = {DamBreakScenario.ReferenceSpeed:0.00} m/s (column: 10·√(2gH) and the default {FluidParameters.Default.SpeedOfSound:0} m/s; droplet: 5 m/s). PBF: {string.Join(", ", Iterations)} iterations " +
                       $"(column: {string.Join(", ", HydrostaticIterations)}). CFL {FluidParameters.Default.CflNumber}.",
            Load = $"Gravity. Dam break: released at rest, run to T = t√(2g/a) = {DamBreakScenario.EndT} in {1000 * DamBreakScenario.FrameSeconds} ms frames; " +
                   $"column: settled {SettleSeconds:0} s in 1/60 s frames, then measured; droplet: no gravity, 2 s with no cohesion (also without viscosity), " +
                   $"flocking ({string.Join(", ", FlockingWeights)}/s²) or Akinci (γ = {string.Join(", ", AkinciTensions)}); hard cases: each its own.",
            Reference = $"Dam break: Martin & Moyce's Table 2 front ({MartinMoyce1952.T.Length} points, T = {MartinMoyce1952.T[0]}…{DamBreakScenario.LastTableT}) and " +
                        $"Table 6 residual column height ({DamBreakScenario.HeightPoints} points, τ = t√(g/a) = {MartinMoyce1952.Tau[0]}…{MartinMoyce1952.Tau[DamBreakScenario.HeightPoints - 1]}); " +
                        "column: hydrostatic p = ρ₀g(H − y) in the interior (2h from walls, floor and surface); droplet: a ball (sphericity 1); hard cases: finite and in the box.",
            Metric = "One item is one particle-substep (a step is a whole run). Front error = RMS of Z_sim − Z_data over the table, Z = x/a, front = leading edge of the " +
                     "particles with ≥ 4 neighbours; height error = RMS of H_sim − H_data, H = the bulk's height at the back wall over 2a; " +
                     "'density error' = mean |ρ/ρ₀ − 1| of the bulk over the run's frames.",
            Notes = new[]
            {
                "Dam break: '(shifted)' uses the best time shift in [0, 0.2] (the gate's opening; the experiment's own band is ±0.07 in T); 'late front speed' = " +
                $"least-squares dZ/dT over {DamBreakScenario.LateT} ≤ T ≤ {DamBreakScenario.LastTableT} (inviscid ideal 2); 'shared shift' is the one shift in [0, 0.2] " +
                $"that minimises front² + height²; a/{FinestResolution} runs only the cheapest setting of each solver; 'floor μ' rows make the bed a Coulomb wall " +
                $"(DomainFriction.y = {FloorFriction:0}) with the slab's side faces still free-slip (default and full runs, up to a/{StandardFinestResolution}).",
                "Column: pressure gradient, L2 and scatter errors against ρ₀g(H − y), 'zero-pressure depth' where the fitted line reaches 0 below the top, 'surface drift' " +
                $"from 1 s on. Droplet: 'sphericity' = smallest over largest width of the cloud over {DropletScenario.DirectionCount} directions (the cube: 0.60); " +
                $"'time to round' = first time at {DropletScenario.RoundSphericity}.",
                "Hard cases: 1000 particles (one for the isolated particle); the counters are the step report's particle-substeps summed over the run.",
                $"Default run: a/10 with every setting, a/{StandardFinestResolution} with the cheapest of each solver, " +
                $"the WCSPH column at the default c₀ only (the 28 m/s and position-based columns take about 80 and 30–50 s of settling here: 600 frames at their ms per step), " +
                $"droplets without cohesion (with water's viscosity and without the viscosity pass), with flocking at {FlockingWeights[0]}/s² and Akinci at γ = {AkinciTensions[0]}. " +
                "Quick run: a/10 with one setting per solver, the default-c₀ WCSPH column settled 0.5 s, one flocking droplet for 1 s, three WCSPH hard cases.",
            },
            Details = "fluids.md#validation-and-the-study",
        };

        public string ErrorMetricForPlot => "front RMS error (shifted)";

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            bool standard = scope == RunScope.Standard;
            foreach (int resolution in quick ? new[] { 10 } : Resolutions)
            {
                if (standard && resolution > StandardFinestResolution)
                    break;
                bool finest = resolution == (standard ? StandardFinestResolution : FinestResolution);
                foreach (float multiple in quick ? new[] { 5f } : finest ? new[] { SoundMultiples[0] } : SoundMultiples)
                    yield return new DamBreakScenario(resolution, Weak(multiple * DamBreakScenario.ReferenceSpeed), $"c0 = {multiple:0}·v");
                foreach (int iterations in quick ? new[] { 4 } : finest ? new[] { Iterations[0] } : Iterations)
                    yield return new DamBreakScenario(resolution, PositionBased(iterations), $"{iterations} it");
                if (!quick && resolution <= StandardFinestResolution)
                {
                    // The bed as a Coulomb wall at the model's strongest grip (the slab's side faces stay free-slip).
                    FluidParameters gripping = Weak(SoundMultiples[0] * DamBreakScenario.ReferenceSpeed);
                    gripping.DomainFriction = new Unity.Mathematics.float3(0f, FloorFriction, 0f);
                    yield return new DamBreakScenario(resolution, gripping, $"c0 = {SoundMultiples[0]:0}·v, floor μ = {FloorFriction:0}");
                }
            }
            float settle = quick ? 0.5f : SettleSeconds;
            yield return new HydrostaticColumnScenario(Weak(FluidParameters.Default.SpeedOfSound), "c0 = 10 m/s (default)", settle,
                members: quick ? 1 : scope == RunScope.Full ? 8 : HydrostaticMembers);
            if (scope == RunScope.Full)
            {
                // Half the spacing: the gradient against the fluid's own density falls with resolution.
                yield return new HydrostaticColumnScenario(Weak(FluidParameters.Default.SpeedOfSound), "c0 = 10 m/s (default), Δx = 1.25 cm", settle,
                    HydrostaticColumnScenario.DefaultSpacing / 2f);
                yield return new HydrostaticColumnScenario(Weak(10f * HydrostaticColumnScenario.ReferenceSpeed), "c0 = 10·v", settle);
            }
            if (scope == RunScope.Full)
                foreach (int iterations in HydrostaticIterations)
                    yield return new HydrostaticColumnScenario(PositionBased(iterations), $"{iterations} it", settle);
            foreach (var (parameters, setting) in Droplets(scope))
                yield return new DropletScenario(parameters, setting, quick ? 1f : 2f);
            foreach (IScenario hardCase in FluidHardCaseScenario.All(quick))
                yield return hardCase;
        }

        static FluidParameters Weak(float speedOfSound)
        {
            FluidParameters p = FluidParameters.Default;
            p.Solver = FluidSolverKind.WeaklyCompressible;
            p.SpeedOfSound = speedOfSound;
            p.ViscosityIterations = 1;
            return p;
        }

        static FluidParameters PositionBased(int iterations)
        {
            FluidParameters p = FluidParameters.Default;
            p.Solver = FluidSolverKind.PositionBased;
            p.PressureIterations = iterations;
            p.ViscosityIterations = 1;
            return p;
        }

        /// <summary>
        /// Droplet rows: no cohesion (the control), flocking at two cohesion weights and Akinci at two γ; the default run takes
        /// the first weight and γ (each compared with the control for the cost of cohesion), the quick run the first flocking row.
        /// </summary>
        static IEnumerable<(FluidParameters, string)> Droplets(RunScope scope)
        {
            bool quick = scope == RunScope.Quick, full = scope == RunScope.Full;
            FluidParameters none = Weak(5f);
            if (!quick)
            {
                yield return (none, "no cohesion");
                // The same drop without the implicit viscosity pass: what water's viscosity costs (the Effects summary).
                FluidParameters inviscid = none;
                inviscid.Viscosity = 0f;
                yield return (inviscid, FluidFindings.InviscidDroplet);
            }
            foreach (float weight in full ? FlockingWeights : new[] { FlockingWeights[0] })
            {
                FluidParameters flocking = none;
                flocking.Cohesion = FluidCohesionModel.Flocking;
                flocking.CohesionWeight = weight;
                flocking.AlignmentRate = 2f;
                yield return (flocking, $"flocking ({weight:0}/s², align 2/s)");
            }
            if (quick)
                yield break;
            foreach (float tension in full ? AkinciTensions : new[] { AkinciTensions[0] })
            {
                FluidParameters akinci = none;
                akinci.Cohesion = FluidCohesionModel.Akinci;
                akinci.SurfaceTension = tension;
                yield return (akinci, $"Akinci (γ = {tension.ToString("0.###", CultureInfo.InvariantCulture)})");
            }
        }

        /// <summary>Coulomb μ of the bed in the floor-friction dam-break rows (the largest the model takes).</summary>
        public const float FloorFriction = 1f;

        /// <summary>Flocking cohesion weights (1/s²) of the droplet rows.</summary>
        public static readonly float[] FlockingWeights = { 50f, 200f };
        /// <summary>Akinci γ of the droplet rows.</summary>
        public static readonly float[] AkinciTensions = { 0.05f, 0.2f };

        public string Series(ScenarioOutcome row) => FluidScene.SeriesOf(row.Method);

        public string PointLabel(ScenarioOutcome row) => FluidScene.PointOf(row.Method);

        public string CostLabel => "ms per 1/60 s of simulated flow (whole scene, all substeps), median";

        /// <summary>The figure's cost: the whole scene per 1/60 s of flow, so a finer resolution (more particles, more substeps) shows its price.</summary>
        public double Cost(ScenarioOutcome row) => FluidFindings.DamBreakFrameMs(row);

        public IEnumerable<Finding> Findings(IReadOnlyList<ScenarioOutcome> rows, RunScope scope) => FluidFindings.Findings(rows);

        public string Summary(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            var md = new StringBuilder();
            DamBreakSummary(md, rows);
            HydrostaticSummary(md, rows);
            DropletSummary(md, rows);
            HardCaseSummary(md, rows);
            return md.ToString();
        }

        static string F(string format, params object[] args) => string.Format(CultureInfo.InvariantCulture, format, args);

        /// <summary>Milliseconds of a whole run: ns per item × items per run.</summary>
        static double RunMs(ScenarioOutcome r) => r.NsPerItem * r.ItemsPerStep * 1e-6;

        void DamBreakSummary(StringBuilder md, IReadOnlyList<ScenarioOutcome> rows)
        {
            var dam = new List<ScenarioOutcome>();
            foreach (ScenarioOutcome r in rows)
                if (!double.IsNaN(r.Value("front RMS error (shifted)")))
                    dam.Add(r);
            if (dam.Count == 0)
                return;
            double dataSpeed = DamBreakScenario.FrontSpeed(MartinMoyce1952.T, MartinMoyce1952.Z, MartinMoyce1952.T.Length, DamBreakScenario.LateT, DamBreakScenario.LastTableT);
            md.AppendLine(F("| Dam break | front error | shifted (shift) | height error | front / height, shared shift (shift) | Z at T = 3.33 (data 4.11) | dZ/dT for T ≥ 2 (data {0:0.00}) | density error | ns per particle-substep | ms per run | max substeps per 2 ms frame |", dataSpeed));
            md.AppendLine("|---|---|---|---|---|---|---|---|---|---|---|");
            foreach (ScenarioOutcome r in dam)
                md.AppendLine(F("| {0} | {1:0.000} | {2:0.000} ({3:0.00}) | {4:0.000} | {5:0.000} / {6:0.000} ({7:0.00}) | {8:0.00} | {9:0.00} | {10:0.00} % | {11:0} | {12:0} | {13:0} |",
                    r.Method, r.Value("front RMS error"), r.Value("front RMS error (shifted)"), r.Value("shift"), r.Value("height RMS error"),
                    r.Value("front RMS error (shared shift)"), r.Value("height RMS error (shared shift)"), r.Value("shared shift"), r.Value("Z at T=3.33"),
                    r.Value("late front speed"), 100 * r.Value("density error"), r.NsPerItem, RunMs(r), r.Value("max substeps per frame")));
            md.AppendLine();

            // Front error per resolution: one line per setting, one column per resolution.
            var series = new List<string>();
            var labels = new List<string>();
            foreach (ScenarioOutcome r in dam)
            {
                if (!series.Contains(Series(r)))
                    series.Add(Series(r));
                if (!labels.Contains(PointLabel(r)))
                    labels.Add(PointLabel(r));
            }
            md.Append("| Front error, unshifted / shifted |");
            foreach (string l in labels)
                md.Append(' ').Append(l).Append(" |");
            md.AppendLine();
            md.Append("|---|");
            foreach (string _ in labels)
                md.Append("---|");
            md.AppendLine();
            foreach (string name in series)
            {
                md.Append("| ").Append(name).Append(" |");
                foreach (string l in labels)
                {
                    ScenarioOutcome? found = null;
                    foreach (ScenarioOutcome r in dam)
                        if (Series(r) == name && PointLabel(r) == l)
                            found = r;
                    md.Append(found == null ? " – |" : F(" {0:0.000} / {1:0.000} |", found.Value.Value("front RMS error"), found.Value.Value("front RMS error (shifted)")));
                }
                md.AppendLine();
            }
            md.AppendLine();

            // Ranking by the shifted front error, and the cheapest whole run within the tolerance with and without the shift.
            var ranked = new List<ScenarioOutcome>(dam);
            ranked.Sort((a, b) => a.Value("front RMS error (shifted)").CompareTo(b.Value("front RMS error (shifted)")));
            md.Append("Ranking by shifted front error: ");
            for (int k = 0; k < ranked.Count; k++)
                md.Append(F("{0}{1}. {2} ({3:0.000}, {4:0} ms)", k == 0 ? "" : "; ", k + 1, ranked[k].Method, ranked[k].Value("front RMS error (shifted)"), RunMs(ranked[k])));
            md.AppendLine(".");
            md.AppendLine();
            foreach (string metric in new[] { "front RMS error (shifted)", "front RMS error" })
            {
                ScenarioOutcome? cheapest = null;
                foreach (ScenarioOutcome r in dam)
                    if (r.Value(metric) <= FrontTolerance && (cheapest == null || RunMs(r) < RunMs(cheapest.Value)))
                        cheapest = r;
                string what = metric == "front RMS error" ? "without a time shift" : "with the best shift ≤ 0.2";
                md.AppendLine(cheapest != null
                    ? F("- Cheapest run within {0} in Z {1}: {2}, {3:0} ms for the whole run (error {4:0.000}).",
                        FrontTolerance, what, cheapest.Value.Method, RunMs(cheapest.Value), cheapest.Value.Value(metric))
                    : F("- No run came within {0} in Z {1}.", FrontTolerance, what));
            }
            md.AppendLine();
        }

        static void HydrostaticSummary(StringBuilder md, IReadOnlyList<ScenarioOutcome> rows)
        {
            bool header = false;
            foreach (ScenarioOutcome r in rows)
            {
                if (double.IsNaN(r.Value("surface drift")))
                    continue;
                if (!header)
                {
                    md.AppendLine("| Hydrostatic column | pressure gradient error (ρ₀g), mean ± SD | against its own density (ρ̄g) | pressure L2 error | scatter about the fitted line | depth of p = 0 below the surface (mm) | density error | kinetic energy (J/kg) | surface drift (mm) | lost |");
                    md.AppendLine("|---|---|---|---|---|---|---|---|---|---|");
                    header = true;
                }
                double depth = r.Value("zero-pressure depth");
                md.AppendLine(F("| {0} | {1} | {2} | {3} | {4} | {5} | {6:0.00} % | {7:0.0e+0} | {8:0.0} | {9:0} |", Members(r),
                    WithSpread(r, "pressure gradient error"), WithSpread(r, "pressure gradient error (own density)"), Percent(r.Value("pressure L2 error")), Percent(r.Value("pressure scatter")), double.IsNaN(depth) ? "–" : F("{0:0}", depth),
                    100 * r.Value("density error"), r.Value("kinetic energy"), r.Value("surface drift"), r.Value("particles lost")));
            }
            if (header)
                md.AppendLine();
        }

        static string Percent(double fraction) => double.IsNaN(fraction) ? "–" : F("{0:0.0} %", 100 * fraction);

        /// <summary>A gradient error as "mean ± spread" over the row's ensemble (the mean alone for one column).</summary>
        static string WithSpread(ScenarioOutcome r, string metric)
        {
            double spread = r.Value(metric + " spread");
            return double.IsNaN(spread) || double.IsNaN(r.Value(metric)) ? Percent(r.Value(metric)) : F("{0} ± {1:0.0}", Percent(r.Value(metric)), 100 * spread);
        }

        static string Members(ScenarioOutcome r)
        {
            double members = r.Value("ensemble members");
            return members > 1 ? F("{0} ({1:0} columns)", r.Method, members) : r.Method;
        }

        static void DropletSummary(StringBuilder md, IReadOnlyList<ScenarioOutcome> rows)
        {
            bool header = false;
            foreach (ScenarioOutcome r in rows)
            {
                if (double.IsNaN(r.Value("sphericity")))
                    continue;
                if (!header)
                {
                    md.Append("| Droplet | sphericity at 0 s |");
                    foreach (double t in DropletScenario.ReportTimes)
                        md.Append(F(" {0:0.##} s |", t));
                    md.AppendLine(F(" end | time to {0:0.##} | radius error | density error | RMS speed (m/s) | ms per run |", DropletScenario.RoundSphericity));
                    md.Append("|---|---|");
                    foreach (double _ in DropletScenario.ReportTimes)
                        md.Append("---|");
                    md.AppendLine("---|---|---|---|---|---|");
                    header = true;
                }
                md.Append(F("| {0} | {1:0.000} |", r.Method, r.Value("sphericity at 0 s")));
                foreach (double t in DropletScenario.ReportTimes)
                    md.Append(F(" {0:0.000} |", r.Value(F("sphericity at {0:0.##} s", t))));
                double round = r.Value("time to round");
                md.AppendLine(F(" {0:0.000} | {1} | {2:+0.0;−0.0} % | {3:0.00} % | {4:0.0e+0} | {5:0} |", r.Value("sphericity"),
                    double.IsNaN(round) ? "not reached" : F("{0:0.00} s", round), 100 * r.Value("radius error"), 100 * r.Value("density error"), r.Value("RMS speed"), RunMs(r)));
            }
            if (header)
                md.AppendLine();
        }

        static void HardCaseSummary(StringBuilder md, IReadOnlyList<ScenarioOutcome> rows)
        {
            bool header = false;
            foreach (ScenarioOutcome r in rows)
            {
                if (double.IsNaN(r.Value("invalid removed")))
                    continue;
                if (!header)
                {
                    md.AppendLine("| Hard case | finite, in box | alive | invalid removed | max speed (m/s) | speed clamped | over-compressed | neighbour overflow | max ρ/ρ₀ (after frame 1) | substeps wanted / run | time simulated | spread (Δx) |");
                    md.AppendLine("|---|---|---|---|---|---|---|---|---|---|---|---|");
                    header = true;
                }
                double fall = r.Value("free-fall error");
                md.AppendLine(F("| {0} | {1}, {2} | {3:0} | {4:0} | {5:0.00} | {6:0} | {7:0} | {8:0} | {9:0.00} ({10:0.00}) | {11:0} / {12:0} | {13:0.###} | {14} |", r.Method,
                    r.Value("finite") == 1 ? "yes" : "NO", r.Value("in box") == 1 ? "yes" : "NO", r.Value("alive"), r.Value("invalid removed"),
                    r.Value("max speed"), r.Value("speed clamped"), r.Value("over-compressed"), r.Value("neighbour overflow"), r.Value("max density ratio"),
                    r.Value("late max density ratio"), r.Value("substeps wanted"), r.Value("substeps run"), r.Value("simulated"),
                    double.IsNaN(fall) ? F("{0:0.0}", r.Value("spread")) : F("– (free fall {0:0.00} % off ½gt²)", 100 * fall)));
            }
            if (header)
            {
                md.AppendLine();
                md.AppendLine("Counters are particle-substeps summed over the run; 'substeps wanted / run' is the largest per frame (the cap is 32); " +
                              "'time simulated' is the fraction of the asked time the fluid advanced (below 1: a capped frame ran in slow motion).");
            }
        }
    }
}
