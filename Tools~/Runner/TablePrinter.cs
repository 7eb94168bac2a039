using System.Collections.Generic;
using System.IO;
using System.Linq;
using SoftBodyDynamics.Benchmarks.Scenarios;

namespace SoftBodyDynamics.Runner
{
    /// <summary>
    /// The console table: one row per scenario, time first (ms per step, ns per item, items per second),
    /// then its error metrics. Column widths fit the longest scenario and method names of the suite.
    /// </summary>
    sealed class TablePrinter
    {
        readonly TextWriter m_Writer;
        readonly int m_NameWidth, m_MethodWidth;

        public TablePrinter(TextWriter writer, IEnumerable<IScenario> scenarios)
        {
            m_Writer = writer;
            m_NameWidth = System.Math.Max(20, scenarios.Select(s => s.Name.Length).DefaultIfEmpty(0).Max());
            m_MethodWidth = System.Math.Max(16, scenarios.Select(s => s.Method.Length).DefaultIfEmpty(0).Max());
        }

        public void PrintHeader()
        {
            m_Writer.WriteLine($"{Pad("scenario", m_NameWidth)} {Pad("method", m_MethodWidth)} {"size",9} {"ms/step",10} {"ns/item",9} {"items/s",9}  error metrics");
            m_Writer.WriteLine(new string('-', m_NameWidth + m_MethodWidth + 52 + 40));
        }

        public void PrintRow(ScenarioResult r)
        {
            string metrics = string.Join("  ", r.Metrics.Select(m => $"{m.Name}={Format.Value(MetricUnits.Displayed(m.Value, m.Unit))}{MetricUnits.Suffix(m.Unit)}"));
            m_Writer.WriteLine($"{Pad(r.Name, m_NameWidth)} {Pad(r.Method, m_MethodWidth)} {r.Size,9} {r.MedianMs,10:F3} {r.NsPerItem,9:F1} {Format.Rate(r.ItemsPerSecond),9}  {metrics}");
            if (r.AllocatedBytesPerStep > 0)
                m_Writer.WriteLine($"  warning: Step allocated {r.AllocatedBytesPerStep:F0} bytes per call (scenarios must not allocate in Step)");
        }

        static string Pad(string s, int width) => s.PadRight(width);
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

        /// <summary>A rate in items per second with three significant digits, e.g. 2.45E+7.</summary>
        public static string Rate(double v) =>
            double.IsInfinity(v) || double.IsNaN(v) ? v.ToString() : v.ToString("0.00E+0");
    }
}
