namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Surge-front data of Martin &amp; Moyce 1952 (Phil. Trans. R. Soc. A 244:312–324, doi 10.1098/rsta.1952.0006),
    /// Table 2, the n² = 2 column (width a = 2¼ in = 0.05715 m, height 2a, dry bed): front position Z = x/a against
    /// T = t·√(2g/a). The values are the table as transcribed in TormodLandet/Ocellaris scripts/plot_dam_break.py
    /// (the same Z values appear in chaos-polymtl/lethe's dam-break example within ±0.02). An independent
    /// digitisation of the paper's Fig. 3 (pypr/pysph db_exp_data.py) agrees within −0.025…+0.064 in T, so the
    /// experimental uncertainty is about ±0.07 in T. The gate took time to open: comparisons commonly shift the
    /// simulated time by up to 0.2 (lethe adds 0.175).
    /// </summary>
    public static class MartinMoyce1952
    {
        /// <summary>Column width a (m).</summary>
        public const double ColumnWidth = 0.05715;

        /// <summary>Dimensionless time T = t·√(2g/a) of each table point.</summary>
        public static readonly double[] T = { 0.41, 0.84, 1.19, 1.43, 1.63, 1.83, 1.98, 2.20, 2.32, 2.51, 2.65, 2.83, 2.98, 3.11, 3.33 };

        /// <summary>Front position Z = x_front/a of each table point.</summary>
        public static readonly double[] Z = { 1.11, 1.22, 1.44, 1.67, 1.89, 2.11, 2.33, 2.56, 2.78, 3.00, 3.22, 3.44, 3.67, 3.89, 4.11 };

        /// <summary>
        /// Dimensionless time τ = t·√(g/a) of each residual-column point (Table 6, n² = 2, as transcribed in the same
        /// Ocellaris script): T = τ·√2. The last three points (τ ≥ 4.2) come after the front reaches the end of a 6a tank.
        /// </summary>
        public static readonly double[] Tau = { 0.56, 0.77, 0.93, 1.08, 1.28, 1.46, 1.66, 1.84, 2.00, 2.21, 2.45, 2.70, 3.06, 3.44, 4.20, 5.25, 7.40 };

        /// <summary>Residual column height H = η/(n²a) at the wall the column stood against, at each <see cref="Tau"/>.</summary>
        public static readonly double[] Height = { 0.94, 0.89, 0.83, 0.78, 0.72, 0.67, 0.61, 0.56, 0.50, 0.44, 0.39, 0.33, 0.28, 0.22, 0.17, 0.11, 0.06 };

        /// <summary>T of a time t (s) with gravity g (m/s²).</summary>
        public static double DimensionlessTime(double t, double g = 9.81) => t * System.Math.Sqrt(2 * g / ColumnWidth);
    }
}
