using System;
using System.Collections.Generic;
using System.Globalization;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>The fluid suites' lines in the report's summary: accuracy against cost, hard cases per solver, and what cohesion and viscosity cost.</summary>
    public static class FluidFindings
    {
        /// <summary>Dam-break front thresholds (in column widths a, Z = x/a): the suite's tolerance, twice it and half it.</summary>
        public static readonly double[] FrontThresholds = { 2 * FluidAccuracySuite.FrontTolerance, FluidAccuracySuite.FrontTolerance, 0.5 * FluidAccuracySuite.FrontTolerance };

        /// <summary>Simulated seconds of one dam-break run: T = <see cref="DamBreakScenario.EndT"/> in Martin &amp; Moyce's time t·√(2g/a).</summary>
        public static double DamBreakSeconds => DamBreakScenario.EndT / Math.Sqrt(2 * 9.81 / MartinMoyce1952.ColumnWidth);

        /// <summary>ms of compute per 1/60 s of simulated time of a dam-break row: the whole run's cost (every particle, every substep) over its simulated length.</summary>
        public static double DamBreakFrameMs(ScenarioOutcome r) => r.NsPerItem * r.ItemsPerStep * 1e-6 / (60 * DamBreakSeconds);

        public static IEnumerable<Finding> Findings(IReadOnlyList<ScenarioOutcome> rows)
        {
            var dam = new List<ScenarioOutcome>();
            var column = new List<ScenarioOutcome>();
            var hard = new List<ScenarioOutcome>();
            var droplets = new List<ScenarioOutcome>();
            foreach (ScenarioOutcome r in rows)
            {
                if (!double.IsNaN(r.Value("front RMS error (shifted)"))) dam.Add(r);
                else if (!double.IsNaN(r.Value("pressure gradient error"))) column.Add(r);
                else if (!double.IsNaN(r.Value("invalid removed"))) hard.Add(r);
                else if (!double.IsNaN(r.Value("sphericity"))) droplets.Add(r);
            }
            if (dam.Count > 0)
                yield return AccuracyFinding.FromRows("Dam break (Martin & Moyce 1952)",
                    $"front RMS error with the best time shift, in column widths a (thresholds {F(FrontThresholds[0])} / {F(FrontThresholds[1])} / {F(FrontThresholds[2])} a)",
                    "front RMS error (shifted)", dam, FrontThresholds,
                    DamBreakFrameMs, r => r.Method, "ms/frame", MetricUnit.ColumnWidth);
            if (column.Count > 0)
                yield return AccuracyFinding.FromRows("Hydrostatic column", "interior pressure gradient against ρ₀g", "pressure gradient error", column,
                    AccuracyFinding.RelativeThresholds, r => r.NsPerItem * r.ItemsPerStep * 1e-6,
                    r => r.Method, "ms/frame");
            foreach (Finding f in HardCases(hard))
                yield return f;
            foreach (Finding f in Cohesion(droplets))
                yield return f;
        }

        /// <summary>
        /// One line per solver: a hard case passes when every particle left is finite and inside the box, no valid particle was
        /// lost (alive + invalid removed = the particles it started with), and a frame the substep cap held back (slow motion)
        /// kept the density below the over-compression bound after the first frame.
        /// </summary>
        public static IEnumerable<Finding> HardCases(IReadOnlyList<ScenarioOutcome> rows)
        {
            var bySolver = new Dictionary<string, HardCaseFinding>();
            var order = new List<string>();
            foreach (ScenarioOutcome r in rows)
            {
                int space = r.Method.IndexOf(' ');
                string solver = space > 0 ? r.Method.Substring(0, space) : r.Method;
                string hardCase = space > 0 ? r.Method.Substring(space + 1) : r.Method;
                if (!bySolver.TryGetValue(solver, out HardCaseFinding f))
                {
                    bySolver[solver] = f = new HardCaseFinding { Group = "Fluids", Criterion = Criterion, Method = solver, Failed = new List<string>() };
                    order.Add(solver);
                }
                f.Total++;
                string why = Failure(r);
                if (why == null)
                    f.Passed++;
                else
                    ((List<string>)f.Failed).Add($"{hardCase}: {why}");
            }
            foreach (string s in order)
                yield return bySolver[s];
        }

        /// <summary>The pass rule, as the summary states it.</summary>
        public const string Criterion = "a case passes when every particle left is finite and in the box, none is lost but the invalid ones, and a frame the substep cap holds back runs in slow motion with the density below the over-compression bound after its first frame";

        /// <summary>Why a fluid hard case failed, or null when it passed.</summary>
        public static string Failure(ScenarioOutcome r)
        {
            if (r.Value("finite") != 1) return "non-finite particles";
            if (r.Value("in box") != 1) return "particles outside the box";
            double lost = r.Size - r.Value("alive") - r.Value("invalid removed");
            if (lost != 0) return $"{lost:0} valid particles lost";
            if (r.Value("substeps wanted") > r.Value("substeps run") && r.Value("late max density ratio") > FluidParameters.Default.MaxDensityRatio)
                return $"capped at {r.Value("substeps run"):0} substeps (wanted {r.Value("substeps wanted"):0}) and compressed to {r.Value("late max density ratio"):0.#} ρ₀";
            return null;
        }

        /// <summary>The droplet row without cohesion and without the viscosity pass.</summary>
        public const string InviscidDroplet = "no cohesion, inviscid";

        /// <summary>
        /// What cohesion and the implicit viscosity add per particle-substep, from the droplet rows with and without them
        /// (viscosity: water's ν against the inviscid drop).
        /// </summary>
        static IEnumerable<Finding> Cohesion(IReadOnlyList<ScenarioOutcome> droplets)
        {
            ScenarioOutcome? none = null, inviscid = null;
            foreach (ScenarioOutcome r in droplets)
                if (r.Method.EndsWith(InviscidDroplet, StringComparison.Ordinal))
                    inviscid = r;
                else if (r.Method.Contains("no cohesion"))
                    none = r;
            if (none == null)
                yield break;
            if (inviscid != null)
                yield return new EffectFinding
                {
                    Effect = EffectNames.FluidViscosity,
                    Cost = EffectCost(inviscid.Value, none.Value, "the same droplet without the viscosity pass"),
                };
            foreach ((string effect, string key) in new[] { (EffectNames.FlockingCohesion, "flocking"), (EffectNames.AkinciCohesion, "Akinci") })
            {
                ScenarioOutcome? with = null;
                foreach (ScenarioOutcome r in droplets)
                    if (r.Method.Contains(key) && with == null)
                        with = r;
                if (with == null)
                    continue;
                yield return new EffectFinding { Effect = effect, Cost = EffectCost(none.Value, with.Value, "the same droplet without cohesion") };
            }
        }

        /// <summary>
        /// "+x ns per particle-substep (+y %): z ms per frame for 10 000 particles at one substep", measured on the droplet
        /// <paramref name="with"/> the effect against <paramref name="against"/>, the droplet <paramref name="without"/> it.
        /// </summary>
        public static string EffectCost(ScenarioOutcome without, ScenarioOutcome with, string against)
        {
            double delta = with.NsPerItem - without.NsPerItem;
            string setting = with.Method;
            if (delta <= 0)
                return $"no cost above the timing noise ({F(delta)} ns per particle-substep against {against}; {setting})";
            return $"+{F(delta)} ns per particle-substep (+{F(100 * delta / without.NsPerItem)} %), i.e. {F(delta * 1e4 * 1e-6)} ms per frame " +
                   $"for 10 000 particles at one substep ({setting}, {with.Size}-particle droplet, against {against})";
        }

        static string F(double v) => v.ToString(Math.Abs(v) >= 100 ? "0" : Math.Abs(v) >= 10 ? "0.#" : "0.##", CultureInfo.InvariantCulture);
    }
}
