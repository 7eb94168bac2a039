using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Euler–Bernoulli beam formulas for a cantilever (clamped at one end, free at the other), small deflection
    /// (δ/L ≲ 0.1), slender beam (shear and 3-D effects of order (h/L)² neglected). Textbook results, e.g. Timoshenko
    /// &amp; Gere, Mechanics of Materials; Blevins, Formulas for Natural Frequency and Mode Shape, Table 8-1.
    /// </summary>
    public static class EulerBernoulli
    {
        /// <summary>Tip deflection δ = qL⁴/(8EI) (m) under a uniform line load.</summary>
        /// <param name="q">Line load (N/m), e.g. ρ g A for self-weight.</param>
        /// <param name="length">L (m).</param>
        /// <param name="youngModulus">E (Pa).</param>
        /// <param name="secondMoment">I (m⁴), w h³/12 for a rectangle bent across its height h.</param>
        public static double TipDeflectionUnderSelfWeight(double q, double length, double youngModulus, double secondMoment) =>
            q * Math.Pow(length, 4) / (8 * youngModulus * secondMoment);

        /// <summary>First bending frequency f₁ = 1.8751²/(2π) √(EI/(ρA L⁴)) (Hz); 1.8751 solves cos β cosh β = −1.</summary>
        /// <param name="length">L (m).</param>
        /// <param name="youngModulus">E (Pa).</param>
        /// <param name="secondMoment">I (m⁴).</param>
        /// <param name="density">ρ (kg/m³).</param>
        /// <param name="area">A (m²).</param>
        public static double FirstFrequency(double length, double youngModulus, double secondMoment, double density, double area)
        {
            const double beta = 1.875104068711961;
            return beta * beta / (2 * Math.PI) * Math.Sqrt(youngModulus * secondMoment / (density * area * Math.Pow(length, 4)));
        }

        /// <summary>
        /// Timoshenko's shear correction to the self-weight tip deflection, δ_shear/δ_bending = 4EI/(κGAL²) =
        /// 0.8(1 + ν)(h/L)² for a rectangle (κ = 5/6, G = E/(2(1 + ν))): δ_shear = qL²/(2κGA).
        /// </summary>
        /// <param name="height">h (m), the section depth in the bending plane.</param>
        /// <param name="length">L (m).</param>
        /// <param name="poissonRatio">ν.</param>
        public static double ShearCorrectionRatio(double height, double length, double poissonRatio) =>
            0.8 * (1 + poissonRatio) * (height / length) * (height / length);
    }
}
