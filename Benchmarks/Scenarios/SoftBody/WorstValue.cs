namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Running maximum of an error that treats NaN as the worst value (a plain max would hide or spread it).</summary>
    public static class WorstValue
    {
        /// <summary>The larger of <paramref name="worst"/> and <paramref name="value"/>; +∞ when <paramref name="value"/> is NaN.</summary>
        public static double Max(double worst, double value) =>
            value <= worst ? worst : double.IsNaN(value) ? double.PositiveInfinity : value;
    }
}
