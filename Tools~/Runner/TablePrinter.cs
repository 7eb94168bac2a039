using System.IO;
using System.Linq;

namespace SoftBodyDynamics.Runner
{
    /// <summary>The console table: one row per scenario, time first, then its error metrics.</summary>
    static class TablePrinter
    {
        public static void PrintHeader(TextWriter w)
        {
            w.WriteLine($"{"scenario",-20} {"method",-16} {"size",9} {"ms/step",10} {"ns/item",9}  error metrics");
            w.WriteLine(new string('-', 110));
        }

        public static void PrintRow(TextWriter w, ScenarioResult r)
        {
            string metrics = string.Join("  ", r.Metrics.Select(m => $"{m.Name}={Format.Value(m.Value)}{m.Unit}"));
            w.WriteLine($"{r.Name,-20} {r.Method,-16} {r.Size,9} {r.MedianMs,10:F3} {r.NsPerItem,9:F1}  {metrics}");
        }
    }

    static class Format
    {
        public static string Value(double v)
        {
            if (v == 0) return "0";
            if (double.IsInfinity(v) || double.IsNaN(v)) return v.ToString();
            if (v == System.Math.Floor(v) && System.Math.Abs(v) < 1e6) return v.ToString("0");
            double a = System.Math.Abs(v);
            return a >= 1e-2 && a < 1e4 ? v.ToString("0.###") : v.ToString("0.00E+0");
        }
    }
}
