using System.Collections.Generic;
using System.Linq;
using System.Globalization;
using System.Text;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Akinci surface tension measured twice on one drop (<see cref="DropletOscillationScenario"/>): σ from the interior's
    /// virial pressure (Laplace) and σ from the l = 2 oscillation frequency (Rayleigh), with the drop's volume change.
    /// </summary>
    public sealed class FluidDropletSuite : IScenarioSuite, IScenarioSuiteSummary, IScenarioSuiteFigure, IScenarioSuiteIndependent
    {
        /// <summary>Akinci γ of the rows (the droplet rows' of <see cref="FluidAccuracySuite"/>).</summary>
        public static readonly float[] Tensions = FluidAccuracySuite.AkinciTensions;
        /// <summary>Coarse and fine spacing (m): R = 2.5h and 5h.</summary>
        public static readonly float[] Spacings = { 0.01f, 0.005f };
        /// <summary>Surface amplitudes a/R of the amplitude rows (γ = 0.2, Δx = 1 cm).</summary>
        public static readonly double[] Amplitudes = { 0.05, 0.3 };

        public string Name => "FluidAccuracyDroplet";

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "Whether Akinci cohesion acts as one surface tension σ: the σ a drop's interior pressure gives (Laplace) against the σ its oscillation gives (Rayleigh).",
            Body = $"A lattice ball of radius {DropletOscillationScenario.BallRadius} m (Δx = 1 cm: {DropletOscillationScenario.BallCount(0.01f)} particles; " +
                   $"5 mm in the full run: {DropletOscillationScenario.BallCount(0.005f)}), h = 2Δx, no gravity, in a 0.4 m box it never reaches.",
            Material = "Water: ρ₀ = 1000 kg/m³, WCSPH c₀ = 5 m/s, α = 0.05, bulk viscosity β = 0.5 (the droplet rows of FluidAccuracy); Akinci cohesion " +
                       "and curvature at γ = " + string.Join(", ", Tensions.Select(t => t.ToString("0.##", CultureInfo.InvariantCulture))) + ".",
            Load = $"{DropletOscillationScenario.SettleSeconds} s of settling, then the l = 2 velocity v = ε·(−x, −y, 2z) about the centre of mass, " +
                   $"ε = (a/R)·ω_p/2 with a/R = {DropletOscillationScenario.DefaultAmplitude} (the full run adds {Amplitudes[0]} and {Amplitudes[1]}), " +
                   $"recorded every 1/60 s for {DropletOscillationScenario.Periods} periods of ω_p.",
            Reference = "Laplace: P = 2σ/R; Rayleigh (1879): ω² = 8σ/(ρR³) for the l = 2 mode of an inviscid drop.",
            Metric = "σ from pressure = P·R/2, P the virial pressure of the pair forces (pressure and Akinci) over the particles deeper than h, averaged over " +
                     $"the last {DropletOscillationScenario.AveragedFrames} settling frames; σ from EOS pressure = the mean Tait pressure there times R/2; " +
                     "σ from frequency = ω²·3M/(32π), ω of a damped-sine fit to Q = mean(2z² − x² − y²); σ ratio = σ_f/σ_p; frequency error = ω/ω_p − 1, " +
                     "ω_p Rayleigh's for σ_p; R = (3Nm/(4πρ̄))^⅓, ρ̄ the interior's mean density; volume change = ρ₀/ρ̄ − 1; gyration volume change = " +
                     "(R_g/R_g,0)³ − 1 against the starting lattice ball. Each row is the mean over " + Members + " drops whose ν is scaled by 1 + k/100 " +
                     "(one drop's σ ratio moves by 0.1–0.4 under such a change), the σ ratio with its standard deviation over them. " +
                     "One item is one particle-substep; a step is one 1/60 s frame.",
            Notes = new[]
            {
                "Default run: γ = 0.2 at Δx = 1 cm; full run: both γ at 1 cm, the amplitude rows, and γ = 0.2 at 5 mm (about 3 min).",
            },
            Details = "fluids.md#droplet-oscillation-fluidaccuracydroplet",
        };

        public string ErrorMetricForPlot => "frequency error";

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            bool full = scope == RunScope.Full;
            yield return Row(Tensions[1], Spacings[0], DropletOscillationScenario.DefaultAmplitude);
            if (!full)
                yield break;
            yield return Row(Tensions[0], Spacings[0], DropletOscillationScenario.DefaultAmplitude);
            foreach (double amplitude in Amplitudes)
                yield return Row(Tensions[1], Spacings[0], amplitude);
            yield return Row(Tensions[1], Spacings[1], DropletOscillationScenario.DefaultAmplitude);
        }

        /// <summary>Drops per row (<see cref="DropletOscillationScenario"/>'s ensemble).</summary>
        public const int Members = 4;

        static DropletOscillationScenario Row(float tension, float spacing, double amplitude)
        {
            FluidParameters p = FluidParameters.Default;
            p.SpeedOfSound = 5f;
            p.ViscosityIterations = 1;
            p.Cohesion = FluidCohesionModel.Akinci;
            p.SurfaceTension = tension;
            string label = F("Akinci (γ = {0:0.##}, a/R = {1:0.##})", tension, amplitude);
            return new DropletOscillationScenario(spacing, p, label, amplitude, Members);
        }

        public string Series(ScenarioOutcome row) => FluidScene.SeriesOf(row.Method);

        public string PointLabel(ScenarioOutcome row) => FluidScene.PointOf(row.Method);

        public string CostLabel => "µs per 1/60 s frame (whole scene, all substeps), median";

        public double Cost(ScenarioOutcome row) => row.NsPerItem * row.ItemsPerStep * 1e-3;

        public string Summary(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            var md = new StringBuilder();
            md.AppendLine("| row (means over the drops) | σ from EOS pressure (N/m) | σ from pressure (N/m) | σ from frequency (N/m) | σ ratio, mean ± SD | damping ratio | volume change | gyration volume change |");
            md.AppendLine("|---|---:|---:|---:|---:|---:|---:|---:|");
            foreach (ScenarioOutcome r in rows)
                md.AppendLine(F("| {0} | {1:0.000} | {2:0.000} | {3:0.000} | {4} | {5:0.00} | {6:+0.00;−0.00} % | {7:+0.0;−0.0} % |", r.Method,
                    r.Value("σ from EOS pressure (N/m)"), r.Value("σ from pressure (N/m)"), r.Value("σ from frequency (N/m)"),
                    double.IsNaN(r.Value("σ ratio spread")) ? F("{0:0.00}", r.Value("σ ratio")) : F("{0:0.00} ± {1:0.00}", r.Value("σ ratio"), r.Value("σ ratio spread")),
                    r.Value("damping ratio"), 100 * r.Value("volume change"), 100 * r.Value("gyration volume change")));
            return md.ToString();
        }

        static string F(string format, params object[] args) => string.Format(CultureInfo.InvariantCulture, format, args);
    }
}
