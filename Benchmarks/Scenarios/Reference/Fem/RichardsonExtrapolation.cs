using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>A quantity's observed convergence: f(h) ≈ f₀ + C h^p fitted through three (h, f).</summary>
    public struct ConvergenceEstimate
    {
        /// <summary>Observed order p; NaN if the three values do not converge monotonically.</summary>
        public double Order;
        /// <summary>Richardson-extrapolated f₀ (the h → 0 limit); the finest value if p is NaN.</summary>
        public double Extrapolated;
        /// <summary>|f(h_finest) − f₀|: the estimated error of the finest value; the extrapolated value is more accurate
        /// than this by about (h_finest / h_middle)^p or better.</summary>
        public double ErrorEstimate;
    }

    /// <summary>
    /// Richardson extrapolation (Roache, Verification and Validation in Computational Science and Engineering, 1998,
    /// §5.4) from three values at sizes h₁ &gt; h₂ &gt; h₃ (any ratios): p solves
    /// (f₁ − f₂)/(f₂ − f₃) = (h₁^p − h₂^p)/(h₂^p − h₃^p) (by bisection on [0.05, 20]), then
    /// f₀ = f₃ − (f₂ − f₃) h₃^p / (h₂^p − h₃^p).
    /// </summary>
    public static class RichardsonExtrapolation
    {
        /// <summary>The estimate from the last three entries (h descending, e.g. element size or time step).</summary>
        public static ConvergenceEstimate Estimate(ReadOnlySpan<double> h, ReadOnlySpan<double> f)
        {
            int n = h.Length;
            if (n < 3 || f.Length != n)
                throw new ArgumentException("Need three or more (h, f) pairs.");
            double h1 = h[n - 3], h2 = h[n - 2], h3 = h[n - 1];
            double f1 = f[n - 3], f2 = f[n - 2], f3 = f[n - 1];
            double ratio = (f1 - f2) / (f2 - f3);
            var result = new ConvergenceEstimate { Order = double.NaN, Extrapolated = f3, ErrorEstimate = double.NaN };
            if (!(ratio > 0) || double.IsInfinity(ratio))
                return result;
            double G(double p) => (Math.Pow(h1, p) - Math.Pow(h2, p)) / (Math.Pow(h2, p) - Math.Pow(h3, p)) - ratio;
            double lo = 0.05, hi = 20;
            if (G(lo) > 0 || G(hi) < 0)
                return result;
            for (int it = 0; it < 200; it++)
            {
                double mid = 0.5 * (lo + hi);
                if (G(mid) > 0) hi = mid; else lo = mid;
            }
            double order = 0.5 * (lo + hi);
            double f0 = f3 - (f2 - f3) * Math.Pow(h3, order) / (Math.Pow(h2, order) - Math.Pow(h3, order));
            result.Order = order;
            result.Extrapolated = f0;
            result.ErrorEstimate = Math.Abs(f3 - f0);
            return result;
        }
    }
}
