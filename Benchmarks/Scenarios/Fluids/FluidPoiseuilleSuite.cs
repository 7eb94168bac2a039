using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Fluid accuracy against an analytic solution that converges: plane Poiseuille flow (<see cref="PoiseuilleScenario"/>)
    /// at a resolution sweep, its profile error against µs per 1/60 s frame of the whole scene, with the observed order.
    /// </summary>
    public sealed class FluidPoiseuilleSuite : IScenarioSuite, IScenarioSuiteSummary, IScenarioSuiteFigure, IScenarioSuiteFindings, IScenarioSuiteIndependent
    {
        /// <summary>Particle layers across the channel in the full run; the default run stops at <see cref="StandardFinestLayers"/>.</summary>
        public static readonly int[] Layers = { 5, 10, 20, 40 };
        /// <summary>Finest resolution of the default run (W/10, 1 s of setup here; W/20 takes 5 s and W/40 40 s, in the full run).</summary>
        public const int StandardFinestLayers = 10;
        public string Name => "FluidAccuracyPoiseuille";

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "Whether the fluid's viscosity, no-slip faces and periodic axes converge to an analytic flow as resolution is bought, and what each resolution costs per frame.",
            Body = $"Plane Poiseuille flow: a channel W = {PoiseuilleScenario.Width} m between two no-slip faces (y), periodic along x and z over " +
                   $"{PoiseuilleScenario.PeriodicLayers}Δx, filled with a lattice at rest, Δx = W/{string.Join(", W/", Layers)} (h = 2Δx).",
            Material = $"ν = {PoiseuilleScenario.Viscosity} m²/s (the honey preset), ρ₀ = 1000 kg/m³, WCSPH c₀ = 10·u_max = {10 * PoiseuilleScenario.PeakSpeed:0.#} m/s, " +
                       $"α = {FluidParameters.Default.ArtificialViscosity}; viscosity iterations: the default {FluidParameters.Default.ViscosityIterations}, which the step raises " +
                       $"until the solve converges (up to {FluidParameters.MaxViscosityIterations}).",
            Load = $"Body force f = 8νu_max/W² = {PoiseuilleScenario.BodyForce:0.###} m/s² along x for u_max = {PoiseuilleScenario.PeakSpeed} m/s; " +
                   $"{PoiseuilleScenario.SettleSeconds} s in 1/60 s frames (eleven e-folding times of the slowest transient), then measured.",
            Reference = "Analytic steady profile u(y) = f/(2ν)·y(W − y).",
            Metric = "Profile error = RMS over layers Δx thick of the layer's mean u_x against u(mean y), over u_max; mean flow error = |ū/(2u_max/3) − 1|; " +
                     "cross flow = mean |(u_y, u_z)| over u_max. One item is one particle-substep; a step is one 1/60 s frame.",
            Notes = new[]
            {
                $"Observed order = log(e₁/e₂)/log(Δx₁/Δx₂) between neighbouring resolutions. Default run: W/{Layers[0]}…W/{StandardFinestLayers}; full run: " +
                $"every resolution. A substep runs n = ln 0.01/ln(a/(1 + a)) viscosity iterations when that is more than asked for, a = 15·hν/h² " +
                "(about 20 at W/20 here); a fixed 4 left the steady flow 8 % and 37 % too fast at W/10 and W/20 (fluids.md).",
            },
            Details = "fluids.md#poiseuille-flow-fluidaccuracypoiseuille",
        };

        public string ErrorMetricForPlot => "profile RMS error";

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            int finest = scope == RunScope.Full ? Layers[Layers.Length - 1] : scope == RunScope.Quick ? Layers[0] : StandardFinestLayers;
            foreach (int layers in Layers)
                if (layers <= finest)
                    yield return new PoiseuilleScenario(layers, Fluid(), "defaults");
        }

        static FluidParameters Fluid()
        {
            FluidParameters p = FluidParameters.Default;
            p.SpeedOfSound = 10f * PoiseuilleScenario.PeakSpeed;
            return p;
        }

        public string Series(ScenarioOutcome row) => FluidScene.SeriesOf(row.Method);

        public string PointLabel(ScenarioOutcome row) => FluidScene.PointOf(row.Method);

        public string CostLabel => FluidSweepTable.CostLabel;

        public double Cost(ScenarioOutcome row) => FluidSweepTable.Cost(row);

        public IEnumerable<Finding> Findings(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            yield return FluidSweepTable.Finding("Poiseuille flow", "layer-mean speed profile against the analytic u(y), over u_max", "profile RMS error", rows);
        }

        public string Summary(IReadOnlyList<ScenarioOutcome> rows, RunScope scope) =>
            FluidSweepTable.Write(rows, "profile RMS error", "profile error", "mean flow error", r => FluidSweepTable.F("{0:0.00} %", 100 * r.Value("mean flow error")));
    }
}
