using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>The frequency of a recorded oscillation: a least-squares damped sine (standing wave, droplet).</summary>
    public static class DampedSineFit
    {
        /// <summary>
        /// Least-squares fit of y(t) ≈ e^(−γt)(a·sin ωt + b·cos ωt) + c: for each (ω, γ) the linear coefficients are solved
        /// exactly; ω is scanned over ±30 % of <paramref name="guess"/> and γ over 0…2ω/(2π), then refined by golden
        /// sections. Returns ω (rad/s), γ (1/s), √(a² + b²) and the RMS residual (units of y).
        /// </summary>
        public static (double omega, double damping, double amplitude, double residual) Fit(double[] t, double[] y, double guess)
        {
            double bestOmega = guess, bestDamping = 0, best = double.MaxValue;
            for (int i = 0; i <= 120; i++)
            {
                double w = guess * (0.7 + 0.6 * i / 120.0);
                for (int j = 0; j <= 20; j++)
                {
                    double g = j / 20.0 * 2.0 * w / (2 * Math.PI);
                    double r = Residual(t, y, w, g, out _);
                    if (r < best)
                    {
                        best = r;
                        bestOmega = w;
                        bestDamping = g;
                    }
                }
            }
            double step = 0.6 * guess / 120.0, gStep = 2.0 * guess / (2 * Math.PI) / 20.0;
            for (int round = 0; round < 4; round++)
            {
                bestOmega = Golden(w => Residual(t, y, w, bestDamping, out _), bestOmega - step, bestOmega + step);
                bestDamping = Golden(g => Residual(t, y, bestOmega, g, out _), Math.Max(0, bestDamping - gStep), bestDamping + gStep);
                step *= 0.5;
                gStep *= 0.5;
            }
            double residual = Residual(t, y, bestOmega, bestDamping, out double amplitude);
            return (bestOmega, bestDamping, amplitude, residual);
        }

        static double Golden(Func<double, double> f, double lo, double hi)
        {
            double phi = (Math.Sqrt(5) - 1) / 2;
            double a = hi - phi * (hi - lo), b = lo + phi * (hi - lo);
            double fa = f(a), fb = f(b);
            for (int i = 0; i < 60; i++)
            {
                if (fa < fb) { hi = b; b = a; fb = fa; a = hi - phi * (hi - lo); fa = f(a); }
                else { lo = a; a = b; fa = fb; b = lo + phi * (hi - lo); fb = f(b); }
            }
            return 0.5 * (lo + hi);
        }

        /// <summary>RMS residual of the best a, b, c for a given ω and γ (3 × 3 normal equations).</summary>
        static double Residual(double[] t, double[] y, double omega, double damping, out double amplitude)
        {
            var m = new double[3, 3];
            var v = new double[3];
            int n = t.Length;
            for (int i = 0; i < n; i++)
            {
                double e = Math.Exp(-damping * t[i]);
                double s = e * Math.Sin(omega * t[i]), c = e * Math.Cos(omega * t[i]);
                double[] basis = { s, c, 1.0 };
                for (int r = 0; r < 3; r++)
                {
                    v[r] += basis[r] * y[i];
                    for (int q = 0; q < 3; q++)
                        m[r, q] += basis[r] * basis[q];
                }
            }
            double[] coef = Solve3(m, v);
            double sum = 0;
            for (int i = 0; i < n; i++)
            {
                double e = Math.Exp(-damping * t[i]);
                double d = y[i] - (coef[0] * e * Math.Sin(omega * t[i]) + coef[1] * e * Math.Cos(omega * t[i]) + coef[2]);
                sum += d * d;
            }
            amplitude = Math.Sqrt(coef[0] * coef[0] + coef[1] * coef[1]);
            return Math.Sqrt(sum / n);
        }

        static double[] Solve3(double[,] m, double[] v)
        {
            double det = Det(m[0, 0], m[0, 1], m[0, 2], m[1, 0], m[1, 1], m[1, 2], m[2, 0], m[2, 1], m[2, 2]);
            if (!(Math.Abs(det) > 0))
                return new double[3];
            return new[]
            {
                Det(v[0], m[0, 1], m[0, 2], v[1], m[1, 1], m[1, 2], v[2], m[2, 1], m[2, 2]) / det,
                Det(m[0, 0], v[0], m[0, 2], m[1, 0], v[1], m[1, 2], m[2, 0], v[2], m[2, 2]) / det,
                Det(m[0, 0], m[0, 1], v[0], m[1, 0], m[1, 1], v[1], m[2, 0], m[2, 1], v[2]) / det,
            };
        }

        static double Det(double a, double b, double c, double d, double e, double f, double g, double h, double i) =>
            a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
    }
}
