using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The exact rule from a time-based material (natural frequency ω, damping ratio ζ) to the per-substep
    /// coefficients of a particle body's substep. The continuous model of every deformation the goals resist
    /// fully is the damped oscillator ẍ = −ω² x − 2ζω ẋ. One substep of length h applies
    /// <code>
    ///   v ← D v − (α / h) x      (damping of the non-rigid velocity, then the pull toward the goal)
    ///   x ← x + h v              (positions follow the velocities)
    /// </code>
    /// whose 2×2 map has determinant D and trace 1 − α + D. Choosing D = λ₁λ₂ and α = (1 − λ₁)(1 − λ₂),
    /// with λ₁,₂ = e^{s₁,₂ h} the eigenvalues of the exact flow over h (s₁,₂ = −ζω ± ω√(ζ² − 1)), gives the
    /// discrete map exactly the eigenvalues of the continuous one: the same frequency and the same decay for
    /// any h, and |λ| ≤ 1, so the substep is stable at any step size. Static deflection under a load f is
    /// h² f / α instead of f / ω²: its relative error 1 − α/(ωh)² ≈ ζωh + O((ωh)²) is bounded by keeping
    /// ωh small (<see cref="SubstepsFor"/>).
    /// Both coefficients are formed without cancellation (products of 1 − e^{−x}), so α stays accurate in
    /// float32 when it is as small as (ωh)² ~ 10⁻⁶.
    /// <para>Above the Nyquist phase θ = ω√(1 − ζ²)h = π no substep can show the oscillator: the exact α would alias, falling
    /// back toward (1 − e^{−ζωh})² each time θ passes a multiple of 2π, so a lightly damped body would lose its pull where
    /// f·h is a whole number and sag freely. There θ is taken as <see cref="AliasedPhase"/> = π/3 instead (α ≤ 1, the
    /// pull of a projection onto the goals, stable for every mode) with the same decay e^{−ζωh}.</para>
    /// </summary>
    public static class OscillatorDiscretization
    {
        /// <summary>Per-substep coefficients.</summary>
        public struct Coefficients
        {
            /// <summary>α: fraction of the way to the goal added per substep, in [0, 4] (above 1 only for π/3 &lt; θ ≤ π).</summary>
            public float Pull;
            /// <summary>D = e^{−2ζωh}: the fraction of the non-rigid velocity kept per substep, in (0, 1].</summary>
            public float VelocityRetention;
        }

        /// <summary>Phase θ (rad) used for a substep whose θ = ω√(1 − ζ²)h is above π: α = 1 there when undamped.</summary>
        public const double AliasedPhase = System.Math.PI / 3.0;

        /// <summary>α and D for angular frequency <paramref name="omega"/> (rad/s), damping ratio <paramref name="zeta"/> and substep <paramref name="h"/> (s).</summary>
        public static Coefficients Compute(float omega, float zeta, float h)
        {
            var c = new Coefficients { Pull = 0f, VelocityRetention = 1f };
            double w = omega, z = zeta, dt = h;
            if (!(w > 0.0) || !(dt > 0.0) || double.IsInfinity(w) || double.IsInfinity(dt))
                return c;
            if (!(z >= 0.0) || double.IsInfinity(z))
                z = 0.0;
            double x = z * w * dt;
            double retention = System.Math.Exp(-2.0 * x);
            double pull;
            if (z < 1.0)
            {
                // |1 − E e^{iθ}|² = (1 − E)² + 4E sin²(θ/2), E = e^{−ζωh}, θ = ω√(1 − ζ²) h.
                double e = System.Math.Exp(-x);
                double oneMinusE = OneMinusExpNeg(x);
                double theta = w * System.Math.Sqrt(1.0 - z * z) * dt;
                double s = System.Math.Sin(0.5 * (theta > System.Math.PI ? AliasedPhase : theta));
                pull = oneMinusE * oneMinusE + 4.0 * e * s * s;
            }
            else
            {
                // Real roots s₁,₂ = −ω(ζ ∓ √(ζ² − 1)): α = (1 − e^{s₁h})(1 − e^{s₂h}).
                double root = System.Math.Sqrt(z * z - 1.0);
                pull = OneMinusExpNeg(w * (z - root) * dt) * OneMinusExpNeg(w * (z + root) * dt);
            }
            c.Pull = (float)pull;
            c.VelocityRetention = (float)retention;
            return c;
        }

        /// <summary>
        /// Substeps for a step <paramref name="dt"/>: at least <paramref name="minSubsteps"/>, and enough that
        /// ω·h ≤ <paramref name="maxPhase"/>, capped at <paramref name="maxSubsteps"/>.
        /// </summary>
        public static int SubstepsFor(float omega, float dt, int minSubsteps, float maxPhase, int maxSubsteps)
        {
            int n = math.max(1, minSubsteps);
            if (omega > 0f && maxPhase > 0f && dt > 0f)
            {
                float needed = math.ceil(omega * dt / maxPhase);
                if (needed > n)
                    n = needed >= maxSubsteps ? maxSubsteps : (int)needed;
            }
            return math.min(n, maxSubsteps);
        }

        /// <summary>1 − e^{−x} for x ≥ 0, accurate for small x.</summary>
        static double OneMinusExpNeg(double x) =>
            x < 1e-5 ? x * (1.0 - 0.5 * x * (1.0 - x / 3.0)) : 1.0 - System.Math.Exp(-x);
    }
}
