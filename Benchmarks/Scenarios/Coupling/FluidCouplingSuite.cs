using System.Collections.Generic;
using System.Globalization;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Fluid and bodies acting on each other (<see cref="FluidCouplingScenario"/>): buoyancy, flotation and the momentum they trade, with the cost.</summary>
    public sealed class FluidCouplingSuite : IScenarioSuite, IScenarioSuiteIndependent, IScenarioSuiteFindings
    {
        public string Name => "FluidCoupling";

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "Whether a fluid and the bodies in it push each other as they should: Archimedes' force, the depth a light body floats at, and momentum traded, not made.",
            Body = $"A {FluidCouplingScenario.BodySize} m box held with its top 6 cm under {FluidCouplingScenario.HeldDepth} m of water; a {FluidCouplingScenario.BodySize} m " +
                   $"shape-matching cube (5³ particles, one cluster, defaults) of {FluidCouplingScenario.CubeDensity} kg/m³ dropped onto {FluidCouplingScenario.FloatDepth} m of water; " +
                   $"both in a {FluidCouplingScenario.Tank} m square tank at Δx = {FluidCouplingScenario.Spacing} m. A 0.3 kg, 4 cm ball thrown at 1 m/s into a weightless 16 cm blob. The held box's tank without the box, for the cost.",
            Material = "Water: WCSPH defaults (c₀ = 10 m/s, α = 0.05, bulk viscosity 0.5), h = 2Δx; the bodies enter as rigid proxies (FluidCoupling.Step).",
            Load = "Gravity (none for the ball); 1/60 s frames, 2 s held, 3 s floating, 0.5 s ball (quick run: 0.25 s each, no settled answer).",
            Reference = "Archimedes: ρ₀gV on the held box, a submerged share ρ/ρ₀ = 0.5 for the cube; zero change of the total momentum for the ball.",
            Metric = "Buoyancy error: the mean upward force over the last quarter of the run / ρ₀gV − 1 (held); 0.5 / the mean submerged share over the last third − 1 " +
                     "(floating; the share of the proxy box under the waterline of the columns away from it). Momentum change: |Δp| of fluid + ball / the ball's " +
                     "starting momentum. The tank alone runs the plain fluid step on the held box's water: the difference in time is what a body costs. One item is one particle-substep; a step is the whole run.",
            Details = "fluids.md#bodies-in-the-fluid-solver-level",
        };

        public string ErrorMetricForPlot => null;

        static float HeldSeconds(RunScope scope) => scope == RunScope.Quick ? 0.25f : 2f;

        /// <summary>What one body costs: the held box's run against the tank alone, per 1/60 s frame.</summary>
        public IEnumerable<Finding> Findings(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            if (rows.Count < 2)
                yield break;
            double frames = System.Math.Round(HeldSeconds(scope) * 60.0);
            double with = rows[0].NsPerItem * rows[0].ItemsPerStep / frames * 1e-6, without = rows[1].NsPerItem * rows[1].ItemsPerStep / frames * 1e-6;
            yield return new EffectFinding
            {
                Effect = EffectNames.FluidSoftBodyCoupling,
                Cost = string.Format(CultureInfo.InvariantCulture,
                    "+{0:0.00} ms per 1/60 s frame (+{1:0} %) for a 10 cm body in {2} particles of water (the held box against its tank alone, one thread)",
                    with - without, 100 * (with / without - 1), rows[1].Size),
            };
        }

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            yield return new FluidCouplingScenario(FluidCouplingScene.HeldBox, HeldSeconds(scope));
            yield return new FluidCouplingScenario(FluidCouplingScene.TankAlone, HeldSeconds(scope));
            yield return new FluidCouplingScenario(FluidCouplingScene.FloatingCube, quick ? 0.25f : 3f);
            yield return new FluidCouplingScenario(FluidCouplingScene.BallInBlob, quick ? 0.25f : 0.5f);
        }
    }
}
