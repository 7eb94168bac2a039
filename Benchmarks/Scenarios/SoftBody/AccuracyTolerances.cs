using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// The tolerances the accuracy suites and tests hold the solver to, each derived from the discretisation rule
    /// or from float32 round-off (Documentation~/accuracy.md explains each term), never from a measured value.
    /// </summary>
    public static class AccuracyTolerances
    {
        /// <summary>u = 2⁻²⁴: the largest relative error of one float32 rounding.</summary>
        public const double Unit = 5.9604644775390625e-8;

        /// <summary>
        /// α = (1 − λ₁)(1 − λ₂) with λ₁,₂ = e^{s₁,₂h} the eigenvalues of the exact flow of ẍ = −ω²x − 2ζωẋ over h:
        /// 1 − 2e^{−ζωh} cos(ω√(1−ζ²) h) + e^{−2ζωh} for ζ &lt; 1, the product of real factors otherwise.
        /// </summary>
        public static double Pull(double omega, double zeta, double h)
        {
            double x = omega * h;
            if (zeta < 1)
                return 1 - 2 * Math.Exp(-zeta * x) * Math.Cos(x * Math.Sqrt(1 - zeta * zeta)) + Math.Exp(-2 * zeta * x);
            double root = Math.Sqrt(zeta * zeta - 1);
            return (1 - Math.Exp(-(zeta - root) * x)) * (1 - Math.Exp(-(zeta + root) * x));
        }

        /// <summary>
        /// Largest relative sag error the substep phase limit allows: (ωh)²/α − 1 at ωh = <paramref name="maxPhase"/>
        /// (≈ ζ·φ + (1/12 + ζ²/3)·φ²; it grows with ωh, so every h ≤ φ/ω has a smaller one).
        /// </summary>
        public static double SagBound(double zeta, double maxPhase) => RestingSag.PredictedSagRatio(1.0, zeta, maxPhase) - 1;

        /// <summary>
        /// Relative errors of the fully resisted mode's frequency and damping ratio that float32 coefficients allow,
        /// with u = 2⁻²⁴ and x = ωh:
        /// <list type="bullet">
        /// <item>decay: D = e^{−2ζx} is stored in float32 (relative error ≤ u) and the decay rate per substep is −ln D / 2h,
        /// so ζω is off by ≤ u / (2ζx), plus 4u for ω, h and the products;</item>
        /// <item>damped frequency: α, 1/h and h each carry ≤ u (cos θ moves by ≤ 3uα/2, θ by ≤ 1.5u·x, relative 1.5u), f and
        /// the frame time ≤ 3u more, and D's error moves cos θ = (1 − α + D)/(2√D) by (D − 1 + α)/(4D^{3/2})·uD, relative
        /// (2ζ + x)·u / (8(1 − ζ²)x); 8u covers the first terms;</item>
        /// <item>ω² = ω_d² + σ², so the natural frequency's error is ≤ the damped one's + ζ²·(decay's), and ζ = σ/ω adds both.</item>
        /// </list>
        /// </summary>
        public static void CoefficientRounding(double omega, double zeta, double h, out double frequency, out double dampingRatio)
        {
            double x = omega * h;
            double decay = (zeta > 0 ? Unit / (2 * zeta * x) : 0) + 4 * Unit;
            double damped = 8 * Unit + (2 * zeta + x) * Unit / (8 * Math.Max(1e-3, 1 - zeta * zeta) * x);
            frequency = damped + zeta * zeta * decay;
            dampingRatio = decay + frequency;
        }

        /// <summary>
        /// The per-frame noise σₐ (m) that float32 positions add to the fitted amplitude y of a mode with pattern s:
        /// each substep rounds every coordinate (uniform, standard deviation ≤ u·X/√3 for |x| ≤ X, and up to α times
        /// that again through the goals), which projects onto y = Σ mᵢsᵢxᵢ / Σ mᵢsᵢ² with the factor √(Σ m²s²)/Σ ms²,
        /// adds up over the n substeps of a frame (√n), and enters the recurrence residual of three samples at most
        /// 1 + |p| ≤ 3 times (older perturbations follow the oscillator and cancel in the recurrence).
        /// </summary>
        public static double PositionRoundingNoise(double extent, int substeps, double pull, double projection) =>
            3 * Math.Sqrt(substeps) * (1 + pull) * Unit * extent / Math.Sqrt(3) * projection;

        /// <summary>ulp of a float32 of magnitude <paramref name="x"/>: 2^(⌊log₂ x⌋ − 23).</summary>
        public static double Ulp(double x) => x > 0 ? Math.Pow(2, Math.Floor(Math.Log(x, 2)) - 23) : 0;

        /// <summary>
        /// Relative precision of a float32 resting position: a particle stops moving once its per-substep step h·v is below
        /// half an ulp of x, and under damping (velocity kept D = e^{−2ζωh} per substep) a residual force f keeps
        /// v = f·h / (2ζωh); so the rest is only defined to a force f ≈ ulp·ζω/h, a displacement f/(κω²) in a mode of
        /// stiffness κω², which relative to that mode's sag a/(κω²) is ulp(X)·ζω/(a·h), whatever κ.
        /// </summary>
        public static double RestingDeadBand(double extent, double zeta, double omega, double acceleration, double h) =>
            Ulp(extent) * zeta * omega / (acceleration * h);

        /// <summary>Standard errors of the fit allowed on top of the coefficient rounding.</summary>
        public const double FitSigmas = 5;

        /// <summary>The residual may exceed the a priori rounding noise by at most this factor (else the data are not a clean oscillation).</summary>
        public const double NoiseFactor = 5;

        /// <summary>The smallest observed order of convergence accepted for ωh ≤ 0.5: 1 − O(ωh), see the convergence suite.</summary>
        public const double MinimumOrder = 0.8;
    }
}
