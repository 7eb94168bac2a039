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
        /// <summary>Lattice edges of the default run: three sizes for the slope, up to 22³ (the full run goes on to 46³).</summary>
        public static readonly int[] StandardEdges = { 10, 16, 22 };

        public string Name => "ShapeMatchingThroughput";

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "What one shape-matching substep costs per particle, from 1k to 100k particles, for each mode and cluster layout.",
            Body = $"A {ShapeMatchingThroughputScenario.BodySize} m cube of {Sizes(Edges)} particles, as one cluster ('1 cluster') or as overlapping " +
                   $"{ShapeMatchingBenchmarkBody.ClusterEdge}×{ShapeMatchingBenchmarkBody.ClusterEdge}×{ShapeMatchingBenchmarkBody.ClusterEdge}-point clusters sharing half their width " +
                   "('4^3 clusters': an interior particle is in 8, so a particle-iteration costs about 8 cluster visits).",
            Material = $"{ShapeMatchingBenchmarkBody.Frequency} Hz, ζ = {ShapeMatchingBenchmarkBody.DampingRatio}, β = {ShapeMatchingBenchmarkBody.Beta}, " +
                       $"friction {ShapeMatchingBenchmarkBody.Friction}, no sleeping; rigid, linear or quadratic goals.",
            Load = $"Gravity, settling on a floor plane from rest; one 1/60 s step of exactly {ShapeMatchingThroughputScenario.Substeps} substeps. The body is put back every " +
                   $"{ShapeMatchingThroughputScenario.CycleSteps} steps, so every timed step is in the first second of settling.",
            Reference = "none (cost only).",
            Metric = "One item is one particle-iteration (a particle through one substep: predict, cluster solve, floor contact, update), so items/s is particle-iterations per second. " +
                     "'resets': NaN-guard resets (0 expected); 'contacts': mean particles touching the floor (at least the bottom layer, edge²).",
            Notes = new[] { $"Default run: {Sizes(StandardEdges)} particles; quick run: {Sizes(QuickEdges)} only." },
            Details = "benchmarks.md#shapematchingthroughput-cost-per-particle-iteration",
        };

        /// <summary>"10³ = 1000, 22³ = 10648": the particle counts of lattice edges.</summary>
        static string Sizes(int[] edges) => string.Join(", ", System.Array.ConvertAll(edges, e => $"{e}³ = {e * e * e}"));

        /// <summary>None: throughput has no error reference (the accuracy suite plots error against cost), so no accuracy figure.</summary>
        public string ErrorMetricForPlot => null;

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            foreach (int edge in quick ? QuickEdges : scope == RunScope.Standard ? StandardEdges : Edges)
            foreach (ShapeMatchingClusterLayout layout in new[] { ShapeMatchingClusterLayout.Single, ShapeMatchingClusterLayout.Overlapping })
            foreach (ShapeMatchingMode mode in new[] { ShapeMatchingMode.Rigid, ShapeMatchingMode.Linear, ShapeMatchingMode.Quadratic })
                yield return new ShapeMatchingThroughputScenario(edge, mode, layout);
        }
    }
}
