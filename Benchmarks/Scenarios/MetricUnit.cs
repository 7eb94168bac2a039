namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// The unit of a <see cref="Metric"/>'s value, written beside it in results.csv. Every relative error or deviation is a
    /// <see cref="Fraction"/> (0.05 = 5 %); tables print fractions as percent.
    /// </summary>
    public enum MetricUnit
    {
        /// <summary>A relative error or deviation, as a fraction of its reference (0.05 = 5 %).</summary>
        Fraction,
        /// <summary>A pure number that is not a relative error: a ratio such as sag/sag₀, an order of convergence, a mean count.</summary>
        Dimensionless,
        /// <summary>A whole number of things or events (particles, resets, substeps).</summary>
        Count,
        /// <summary>1 = yes, 0 = no.</summary>
        Flag,
        /// <summary>An enumerated outcome; the suite's definition lists the values.</summary>
        Code,
        /// <summary>Metres.</summary>
        Metre,
        /// <summary>Millimetres.</summary>
        Millimetre,
        /// <summary>Seconds.</summary>
        Second,
        /// <summary>Milliseconds.</summary>
        Millisecond,
        /// <summary>Nanoseconds.</summary>
        Nanosecond,
        /// <summary>Hertz.</summary>
        Hertz,
        /// <summary>Radians.</summary>
        Radian,
        /// <summary>Metres per second.</summary>
        MetrePerSecond,
        /// <summary>Joules per kilogram (specific energy).</summary>
        JoulePerKilogram,
        /// <summary>Bytes.</summary>
        Byte,
        /// <summary>Multiples of the fluid's particle spacing Δx.</summary>
        ParticleSpacing,
        /// <summary>Multiples of the dam-break column width a (Martin &amp; Moyce's Z = x/a).</summary>
        ColumnWidth,
        /// <summary>Martin &amp; Moyce's dimensionless time T = t·√(2g/a).</summary>
        DimensionlessTime,
    }

    /// <summary>Text of a <see cref="MetricUnit"/> for the CSV and the tables.</summary>
    public static class MetricUnits
    {
        /// <summary>The unit as results.csv writes it.</summary>
        public static string Symbol(MetricUnit unit)
        {
            switch (unit)
            {
                case MetricUnit.Fraction: return "fraction";
                case MetricUnit.Dimensionless: return "1";
                case MetricUnit.Count: return "count";
                case MetricUnit.Flag: return "flag";
                case MetricUnit.Code: return "code";
                case MetricUnit.Metre: return "m";
                case MetricUnit.Millimetre: return "mm";
                case MetricUnit.Second: return "s";
                case MetricUnit.Millisecond: return "ms";
                case MetricUnit.Nanosecond: return "ns";
                case MetricUnit.Hertz: return "Hz";
                case MetricUnit.Radian: return "rad";
                case MetricUnit.MetrePerSecond: return "m/s";
                case MetricUnit.JoulePerKilogram: return "J/kg";
                case MetricUnit.Byte: return "B";
                case MetricUnit.ParticleSpacing: return "dx";
                case MetricUnit.ColumnWidth: return "a";
                case MetricUnit.DimensionlessTime: return "T";
                default: return "?";
            }
        }

        /// <summary>The suffix a table prints after a value of this unit ("" for pure numbers, counts, flags and codes).</summary>
        public static string Suffix(MetricUnit unit)
        {
            switch (unit)
            {
                case MetricUnit.Fraction: return " %";
                case MetricUnit.Dimensionless:
                case MetricUnit.Count:
                case MetricUnit.Flag:
                case MetricUnit.Code:
                    return "";
                default: return " " + Symbol(unit);
            }
        }

        /// <summary>The value as a table shows it: fractions ×100 (with <see cref="Suffix"/> " %"), others unchanged.</summary>
        public static double Displayed(double value, MetricUnit unit) => unit == MetricUnit.Fraction ? 100.0 * value : value;
    }
}
