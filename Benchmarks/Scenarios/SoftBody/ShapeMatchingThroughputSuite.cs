using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Shape-matching throughput: particle-iterations per second for every mode and cluster layout, 1k to 100k particles.</summary>
    public sealed class ShapeMatchingThroughputSuite : IScenarioSuite
    {
        /// <summary>Lattice edges of the full run: 10³ = 1000, 22³ = 10648 and 46³ = 97336 particles.</summary>
        public static readonly int[] Edges = { 10, 22, 46 };
        /// <summary>Lattice edge of the quick run: 10³ = 1000 particles.</summary>
        public static readonly int[] QuickEdges = { 10 };

        public string Name => "ShapeMatchingThroughput";

        public SuiteDefinition Definition => new SuiteDefinition { Notes = new[] { LegacyDescription } };

        string LegacyDescription =>
            "One 1 m cube of 10³ = 1000, 22³ = 10648 or 46³ = 97336 particles (quick run: 1000 only) settling on a floor plane " +
            "under gravity, advanced by one 1/60 s step of exactly 4 substeps (9 Hz, ζ = 0.13, β = 0.5, friction 0.5, no sleeping); " +
            "the body starts at rest touching the floor and is put back there every 60 steps, so every timed step is one of the " +
            "first second of settling. " +
            "One item is one particle-iteration (a particle through one substep: predict, cluster solve, floor contact, update), " +
            "so items per step = particles × 4 and items/s is particle-iterations per second. '1 cluster' matches the whole body at " +
            "once; '4^3 clusters' uses overlapping 4×4×4-point clusters sharing half their width (an interior particle is in 8 clusters, " +
            "so each particle-iteration costs about 8 cluster visits). The metrics only check the timed run: NaN-guard resets " +
            "(0 expected) and the mean number of particles in floor contact (at least the bottom layer, edge²).";

        /// <summary>None: throughput has no error reference (the accuracy suite plots error against cost), so no accuracy figure.</summary>
        public string ErrorMetricForPlot => null;

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            foreach (int edge in quick ? QuickEdges : Edges)
            foreach (ShapeMatchingClusterLayout layout in new[] { ShapeMatchingClusterLayout.Single, ShapeMatchingClusterLayout.Overlapping })
            foreach (ShapeMatchingMode mode in new[] { ShapeMatchingMode.Rigid, ShapeMatchingMode.Linear, ShapeMatchingMode.Quadratic })
                yield return new ShapeMatchingThroughputScenario(edge, mode, layout);
        }
    }
}
