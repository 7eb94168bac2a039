using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Throughput of every soft-body method on one jelly cube of about 1k, 10k and 100k
    /// nodes resting on a floor: ns per particle-substep per method and size, and the log–log slope of step time against N.
    /// </summary>
    public sealed class SoftBodyMethodsThroughputSuite : IScenarioSuite, IScenarioSuiteSummary
    {
        /// <summary>One row: a label, fixed substeps per step and how to build the body (setup, cell size in m).</summary>
        public sealed class Variant
        {
            public readonly string Label;
            public readonly int Substeps;
            public readonly Func<MethodBodySetup, float, IMethodBody> Create;

            public Variant(string label, int substeps, Func<MethodBodySetup, float, IMethodBody> create)
            {
                Label = label;
                Substeps = substeps;
                Create = create;
            }
        }

        /// <summary>Substeps per 1/60 s step of every variant, at every size.</summary>
        public const int Substeps = 4;
        /// <summary>
        /// Substeps per step of the explicit (symplectic Euler) variants, at every size: the jelly's pressure wave
        /// (c = √((λ + 2μ)/ρ) ≈ 6.2 m/s) crosses a 46³ cube's 22 mm cell in about 3.6 ms, and the Neo-Hookean FEM already
        /// resets at 4 substeps on the 10³ cube.
        /// </summary>
        public const int ExplicitSubsteps = 64;
        /// <summary>Cap on conjugate-gradient iterations per substep of the implicit variants, at every size.</summary>
        public const int CgIterations = 10;
        /// <summary>Shape-matching cluster width in cells: cluster centres 1.5 cells apart, 3 to 4 nodes per axis in a cluster.</summary>
        public const float ClusterCells = 3f;

        /// <summary>Nodes per axis of the full run: 10³ = 1000, 22³ = 10648 and 46³ = 97336 nodes.</summary>
        public static readonly int[] Edges = { 10, 22, 46 };
        /// <summary>Nodes per axis of the quick run: 10³ = 1000 nodes.</summary>
        public static readonly int[] QuickEdges = { 10 };
        /// <summary>Lattice edges of the default run: three sizes for the slope, up to 16³ = 4096 nodes (the full run goes on to 46³).</summary>
        public static readonly int[] StandardEdges = { 10, 13, 16 };

        /// <summary>The variants in report order.</summary>
        public static IReadOnlyList<Variant> Variants { get; } = new[]
        {
            new Variant("SM linear, 3-cell clusters", Substeps,
                (s, h) => new ShapeMatchingMethodBody(s, ShapeMatchingMode.Linear, Substeps, h * ClusterCells / ShapeMatchingMethodBody.ClusterCells)),
            new Variant("MS symplectic Euler", ExplicitSubsteps, (s, h) => new MassSpringMethodBody(s, MassSpringIntegrator.SymplecticEuler, ExplicitSubsteps)),
            new Variant("MS implicit Euler", Substeps, (s, h) => new MassSpringMethodBody(s, MassSpringIntegrator.ImplicitEuler, Substeps, CgIterations)),
            new Variant("MS XPBD", Substeps, (s, h) => new MassSpringMethodBody(s, MassSpringIntegrator.Xpbd, Substeps)),
            new Variant("FEM co-rotational implicit", Substeps,
                (s, h) => new FemMethodBody(s, FemMaterialModel.CoRotational, FemIntegrator.ImplicitEuler, Substeps, CgIterations)),
            new Variant("FEM Neo-Hookean symplectic Euler", ExplicitSubsteps,
                (s, h) => new FemMethodBody(s, FemMaterialModel.NeoHookean, FemIntegrator.SymplecticEuler, ExplicitSubsteps)),
            new Variant("FEM Neo-Hookean XPBD", Substeps, (s, h) => new FemMethodBody(s, FemMaterialModel.NeoHookean, FemIntegrator.Xpbd, Substeps)),
        };

        public string Name => "SoftBodyMethodsThroughput";

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "What one substep of each soft-body method costs per particle on a jelly cube of 1k to 100k nodes, and how that cost scales with N.",
            Body = $"A {SoftBodyMethodsThroughputScenario.BodySize} m cube of {Sizes(Edges)} nodes, 6 tetrahedra per cell; shape matching with overlapping clusters {ClusterCells} cells wide.",
            Material = $"Jelly ({StudyScene.MaterialText(ElasticMaterial.Jelly)}, ζ = {ElasticMaterial.Jelly.DampingRatio}); floor friction 0.5, no sleeping.",
            Load = $"Gravity, settling on a floor plane from rest (put back every {SoftBodyMethodsThroughputScenario.CycleSteps} steps); one 1/60 s step of exactly {Substeps} substeps " +
                   $"({ExplicitSubsteps} for the symplectic Euler variants, whose stable substep shrinks with the cell), implicit CG capped at {CgIterations} iterations per substep.",
            Reference = "none (cost only).",
            Metric = "One item is one particle-substep, so ns/item compares methods and sizes; 'resets': NaN-guard resets in the timed run (0 expected). " +
                     "The summary adds the log–log slope of step time against N (1 = linear).",
            Notes = new[] { $"Default run: {Sizes(StandardEdges)} nodes; quick run: {Sizes(QuickEdges)} only." },
            Details = "choosing-a-method.md#throughput-per-method",
        };

        /// <summary>"10³ = 1000, 22³ = 10648": the node counts of lattice edges.</summary>
        static string Sizes(int[] edges) => string.Join(", ", Array.ConvertAll(edges, e => $"{e}³ = {e * e * e}"));

        /// <summary>None: throughput has no error reference.</summary>
        public string ErrorMetricForPlot => null;

        public IEnumerable<IScenario> Scenarios(RunScope scope) => Build(scope == RunScope.Quick ? QuickEdges : scope == RunScope.Standard ? StandardEdges : Edges);

        static IEnumerable<IScenario> Build(int[] edges)
        {
            foreach (Variant v in Variants)
            foreach (int edge in edges)
                yield return new SoftBodyMethodsThroughputScenario(edge, v);
        }

        /// <summary>
        /// One line per method: ns per particle-substep at each size and the least-squares slope of log(step time) against
        /// log(N) over the sizes run (step time = ns/item × items per step; 1 = cost linear in N).
        /// </summary>
        public string Summary(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            var sizes = new List<int>();
            foreach (ScenarioOutcome r in rows)
                if (!sizes.Contains(r.Size))
                    sizes.Add(r.Size);
            sizes.Sort();
            var md = new StringBuilder();
            md.Append("| method |");
            foreach (int n in sizes)
                md.Append(string.Format(CultureInfo.InvariantCulture, " ns/particle-substep, N = {0} |", n));
            md.AppendLine(" slope of log t against log N |");
            md.Append("|---|");
            foreach (int _ in sizes)
                md.Append("---:|");
            md.AppendLine("---:|");
            var methods = new List<string>();
            foreach (ScenarioOutcome r in rows)
                if (!methods.Contains(r.Method))
                    methods.Add(r.Method);
            foreach (string m in methods)
            {
                md.Append($"| {m} |");
                double sx = 0, sy = 0, sxx = 0, sxy = 0;
                int count = 0;
                foreach (int n in sizes)
                {
                    double ns = double.NaN;
                    foreach (ScenarioOutcome r in rows)
                        if (r.Method == m && r.Size == n)
                        {
                            ns = r.NsPerItem;
                            double x = Math.Log(n), y = Math.Log(r.NsPerItem * Math.Max(1, r.ItemsPerStep));
                            sx += x; sy += y; sxx += x * x; sxy += x * y;
                            count++;
                        }
                    md.Append(double.IsNaN(ns) ? " – |" : string.Format(CultureInfo.InvariantCulture, " {0:F1} |", ns));
                }
                double d = count * sxx - sx * sx;
                md.AppendLine(count >= 2 && d > 0 ? string.Format(CultureInfo.InvariantCulture, " {0:F2} |", (count * sxy - sx * sy) / d) : " – |");
            }
            return md.ToString();
        }
    }
}
