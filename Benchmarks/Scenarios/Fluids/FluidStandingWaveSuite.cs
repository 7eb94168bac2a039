using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Fluid accuracy against an analytic frequency: the first sloshing mode of a tank (<see cref="StandingWaveScenario"/>) at
    /// a resolution sweep, for each solver at its defaults, its frequency error against µs per 1/60 s frame of the whole
    /// scene, with the observed order.
    /// </summary>
    public sealed class FluidStandingWaveSuite : IScenarioSuite, IScenarioSuiteSummary, IScenarioSuiteFigure, IScenarioSuiteFindings, IScenarioSuiteIndependent
    {
        /// <summary>Particle layers over the depth in the full run (d/20 takes about 3 min of setup for WCSPH here); the default run stops at <see cref="StandardFinestLayers"/>.</summary>
        public static readonly int[] Layers = { 5, 10, 20 };
        /// <summary>Finest resolution of the default run (d/5, a second per solver; d/10 takes 35 s for WCSPH).</summary>
        public const int StandardFinestLayers = 5;
        public string Name => "FluidAccuracyStandingWave";

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "Whether the fluid's free surface, gravity and pressure give the right wave frequency, converging as resolution is bought, and what each resolution costs per frame.",
            Body = $"Water d = {StandingWaveScenario.Depth} m deep in a tank L = {StandingWaveScenario.Length} m long between free-slip walls, a slab periodic along z over " +
                   $"{StandingWaveScenario.PeriodicLayers}Δx, Δx = d/{string.Join(", d/", Layers)} (h = 2Δx).",
            Material = "Water at each solver's defaults (FluidParameters.Default): WCSPH c₀ = " +
                       $"{FluidParameters.Default.SpeedOfSound} m/s, α = {FluidParameters.Default.ArtificialViscosity}, β = {FluidParameters.Default.BulkViscosity}; " +
                       $"PBF {FluidParameters.Default.PressureIterations} iterations, XSPH {FluidParameters.Default.XsphRate}/s.",
            Load = $"Gravity; started flat with the linear first mode's velocity (amplitude A = {1000 * StandingWaveScenario.Amplitude} mm, kA = " +
                   $"{StandingWaveScenario.Wavenumber * StandingWaveScenario.Amplitude:0.000}), run for {StandingWaveScenario.Periods} analytic periods in 1/60 s frames.",
            Reference = $"Linear dispersion relation ω² = gk·tanh(kd), k = π/L: ω = {StandingWaveScenario.AngularFrequency:0.000} rad/s " +
                        $"(period {2 * Math.PI / StandingWaveScenario.AngularFrequency:0.000} s).",
            Metric = $"Frequency error = |mean of ω_fit/ω − 1| over {Members} waves whose ν is scaled by 1 + k/100 (one wave's fit moves by several per cent under such a change), ± its standard deviation over them; " +
                     "ω_fit from a least-squares fit of e^(−γt)(a·sin ωt + b·cos ωt) + c to the centre of mass along x, " +
                     "one sample per frame; damping ratio = γ/ω; amplitude ratio = fitted over the linear 2LA/(π²d); fit residual = RMS over that amplitude. " +
                     "One item is one particle-substep; a step is one 1/60 s frame.",
            Notes = new[]
            {
                $"Observed order = log(e₁/e₂)/log(Δx₁/Δx₂) between neighbouring resolutions. Default run: d/{StandardFinestLayers} only (d/10 takes 35 s of setup); full run: every resolution.",
                "The amplitude's own correction to the frequency is of order (kA)² ≈ 0.2 %; the artificial viscosity's damping shifts it by (γ/ω)²/2.",
            },
            Details = "fluids.md#standing-wave-fluidaccuracystandingwave",
        };

        public string ErrorMetricForPlot => "frequency error";

        /// <summary>Waves per row (<see cref="StandingWaveScenario"/>'s ensemble; one in the quick run).</summary>
        public const int Members = 4;

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            int finest = scope == RunScope.Full ? Layers[Layers.Length - 1] : scope == RunScope.Quick ? Layers[0] : StandardFinestLayers;
            foreach (FluidSolverKind solver in new[] { FluidSolverKind.WeaklyCompressible, FluidSolverKind.PositionBased })
                foreach (int layers in Layers)
                    if (layers <= finest)
                    {
                        FluidParameters p = FluidParameters.Default;
                        p.Solver = solver;
                        yield return new StandingWaveScenario(layers, p, "defaults", scope == RunScope.Quick ? 1 : Members);
                    }
        }

        public string Series(ScenarioOutcome row) => FluidScene.SeriesOf(row.Method);

        public string PointLabel(ScenarioOutcome row) => FluidScene.PointOf(row.Method);

        public string CostLabel => FluidSweepTable.CostLabel;

        public double Cost(ScenarioOutcome row) => FluidSweepTable.Cost(row);

        public IEnumerable<Finding> Findings(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            yield return FluidSweepTable.Finding("Standing wave", "first sloshing mode's frequency against ω² = gk·tanh(kd)", "frequency error", rows);
        }

        public string Summary(IReadOnlyList<ScenarioOutcome> rows, RunScope scope) =>
            FluidSweepTable.Write(rows, "frequency error", "frequency error", "damping ratio", r => FluidSweepTable.F("{0:0.000}", r.Value("damping ratio")));
    }
}
