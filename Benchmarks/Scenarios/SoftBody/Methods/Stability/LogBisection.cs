using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>The largest value at which a yes/no test passes, by bisection on a logarithmic scale.</summary>
    public static class LogBisection
    {
        /// <summary>
        /// Tests <paramref name="hi"/> first and returns it when it passes (the answer is then "at least hi"); otherwise,
        /// taking <paramref name="lo"/> as passing (it is not tested), halves log(hi/lo) at the geometric midpoint √(lo·hi)
        /// until hi/lo ≤ <paramref name="factor"/>, and returns lo: the largest value seen to pass, with a failing one at
        /// most <paramref name="factor"/> above it. When passing is not monotone in the value, this is one of the edges.
        /// </summary>
        /// <param name="passes">The test.</param>
        /// <param name="lo">Lower end (&gt; 0), assumed to pass.</param>
        /// <param name="hi">Upper end (&gt; lo).</param>
        /// <param name="factor">Resolution as a ratio (&gt; 1).</param>
        /// <param name="evaluations">Calls of <paramref name="passes"/> made.</param>
        public static double Largest(Func<double, bool> passes, double lo, double hi, double factor, out int evaluations)
        {
            if (!(lo > 0) || !(hi > lo) || !(factor > 1))
                throw new ArgumentOutOfRangeException(nameof(factor), "Need 0 < lo < hi and factor > 1.");
            evaluations = 1;
            if (passes(hi))
                return hi;
            while (hi / lo > factor)
            {
                double mid = Math.Sqrt(lo * hi);
                evaluations++;
                if (passes(mid))
                    lo = mid;
                else
                    hi = mid;
            }
            return lo;
        }
    }
}
