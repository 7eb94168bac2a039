using System;
using System.Numerics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>What <see cref="OscillationFit.Fit"/> found.</summary>
    public struct OscillationEstimate
    {
        /// <summary>Natural frequency f = ω/2π (Hz) with ω² = |s|² of the fitted exponent s.</summary>
        public double Frequency;
        /// <summary>Damping ratio ζ = −Re s / |s|.</summary>
        public double DampingRatio;
        /// <summary>Standard error of <see cref="Frequency"/> from the least-squares residual (Hz).</summary>
        public double FrequencyError;
        /// <summary>Standard error of <see cref="DampingRatio"/> from the least-squares residual.</summary>
        public double DampingRatioError;
        /// <summary>RMS residual of the recurrence over the RMS of the samples (dimensionless; 0 for an exact damped oscillation).</summary>
        public double RelativeResidual;
        /// <summary>σ: the residual's standard deviation per sample (units of the samples), from which the standard errors follow.</summary>
        public double Noise;
        /// <summary>Standard error of <see cref="Frequency"/> per unit of per-sample noise (Hz per unit of y): the error is σ × this.</summary>
        public double FrequencySensitivity;
        /// <summary>Standard error of <see cref="DampingRatio"/> per unit of per-sample noise (per unit of y).</summary>
        public double DampingRatioSensitivity;
        /// <summary>False when the samples are not a damped oscillation (too few, or no decaying pair of exponents).</summary>
        public bool Valid;
    }

    /// <summary>
    /// Frequency and damping ratio of uniformly sampled data yₙ = y(n·dt) of a damped oscillator, by linear
    /// prediction (Prony's method with two exponents): a sum c₁μ₁ⁿ + c₂μ₂ⁿ satisfies yₙ₊₁ = p yₙ + q yₙ₋₁ exactly, with
    /// μ₁,₂ the roots of μ² − pμ − q; p and q are fitted by least squares over every sample, and s = ln μ / dt gives
    /// ω = |s| and ζ = −Re s/|s|. The fit is exact (no dependence on the phase or amplitude of the data and no
    /// windowing) when the data are such a sum, which the solver's fully resisted mode is, so what it reports is the
    /// solver's own frequency and decay plus round-off. A sampled oscillation determines its phase per sample θ only
    /// modulo 2π: above the Nyquist frequency (f &gt; 1/(2dt)) the branch nearest an expected frequency is taken.
    /// </summary>
    public static class OscillationFit
    {
        /// <param name="samples">y₀ … y_{n−1}, n ≥ 5.</param>
        /// <param name="dt">Sample spacing (s).</param>
        /// <param name="expectedFrequency">Frequency (Hz) used only to pick the branch of an aliased phase; 0 takes the principal branch.</param>
        public static OscillationEstimate Fit(double[] samples, double dt, double expectedFrequency = 0)
        {
            var result = new OscillationEstimate();
            int n = samples.Length;
            if (n < 5)
                return result;
            // Normal equations of yₙ₊₁ = p yₙ + q yₙ₋₁, n = 1 … N−2.
            double saa = 0, sab = 0, sbb = 0, sya = 0, syb = 0, syy = 0;
            for (int k = 1; k < n - 1; k++)
            {
                double a = samples[k], b = samples[k - 1], y = samples[k + 1];
                saa += a * a; sab += a * b; sbb += b * b; sya += y * a; syb += y * b;
            }
            for (int k = 0; k < n; k++)
                syy += samples[k] * samples[k];
            double det = saa * sbb - sab * sab;
            if (!(Math.Abs(det) > 0))
                return result;
            double p = (sya * sbb - syb * sab) / det;
            double q = (syb * saa - sya * sab) / det;
            double residual = 0;
            for (int k = 1; k < n - 1; k++)
            {
                double r = samples[k + 1] - p * samples[k] - q * samples[k - 1];
                residual += r * r;
            }
            int rows = n - 2;
            double sigma2 = rows > 2 ? residual / (rows - 2) : 0;
            result.RelativeResidual = Math.Sqrt(residual / rows) / Math.Sqrt(syy / n);
            // Covariance of (p, q) = σ² (MᵀM)⁻¹; computed per unit σ², then scaled.
            double cpp = sbb / det, cqq = saa / det, cpq = -sab / det;
            if (!Exponents(p, q, dt, expectedFrequency, out double omega, out double zeta))
                return result;
            // Standard errors by the delta method with a numerical Jacobian.
            double dp = 1e-7 * Math.Max(1e-3, Math.Abs(p)), dq = 1e-7 * Math.Max(1e-3, Math.Abs(q));
            if (!Exponents(p + dp, q, dt, expectedFrequency, out double op, out double zp)
                || !Exponents(p, q + dq, dt, expectedFrequency, out double oq, out double zq))
                return result;
            double wp = (op - omega) / dp, wq = (oq - omega) / dq, zpp = (zp - zeta) / dp, zqq = (zq - zeta) / dq;
            double varOmega = wp * wp * cpp + 2 * wp * wq * cpq + wq * wq * cqq;
            double varZeta = zpp * zpp * cpp + 2 * zpp * zqq * cpq + zqq * zqq * cqq;
            result.Frequency = omega / (2 * Math.PI);
            result.DampingRatio = zeta;
            result.Noise = Math.Sqrt(sigma2);
            result.FrequencySensitivity = Math.Sqrt(Math.Max(0, varOmega)) / (2 * Math.PI);
            result.DampingRatioSensitivity = Math.Sqrt(Math.Max(0, varZeta));
            result.FrequencyError = result.Noise * result.FrequencySensitivity;
            result.DampingRatioError = result.Noise * result.DampingRatioSensitivity;
            result.Valid = true;
            return result;
        }

        /// <summary>ω and ζ of the recurrence yₙ₊₁ = p yₙ + q yₙ₋₁ sampled at dt.</summary>
        static bool Exponents(double p, double q, double dt, double expectedFrequency, out double omega, out double zeta)
        {
            omega = zeta = double.NaN;
            Complex root = Complex.Sqrt(new Complex(p * p + 4 * q, 0));
            Complex mu1 = (p + root) / 2, mu2 = (p - root) / 2;
            if (mu1.Magnitude == 0 || mu2.Magnitude == 0)
                return false;
            Complex s1 = Complex.Log(mu1) / dt, s2 = Complex.Log(mu2) / dt;
            if (Math.Abs(s1.Imaginary) > 0 || Math.Abs(s2.Imaginary) > 0)
            {
                // Complex pair: decay σ = ln|μ| / dt, damped frequency ω_d = θ/dt with θ ∈ (0, π], unaliased toward the expected one.
                double sigma = Math.Log(mu1.Magnitude) / dt;
                double theta = Math.Abs(Complex.Log(mu1).Imaginary);
                double damped = theta / dt;
                if (expectedFrequency > 0)
                {
                    double expected = 2 * Math.PI * expectedFrequency, period = 2 * Math.PI / dt, best = double.PositiveInfinity;
                    for (int k = 0; k < 64; k++)
                    foreach (double candidate in new[] { k * period + theta / dt, (k + 1) * period - theta / dt })
                        if (Math.Abs(candidate - expected) < Math.Abs(best - expected))
                            best = candidate;
                    damped = best;
                }
                omega = Math.Sqrt(damped * damped + sigma * sigma);
                zeta = -sigma / omega;
            }
            else
            {
                // Two real exponents (overdamped): ω² = s₁s₂, 2ζω = −(s₁ + s₂). Negative μ cannot come from such a pair.
                if (mu1.Real <= 0 || mu2.Real <= 0)
                    return false;
                double product = s1.Real * s2.Real;
                if (!(product > 0))
                    return false;
                omega = Math.Sqrt(product);
                zeta = -(s1.Real + s2.Real) / (2 * omega);
            }
            return !double.IsNaN(omega) && !double.IsNaN(zeta);
        }
    }
}
