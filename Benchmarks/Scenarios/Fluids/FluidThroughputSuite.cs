using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Fluid throughput per stage at 10k, 100k and 1M particles, with the log-log slope of time against N.</summary>
    public sealed class FluidThroughputSuite : IScenarioSuite, IScenarioSuiteSummary
    {
        /// <summary>Cube edges: 22³ = 10 648, 46³ = 97 336, 100³ = 1 000 000 particles.</summary>
        public static readonly int[] Sides = { 22, 46, 100 };

        public string Name => "FluidThroughput";

        public string Description =>
            "A cube of water at Δx = 2 cm resting in a box (weakly compressible, c₀ = 20 m/s, α = 0.05, one viscosity iteration, h = 2Δx, " +
            "about 30 neighbours), single-threaded .NET on this machine. Each row times one stage over all particles (an item is one " +
            "particle through that stage); 'WCSPH substep' is the whole substep (FluidSolver.Step of one CFL substep), so its items/s are " +
            "particle-substeps per second. 'pack/unpack' gathers the particle arrays into entity order through a fixed random permutation " +
            "and scatters them back: the extra cost of one entity per particle. Bytes per particle = all solver arrays + the cell table.";

        public string ErrorMetricForPlot => null;

        public IEnumerable<IScenario> Scenarios(bool quick)
        {
            foreach (int side in quick ? new[] { 22 } : Sides)
            foreach (FluidStage stage in (FluidStage[])Enum.GetValues(typeof(FluidStage)))
                yield return new FluidThroughputScenario(side, stage);
        }

        public string Summary(IReadOnlyList<ScenarioOutcome> rows, bool quick)
        {
            var sizes = new List<int>();
            foreach (ScenarioOutcome r in rows)
                if (!sizes.Contains(r.Size))
                    sizes.Add(r.Size);
            var md = new StringBuilder();
            md.Append("| Stage (ns per particle) |");
            foreach (int n in sizes)
                md.Append(' ').Append(n.ToString("N0", CultureInfo.InvariantCulture)).Append(" |");
            md.AppendLine(" slope of time vs N (log-log) |");
            md.Append("|---|");
            foreach (int _ in sizes)
                md.Append("---|");
            md.AppendLine("---|");
            foreach (FluidStage stage in (FluidStage[])Enum.GetValues(typeof(FluidStage)))
            {
                string name = FluidThroughputScenario.StageName(stage);
                md.Append("| ").Append(name).Append(" |");
                var xs = new List<double>();
                var ys = new List<double>();
                foreach (int n in sizes)
                {
                    double ns = double.NaN;
                    foreach (ScenarioOutcome r in rows)
                        if (r.Method == name && r.Size == n)
                            ns = r.NsPerItem;
                    md.Append(string.Format(CultureInfo.InvariantCulture, " {0:0} |", ns));
                    if (!double.IsNaN(ns))
                    {
                        xs.Add(Math.Log(n));
                        ys.Add(Math.Log(ns * n));
                    }
                }
                md.AppendLine(xs.Count >= 2 ? string.Format(CultureInfo.InvariantCulture, " {0:0.00} |", Slope(xs, ys)) : " – |");
            }
            md.AppendLine();
            foreach (int n in sizes)
            {
                double step = Find(rows, FluidStage.Substep, n), pack = Find(rows, FluidStage.PackUnpack, n);
                md.AppendLine(string.Format(CultureInfo.InvariantCulture,
                    "- {0:N0} particles: {1:0.00} M particle-substeps/s; pack/unpack = {2:0.0} % of a substep{3}.",
                    n, 1e3 / step, 100 * pack / step, n >= 50000 ? " (issue target: under 15 % of a step at 100k)" : ""));
            }
            return md.ToString();
        }

        static double Find(IReadOnlyList<ScenarioOutcome> rows, FluidStage stage, int n)
        {
            string name = FluidThroughputScenario.StageName(stage);
            foreach (ScenarioOutcome r in rows)
                if (r.Method == name && r.Size == n)
                    return r.NsPerItem;
            return double.NaN;
        }

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
