using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Fluid throughput at 10k, 100k and 1M particles with the log-log slope, split by stage, with the pack/unpack share and the bytes per particle.</summary>
    public sealed class FluidThroughputSuite : IScenarioSuite, IScenarioSuiteSummary
    {
        /// <summary>Cube edges: 22³ = 10 648, 46³ = 97 336, 100³ = 1 000 000 particles.</summary>
        public static readonly int[] Sides = { 22, 46, 100 };
        /// <summary>Cube sides of the default run: three sizes for the slope, up to 46³ (the full run goes on to 100³ = 1M).</summary>
        public static readonly int[] StandardSides = { 22, 32, 46 };

        /// <summary>The issue's target for the weakly compressible substep on one core in .NET (particle-substeps per second).</summary>
        public const double TargetPerSecond = 1e6;

        public string Name => "FluidThroughput";

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "What one weakly compressible SPH substep costs per particle from 10k to 1M particles, stage by stage, with the cost of entity-order pack/unpack and the memory per particle.",
            Body = $"A cube of water of {string.Join(", ", Array.ConvertAll(Sides, n => $"{n}³ = {(n * n * n).ToString("N0", CultureInfo.InvariantCulture)}"))} particles at Δx = 2 cm, resting in a box.",
            Material = "Weakly compressible: c₀ = 20 m/s, α = 0.05, one viscosity iteration, h = 2Δx (26 neighbours on the rest lattice, 27–29 in the settled block).",
            Load = "Gravity, at rest; each timed step is one CFL substep, single-threaded managed .NET on this machine.",
            Reference = "none (cost only); the staged row is checked bit for bit against FluidSolver.Step at setup ('same bits as FluidSolver.Step').",
            Metric = "One item is one particle through one substep (pack/unpack: one particle gathered and scattered back), so items/s is particle-substeps per second. " +
                     "The staged row gives each stage's ns per particle (median over its steps); " +
                     "'bytes per particle' = all solver arrays + the cell table.",
            Notes = new[]
            {
                "'pack/unpack' gathers the particle arrays into entity order through a fixed random permutation and scatters them back: the extra cost of one entity per particle.",
                $"Default run: {string.Join(", ", Array.ConvertAll(StandardSides, n => n + "³"))} particles; quick run: {Sides[0]}³ only.",
            },
            Details = "fluids.md#throughput-fluidthroughput",
        };

        public string ErrorMetricForPlot => null;

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            foreach (int side in quick ? new[] { Sides[0] } : scope == RunScope.Standard ? StandardSides : Sides)
            foreach (FluidThroughputRow row in (FluidThroughputRow[])Enum.GetValues(typeof(FluidThroughputRow)))
                yield return new FluidThroughputScenario(side, row);
        }

        public string Summary(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            var sizes = new List<int>();
            foreach (ScenarioOutcome r in rows)
                if (!sizes.Contains(r.Size))
                    sizes.Add(r.Size);
            var md = new StringBuilder();
            md.Append("| ns per particle |");
            foreach (int n in sizes)
                md.Append(' ').Append(n.ToString("N0", CultureInfo.InvariantCulture)).Append(" |");
            md.AppendLine(" slope of time vs N (log-log) |");
            md.Append("|---|");
            foreach (int _ in sizes)
                md.Append("---|");
            md.AppendLine("---|");
            string substep = FluidThroughputScenario.RowName(FluidThroughputRow.Substep);
            string staged = FluidThroughputScenario.RowName(FluidThroughputRow.Staged);
            string pack = FluidThroughputScenario.RowName(FluidThroughputRow.PackUnpack);
            AppendLine(md, "whole substep (FluidSolver.Step)", sizes, n => Find(rows, substep, n).NsPerItem);
            foreach (FluidStage stage in (FluidStage[])Enum.GetValues(typeof(FluidStage)))
                if (AnyPositive(sizes, n => Find(rows, staged, n).Value(FluidThroughputScenario.StageMetric(stage))))
                    AppendLine(md, "– " + FluidThroughputScenario.StageName(stage), sizes, n => Find(rows, staged, n).Value(FluidThroughputScenario.StageMetric(stage)));
            AppendLine(md, "staged substep (sum, with stopwatches)", sizes, n => Find(rows, staged, n).NsPerItem);
            AppendLine(md, "pack/unpack (entity gather + scatter)", sizes, n => Find(rows, pack, n).NsPerItem);
            md.AppendLine();
            foreach (int n in sizes)
            {
                ScenarioOutcome step = Find(rows, substep, n), stagedRow = Find(rows, staged, n);
                double perSecond = 1e9 / step.NsPerItem;
                md.AppendLine(string.Format(CultureInfo.InvariantCulture,
                    "- {0:N0} particles ({1:0.0} neighbours): {2:0.00} M particle-substeps/s ({3} the {4:0.#} M/s target); pack/unpack = {5:0.0} % of a substep; " +
                    "{6:0} bytes per particle; staged substep {7} FluidSolver.Step's bits.",
                    n, step.Value("neighbours"), perSecond * 1e-6, perSecond >= TargetPerSecond ? "meets" : "below", TargetPerSecond * 1e-6,
                    100 * Find(rows, pack, n).NsPerItem / step.NsPerItem, step.Value("bytes per particle"),
                    stagedRow.Value("same bits as FluidSolver.Step") == 1 ? "matches" : "does NOT match"));
            }
            return md.ToString();
        }

        static bool AnyPositive(List<int> sizes, Func<int, double> value)
        {
            foreach (int n in sizes)
                if (value(n) > 0)
                    return true;
            return false;
        }

        static void AppendLine(StringBuilder md, string label, List<int> sizes, Func<int, double> nsPerParticle)
        {
            md.Append("| ").Append(label).Append(" |");
            var xs = new List<double>();
            var ys = new List<double>();
            foreach (int n in sizes)
            {
                double ns = nsPerParticle(n);
                md.Append(string.Format(CultureInfo.InvariantCulture, " {0:0} |", ns));
                if (ns > 0)
                {
                    xs.Add(Math.Log(n));
                    ys.Add(Math.Log(ns * n));
                }
            }
            md.AppendLine(xs.Count >= 2 ? string.Format(CultureInfo.InvariantCulture, " {0:0.00} |", Slope(xs, ys)) : " – |");
        }

        static ScenarioOutcome Find(IReadOnlyList<ScenarioOutcome> rows, string method, int n)
        {
            foreach (ScenarioOutcome r in rows)
                if (r.Method == method && r.Size == n)
                    return r;
            return new ScenarioOutcome(method, double.NaN, Array.Empty<Metric>(), n);
        }

        /// <summary>Least-squares slope of <paramref name="ys"/> against <paramref name="xs"/>.</summary>
        static double Slope(List<double> xs, List<double> ys)
        {
            double mx = 0, my = 0;
            for (int i = 0; i < xs.Count; i++)
            {
                mx += xs[i];
                my += ys[i];
            }
            mx /= xs.Count;
            my /= xs.Count;
            double sxy = 0, sxx = 0;
            for (int i = 0; i < xs.Count; i++)
            {
                sxy += (xs[i] - mx) * (ys[i] - my);
                sxx += (xs[i] - mx) * (xs[i] - mx);
            }
            return sxy / sxx;
        }
    }
}
