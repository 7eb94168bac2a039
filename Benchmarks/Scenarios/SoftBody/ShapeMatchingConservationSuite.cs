using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Momentum and angular momentum of a free spinning blob, for every mode and cluster layout.</summary>
    public sealed class ShapeMatchingConservationSuite : IScenarioSuite
    {
        /// <summary>Metric: max over the run of |P − P₀| / Σ m|v|₀ (dimensionless).</summary>
        public const string MomentumDrift = "|dP|/sum m|v|";
        /// <summary>Metric: max over the run of |L − L₀| / |L₀| about the centre of mass (dimensionless).</summary>
        public const string AngularMomentumDrift = "|dL|/|L0|";
        /// <summary>Metric: NaN-guard resets (0 expected).</summary>
        public const string Resets = "resets";

        static readonly ShapeMatchingClusterLayout[] s_QuickLayouts = { ShapeMatchingClusterLayout.Single, ShapeMatchingClusterLayout.Overlapping };

        public string Name => "ShapeMatchingConservation";

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "Whether a free, spinning shape-matching body keeps its linear and angular momentum, for each mode and cluster layout.",
            Body = $"A {ShapeMatchingConservationScenario.BodySize} m cube of {ShapeMatchingConservationScenario.Edge}³ particles, as one cluster or 8 overlapping " +
                   $"{ShapeMatchingBenchmarkBody.ClusterEdge}³ clusters, every particle jittered by up to ±20 % of the spacing.",
            Material = $"{ShapeMatchingBenchmarkBody.Frequency} Hz, ζ = {ShapeMatchingBenchmarkBody.DampingRatio}, β = {ShapeMatchingBenchmarkBody.Beta}, " +
                       $"{ShapeMatchingConservationScenario.Substeps} substeps per 1/60 s step; rigid, linear or quadratic goals.",
            Load = $"Spinning at {SpinningBlob.AngularSpeed} rad/s about a seeded axis and drifting at {SpinningBlob.DriftSpeed} m/s, ±0.1 m/s of seeded noise on every velocity; " +
                   $"no gravity, no colliders; {SpinningBlob.Steps} steps ({SpinningBlob.Steps / 60.0:0.#} s).",
            Reference = "The initial momentum P₀ and angular momentum L₀ about the centre of mass: nothing acts from outside (the goals' pull is momentum- and torque-free, " +
                        "the damping spares rigid motion).",
            Metric = $"One item is one particle-step (all substeps). '{MomentumDrift}' = max |P − P₀| / Σ m|v|₀ and '{AngularMomentumDrift}' = max |L − L₀| / |L₀| over the run: " +
                     "float32 round-off (ShapeMatchingMomentumTests holds them to 1e-5 and 1e-3 over 1000 steps).",
            Notes = new[]
            {
                "Conservation is not accuracy: a solver can conserve both and still be far from the reference.",
                "Quick run: linear goals, both layouts.",
            },
            Details = "accuracy.md#conservation",
        };

        /// <summary>None: drift is not an error against a reference, so no accuracy figure.</summary>
        public string ErrorMetricForPlot => null;

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            if (quick)
            {
                foreach (ShapeMatchingClusterLayout layout in s_QuickLayouts)
                    yield return new ShapeMatchingConservationScenario(ShapeMatchingMode.Linear, layout);
                yield break;
            }
            foreach (ShapeMatchingClusterLayout layout in new[] { ShapeMatchingClusterLayout.Single, ShapeMatchingClusterLayout.Overlapping })
            foreach (ShapeMatchingMode mode in new[] { ShapeMatchingMode.Rigid, ShapeMatchingMode.Linear, ShapeMatchingMode.Quadratic })
                yield return new ShapeMatchingConservationScenario(mode, layout);
        }
    }
}
