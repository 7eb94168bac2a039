using System.Numerics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Migration of the per-frame stiffness of package versions up to 0.2 (α ∈ [0, 1], the fraction of the way
    /// to the goal covered per step, with α_sub = 1 − (1 − α)^(1/n) per substep, goals of the predicted
    /// positions, and a damping rate c in 1/s) to the time-based <see cref="ShapeMatchingParameters.Frequency"/>
    /// and <see cref="ShapeMatchingParameters.DampingRatio"/>. Those versions had no time-based meaning: the
    /// same α was a different material at every step and substep count. This returns the oscillator the old
    /// substep was at one step size (the one the body was tuned at, usually the 1/60 s fixed step): the
    /// eigenvalues λ of its 2×2 substep map
    /// <code>
    ///   x ← (1 − α_sub)(x + h v),   v ← e^{−ch} (v − α_sub (x + h v) / h)
    /// </code>
    /// give s = ln λ / h, hence ω² = s₁s₂ and 2ζω = −(s₁ + s₂).
    /// </summary>
    public static class LegacyStiffness
    {
        /// <param name="alpha">Old stiffness α per step, in (0, 1].</param>
        /// <param name="damping">Old damping rate (1/s).</param>
        /// <param name="substeps">Substeps the body used.</param>
        /// <param name="dt">Step the body was tuned at (s), usually 1/60.</param>
        /// <param name="frequency">Equivalent natural frequency (Hz).</param>
        /// <param name="dampingRatio">Equivalent damping ratio.</param>
        /// <returns>False (and the defaults) for values the old solver could not use.</returns>
        public static bool ToFrequency(float alpha, float damping, int substeps, float dt, out float frequency, out float dampingRatio)
        {
            var d = ShapeMatchingParameters.Default;
            frequency = d.Frequency;
            dampingRatio = d.DampingRatio;
            if (!(alpha > 0f) || !(alpha <= 1f) || !(dt > 0f) || substeps < 1 || !(damping >= 0f) || float.IsInfinity(damping))
                return false;
            double h = dt / (double)substeps;
            double a = alpha >= 1f ? 0.999999 : 1.0 - System.Math.Pow(1.0 - alpha, 1.0 / substeps);
            double e = System.Math.Exp(-damping * h);
            double det = e * (1.0 - a), trace = (1.0 - a) * (1.0 + e);
            Complex root = Complex.Sqrt(new Complex(trace * trace - 4.0 * det, 0.0));
            Complex s1 = Complex.Log((trace + root) / 2.0) / h, s2 = Complex.Log((trace - root) / 2.0) / h;
            // ω² = s₁s₂ and 2ζω = −(s₁ + s₂), for complex-conjugate and for real roots alike.
            double omega = System.Math.Sqrt((s1 * s2).Real);
            if (!(omega > 0.0) || double.IsNaN(omega) || double.IsInfinity(omega))
                return false;
            frequency = (float)(omega / (2.0 * System.Math.PI));
            dampingRatio = (float)(-(s1 + s2).Real / (2.0 * omega));
            return true;
        }
    }
}
