using System;
using System.Collections.Generic;
using System.Text;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// The stability part of the method study: for every method family of <see cref="MethodCatalog"/> at one substep, the
    /// largest stable step of a stiff pinned cube against the explicit limits of the mass-spring network and of FEM, and
    /// what the method does with four hard cases at a game frame. Takes minutes; no error-against-cost figure.
    /// </summary>
    public sealed class MethodStudyStabilitySuite : IScenarioSuite, IScenarioSuiteSummary, IScenarioSuiteFindings, IScenarioSuiteIndependent
    {
        /// <summary>The suite's name (the runner's <c>--filter</c>).</summary>
        public const string SuiteName = "MethodStudyStability";

        static readonly object s_Lock = new object();
        static StabilityCube s_Cube;

        /// <summary>The study's cube (<see cref="StabilityCube.StiffMaterial"/>, 0.1 m, 4³ cells), built once.</summary>
        public static StabilityCube Cube
        {
            get
            {
                lock (s_Lock)
                    return s_Cube ??= new StabilityCube(StabilityCube.StiffMaterial);
            }
        }

        public string Name => SuiteName;
        public string ErrorMetricForPlot => null;

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "How large a step each method survives on a stiff pinned cube, against the explicit stability limit, and what it does with four hard cases.",
            Body = $"A {StabilityCube.DefaultSize} m cube of {StabilityCube.DefaultCells}³ cells of 6 tetrahedra " +
                   $"({(StabilityCube.DefaultCells + 1) * (StabilityCube.DefaultCells + 1) * (StabilityCube.DefaultCells + 1)} particles), bottom face pinned (free for the hard cases).",
            Material = $"Stiff: {StudyScene.MaterialText(StabilityCube.StiffMaterial)}, ζ = {StabilityCube.StiffMaterial.DampingRatio}; " +
                       $"every method at {MethodStudyStabilityScenario.StepKnob} substep per step, so the row measures the integrator.",
            Load = $"Gravity, from a {StabilityCube.DefaultCompression * 100} % compression along y about the bottom face; each dt runs for " +
                   $"max({BoundedRun.MinTime} s, {BoundedRun.MinSteps} steps). Hard cases: no pins, no gravity, {MethodStudyStabilityScenario.HardCaseTime} s of 1/60 s steps at the method's first knob.",
            Reference = $"'{MethodStudyStabilityScenario.Bound}': the explicit limit √(β² + 4/ω_max²) − β of the method's own linearised model " +
                        "(mass-spring network or FEM mesh; ω_max by power iteration, β its Rayleigh coefficient); none for the other methods.",
            Metric = $"One item is one particle through one step of dt_max. '{MethodStudyStabilityScenario.MaxStep}': the largest bounded dt (no reset, finite, kinetic energy " +
                     $"< {StabilityCube.KineticEnergyFactor}×(U₀ + MgL), shape deviation < {StabilityCube.DeformationFactor} sizes), bisected in log space between " +
                     $"{StableStepSearch.MinStep:0e0} and {StableStepSearch.MaxStep} s to a factor {StableStepSearch.Resolution}.",
            Notes = new[]
            {
                $"'{MethodStudyStabilityScenario.Capped}' = 1: bounded at {StableStepSearch.MaxStep} s, the search's cap. '{MethodStudyStabilityScenario.BoundedBelow}' = 1: dt_max/2 and dt_max/4 " +
                $"bounded; '{MethodStudyStabilityScenario.Monotone}' = 1: that, and no dt_max·2ᵏ below {StableStepSearch.MaxStep} s bounded; '{MethodStudyStabilityScenario.BoundedAbove}': the largest that was (ms).",
                $"'{MethodStudyStabilityScenario.FailureReason}' of the smallest failing step: {(int)UnboundedReason.Reset} reset, {(int)UnboundedReason.NonFinite} non-finite, " +
                $"{(int)UnboundedReason.KineticEnergy} kinetic energy, {(int)UnboundedReason.Deformation} deformation.",
                $"Hard cases ('huge step': {HardCases.HugeStep} s steps from a {HardCases.HugeStepCompression * 100} % compression): {(int)HardCaseOutcome.Recovers} recovers " +
                $"(no reset, within {HardCaseRun.RecoveredDeviation * 100} % of the rest shape), {(int)HardCaseOutcome.Reset} reset once then at rest, {(int)HardCaseOutcome.Bounded} bounded " +
                $"(≤ 1 reset, finite, not back), {(int)HardCaseOutcome.Diverged} diverged (more resets, or beyond {HardCaseRun.DivergedDeviation} sizes); " +
                $"'…{MethodStudyStabilityScenario.DeviationSuffix}' = final shape deviation over the cube size.",
                $"Default and quick runs: dt_max/2 and dt_max/4 are not run (for the explicit FEM models they are two thirds to nine tenths of the search's steps), so " +
                $"'{MethodStudyStabilityScenario.BoundedBelow}' and '{MethodStudyStabilityScenario.Monotone}' read –; --full runs them. " +
                "Quick run: only the methods with quick knob values in the catalog; default run: not the methods the catalog runs in --full only (Neo-Hookean quadratic FEM: its stable-step search takes ~40 s).",
            },
            Details = "choosing-a-method.md#stability-the-largest-stable-step-and-the-hard-cases-methodstudystability",
        };

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            bool quick = scope == RunScope.Quick, standard = scope == RunScope.Standard;
            // The quick run keeps the methods the catalog keeps in its quick run (those with quick knob values), the default
            // run those it runs by default (the --full-only methods have no default knob values).
            foreach (MethodVariant v in MethodCatalog.Variants)
                if ((!quick || v.QuickKnobs.Length > 0) && (!standard || v.StandardKnobs.Length > 0))
                    yield return new MethodStudyStabilityScenario(() => Cube, v, checkBelow: scope == RunScope.Full);
        }

        public IEnumerable<Finding> Findings(IReadOnlyList<ScenarioOutcome> rows, RunScope scope) => MethodStudyFindings.HardCases(rows);

        public string Summary(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            StabilityCube cube = Cube;
            var md = new StringBuilder();
            md.AppendLine($"Explicit limits of the cube: mass-spring {Ms(cube.MassSpringExplicitStep)}, FEM {Ms(cube.FemExplicitStep)} " +
                          "(√(β² + 4/ω_max²) − β). † = not monotone: dt_max/2 or dt_max/4 was not bounded, or a step dt_max·2ᵏ above it was " +
                          "(the largest such is given). " +
                          $"Hard cases at the first knob of the catalog, {MethodStudyStabilityScenario.HardCaseTime} s; in brackets the final " +
                          "shape deviation over the cube size, or the resets. 'reset' = the guard reset the body once (the state written, or an " +
                          "explicit method above its stable step blowing up at the first motion) and it then stayed at its rest shape.");
            md.AppendLine();
            ShapeMatchingParameters sm = ShapeMatchingCalibration.For(cube.Pinned.Material, cube.Pinned.CalibrationLength, cube.Pinned.CalibrationLoad,
                ShapeMatchingMode.Linear, ShapeMatchingParameters.Default);
            md.AppendLine($"Shape matching is calibrated for a compact body in compression: f = {sm.Frequency:0} Hz, ζ = {sm.DampingRatio:0.###}.");
            md.AppendLine();
            md.Append("| method | dt_max | explicit bound | inverted | flattened | huge step | NaN input | compute per simulated s at dt_max |");
            md.AppendLine();
            md.AppendLine("|---|---:|---:|---|---|---|---|---:|");
            foreach (ScenarioOutcome r in rows)
            {
                string family = MethodStudyRanking.Family(r.Method);
                double dt = r.Value(MethodStudyStabilityScenario.MaxStep);
                double bound = r.Value(MethodStudyStabilityScenario.Bound);
                bool capped = r.Value(MethodStudyStabilityScenario.Capped) == 1;
                string dtCell = capped ? $"≥ {Ms(dt * 1e-3)} (cap)" : Ms(dt * 1e-3);
                if (!double.IsNaN(bound))
                    dtCell += $" = {(capped ? "≥ " : "")}{Ratio(dt / bound)}× bound";
                if (r.Value(MethodStudyStabilityScenario.Monotone) == 0)
                {
                    double above = r.Value(MethodStudyStabilityScenario.BoundedAbove);
                    var notes = new List<string>();
                    if (r.Value(MethodStudyStabilityScenario.BoundedBelow) == 0)
                        notes.Add("dt_max/2 or /4 not bounded");
                    if (above > 0)
                        notes.Add($"bounded again at {Ms(above * 1e-3)}");
                    dtCell += $" † ({string.Join("; ", notes)})";
                }
                md.Append($"| {family} | {dtCell} | {(double.IsNaN(bound) ? "–" : Ms(bound * 1e-3))} |");
                foreach (HardCase c in HardCases.All)
                    md.Append($" {Case(r, HardCases.Label(c))} |");
                // µs per step of the whole body over the step: compute per simulated second.
                double perSecond = r.NsPerItem * r.Value(StudyScene.Particles) * 1e-9 / (dt * 1e-3);
                md.AppendLine($" {Seconds(perSecond)} |");
            }
            return md.ToString();
        }

        static string Case(ScenarioOutcome r, string label)
        {
            double code = r.Value(label);
            if (double.IsNaN(code))
                return "–";
            var outcome = (HardCaseOutcome)(int)code;
            double dev = r.Value(label + MethodStudyStabilityScenario.DeviationSuffix);
            double resets = r.Value(label + MethodStudyStabilityScenario.ResetsSuffix);
            string detail = outcome == HardCaseOutcome.Diverged && resets > 1 ? $"{resets:0} resets" : MethodStudyRanking.Percent(dev);
            return $"{HardCaseRun.Label(outcome)} ({detail})";
        }

        static string Ratio(double r) => r < 10 ? r.ToString("0.00") : r.ToString("0");

        static string Ms(double seconds) =>
            seconds >= 1e-2 ? $"{seconds * 1e3:0} ms" : seconds >= 1e-3 ? $"{seconds * 1e3:0.0} ms" : $"{seconds * 1e3:0.000} ms";

        static string Seconds(double s) => double.IsFinite(s) ? s >= 1 ? $"{s:0.0} s" : $"{s * 1e3:0.0} ms" : "–";
    }
}
