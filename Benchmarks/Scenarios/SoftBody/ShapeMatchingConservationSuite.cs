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

        public SuiteDefinition Definition => new SuiteDefinition { Notes = new[] { LegacyDescription } };

        string LegacyDescription =>
            $"A {ShapeMatchingConservationScenario.BodySize} m cube of {ShapeMatchingConservationScenario.Edge}³ particles " +
            $"({ShapeMatchingBenchmarkBody.Frequency} Hz, ζ = {ShapeMatchingBenchmarkBody.DampingRatio}, β = {ShapeMatchingBenchmarkBody.Beta}, " +
            $"{ShapeMatchingConservationScenario.Substeps} substeps per 1/60 s step, no gravity, no colliders), as one cluster or 8 overlapping 4³ clusters, " +
            "every particle jittered by up to ±20 % of the spacing, spinning at 3 rad/s about a seeded axis and drifting at 0.5 m/s with ±0.1 m/s of " +
            $"seeded noise on every velocity, for {SpinningBlob.Steps} steps ({SpinningBlob.Steps / 60.0:0.#} s). Nothing outside acts on it: the goals' pull " +
            "is made momentum- and torque-free and the damping leaves rigid motion alone, so linear momentum P and angular momentum L about the centre " +
            $"of mass must stay at their initial values. '{MomentumDrift}' and '{AngularMomentumDrift}' are the largest drifts over the run: float32 " +
            "round-off of the velocity increments (ShapeMatchingMomentumTests holds them to 1e-5 and 1e-3 over 1000 steps). Conservation is not " +
            "accuracy: a solver can conserve both and still be far from the reference, which is why these live in their own table. " +
            "Quick run: linear, both layouts.";

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
