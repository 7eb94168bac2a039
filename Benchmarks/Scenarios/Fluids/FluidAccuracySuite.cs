using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Fluid accuracy against cost: the Martin &amp; Moyce dam break for each solver × setting × resolution (front error
    /// against ns per particle-substep, the figure), the hydrostatic column, and the droplet (flocking against Akinci
    /// cohesion).
    /// </summary>
    public sealed class FluidAccuracySuite : IScenarioSuite, IScenarioSuiteSummary, IScenarioSuiteFigure
    {
        /// <summary>Dam-break resolutions (particles across the column width a) of the full run.</summary>
        public static readonly int[] Resolutions = { 10, 20 };
        /// <summary>Weakly compressible speeds of sound, as multiples of the column's √(2g·2a).</summary>
        public static readonly float[] SoundMultiples = { 5f, 10f, 20f };
        /// <summary>Position-based iteration counts.</summary>
        public static readonly int[] Iterations = { 2, 4, 8 };
        /// <summary>Front error (RMS of Z) a row must reach to count in the summary: the experiment's ±0.07 band in T times the late front speed dZ/dT ≈ 1.4.</summary>
        public const double FrontTolerance = 0.1;

        public string Name => "FluidAccuracy";

        public string Description =>
            "Dam break after Martin & Moyce 1952 (n² = 2, a = 0.05715 m, Table 2; slab four particles deep between free-slip walls; " +
            "front = leading edge of particles with ≥ 4 neighbours) from release to T = t·√(2g/a) = 3.4, for the weakly compressible " +
            "solver (WCSPH, Tait γ = 7, artificial viscosity α = 0.05, CFL 0.4, speed of sound c₀ a multiple of √(2g·2a) = 1.50 m/s) and " +
            "position-based fluids (PBF, CFL 0.4, 2–8 iterations), at a/10 and a/20. Front error = RMS of Z_sim − Z_data over the table's " +
            "15 points, without and with the best time shift in [0, 0.2] (the gate's opening time; the experiment's own band is ±0.07 in T). " +
            "Density error = mean |ρ/ρ₀ − 1| of the bulk over the run's frames. An item is one particle-substep, so ns per item is the " +
            "cost of moving one particle through one substep of that solver. Hydrostatic column: 0.2 × 0.4 × 0.2 m of water at Δx = 2.5 cm, " +
            "settled for the stated time, then measured (interior pressure against ρ₀g(H − y), density error, kinetic energy, surface drift). " +
            "Droplet: a 10 cm cube without gravity rounding under flocking cohesion or Akinci et al. 2013 cohesion and curvature.";

        public string ErrorMetricForPlot => "front RMS error (shifted)";

        public IEnumerable<IScenario> Scenarios(bool quick)
        {
            foreach (int resolution in quick ? new[] { 10 } : Resolutions)
            {
                foreach (float multiple in quick ? new[] { 10f } : SoundMultiples)
                    yield return new DamBreakScenario(resolution, Weak(multiple * DamBreakScenario.ReferenceSpeed), $"c0 = {multiple:0}·v");
                foreach (int iterations in quick ? new[] { 4 } : Iterations)
                    yield return new DamBreakScenario(resolution, PositionBased(iterations), $"{iterations} it");
            }
            float settle = quick ? 1f : 10f;
            yield return new HydrostaticColumnScenario(Weak(10f * HydrostaticColumnScenario.ReferenceSpeed), "c0 = 10·v", settle);
            if (!quick)
                yield return new HydrostaticColumnScenario(PositionBased(4), "4 it", settle);
            foreach (var (parameters, setting) in Droplets(quick))
                yield return new DropletScenario(parameters, setting);
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

        /// <summary>Droplet rows: no cohesion (the control), flocking and Akinci.</summary>
        static IEnumerable<(FluidParameters, string)> Droplets(bool quick)
        {
            FluidParameters none = Weak(5f);
            FluidParameters flocking = none;
            flocking.Cohesion = FluidCohesionModel.Flocking;
            flocking.CohesionWeight = 50f;
            flocking.AlignmentRate = 2f;
            FluidParameters akinci = none;
            akinci.Cohesion = FluidCohesionModel.Akinci;
            akinci.SurfaceTension = AkinciTension;
            if (!quick)
                yield return (none, "no cohesion");
            yield return (flocking, "flocking (50/s², align 2/s)");
            if (!quick)
                yield return (akinci, $"Akinci (γ = {AkinciTension.ToString("0.###", CultureInfo.InvariantCulture)})");
        }

        /// <summary>Akinci γ of the droplet row.</summary>
        public const float AkinciTension = 0.2f;

        public string Series(ScenarioOutcome row)
        {
            int comma = row.Method.LastIndexOf(',');
            return comma > 0 ? row.Method.Substring(0, comma) : row.Method;
        }

        public string PointLabel(ScenarioOutcome row)
        {
            int comma = row.Method.LastIndexOf(',');
            return comma > 0 ? row.Method.Substring(comma + 1).Trim() : "";
        }

        public string CostLabel => "ns per particle-substep, median";

        public double Cost(ScenarioOutcome row) => row.NsPerItem;

        public string Summary(IReadOnlyList<ScenarioOutcome> rows, bool quick)
        {
            var md = new StringBuilder();
            md.AppendLine("| Dam break | front error | shifted (shift) | Z at T = 3.33 (data 4.11) | density error | ns per particle-substep | ms per run | max substeps per 2 ms frame |");
            md.AppendLine("|---|---|---|---|---|---|---|---|");
            ScenarioOutcome? cheapest = null;
            foreach (ScenarioOutcome r in rows)
            {
                double shifted = r.Value("front RMS error (shifted)");
                if (double.IsNaN(shifted))
                    continue;
                md.AppendLine(string.Format(CultureInfo.InvariantCulture, "| {0} | {1:0.000} | {2:0.000} ({3:0.00}) | {4:0.00} | {5:0.00} % | {6:0} | {7:0} | {8:0} |",
                    r.Method, r.Value("front RMS error"), shifted, r.Value("shift"), r.Value("Z at T=3.33"), r.Value("density error"), r.NsPerItem,
                    r.NsPerItem * r.ItemsPerStep * 1e-6, r.Value("max substeps per frame")));
                // Cost of a whole run: ns per item × items per run.
                if (shifted <= FrontTolerance && (cheapest == null || r.NsPerItem * r.ItemsPerStep < cheapest.Value.NsPerItem * cheapest.Value.ItemsPerStep))
                    cheapest = r;
            }
            md.AppendLine();
            md.AppendLine(cheapest != null
                ? string.Format(CultureInfo.InvariantCulture, "Cheapest run within {0} in Z (shifted): {1}, {2:0.0} ms for the whole run.",
                    FrontTolerance, cheapest.Value.Method, cheapest.Value.NsPerItem * cheapest.Value.ItemsPerStep * 1e-6)
                : string.Format(CultureInfo.InvariantCulture, "No run came within {0} in Z (shifted).", FrontTolerance));
            return md.ToString();
        }
    }
}
