using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Homogeneous uniaxial stretch of the compressible Neo-Hookean solid.</summary>
    public struct UniaxialResult
    {
        /// <summary>Nominal (first Piola–Kirchhoff) stress P₁₁ (Pa): force per reference area.</summary>
        public double NominalStress;
        /// <summary>Lateral stretch s (free lateral faces).</summary>
        public double LateralStretch;
        /// <summary>J = λ s².</summary>
        public double VolumeRatio;
        /// <summary>Strain energy density Ψ (J/m³).</summary>
        public double Energy;
    }

    /// <summary>
    /// Exact force–extension curve of the compressible Neo-Hookean law of <see cref="FemMaterial"/>
    /// (Ψ = μ/2 (I_C − 3) − μ ln J + λ/2 (ln J)²) under homogeneous uniaxial stretch λ₁ with traction-free lateral
    /// faces: F = diag(λ₁, s, s), J = λ₁ s², P = μ(F − F⁻ᵀ) + λ ln J F⁻ᵀ.
    /// <code>
    ///   P₂₂ = 0  ⇔  μ(s² − 1) + λ ln(λ₁ s²) = 0      (solved for s by Newton, monotone in s)
    ///   P₁₁ = μ(λ₁ − 1/λ₁) + λ ln J / λ₁
    /// </code>
    /// Since ∂Ψ/∂s = 0 at the lateral solution, P₁₁ = dΨ/dλ₁ along the curve. Small stretch: P₁₁ ≈ E(λ₁ − 1).
    /// For the force–extension scene of the comparison study; exact to round-off (s to 1e-15 relative).
    /// The stable law (<see cref="FemMaterialLaw.StableNeoHookean"/>, P = μF + λ'(J − α) cof F) has a closed form:
    /// <code>
    ///   P₂₂ = 0  ⇔  μ + λ'(J − α) λ₁ = 0  ⇔  J = 1 + μ/λ' (1 − 1/λ₁),   P₁₁ = μ(λ₁ − J/λ₁²)
    /// </code>
    /// </summary>
    public static class UniaxialNeoHookean
    {
        /// <summary>The state at stretch λ₁ (&gt; 0) for Young's modulus E (Pa) and Poisson ratio ν.</summary>
        /// <param name="law">A Neo-Hookean law: <see cref="FemMaterialLaw.NeoHookean"/> or <see cref="FemMaterialLaw.StableNeoHookean"/>.</param>
        public static UniaxialResult Stress(double stretch, double youngModulus, double poissonRatio,
            FemMaterialLaw law = FemMaterialLaw.NeoHookean)
        {
            if (!(stretch > 0))
                throw new ArgumentOutOfRangeException(nameof(stretch));
            var m = new FemMaterial(law, youngModulus, poissonRatio);
            double mu = m.Mu, la = m.Lambda;
            if (law == FemMaterialLaw.StableNeoHookean)
                return Stable(stretch, mu, la + mu);
            if (law != FemMaterialLaw.NeoHookean)
                throw new ArgumentOutOfRangeException(nameof(law));
            // g(s) = μ(s² − 1) + λ(ln λ₁ + 2 ln s), g' = 2μ s + 2λ/s > 0; start at the linear guess, stay positive.
            double s = Math.Max(1e-3, 1 - poissonRatio * (stretch - 1));
            for (int it = 0; it < 100; it++)
            {
                double g = mu * (s * s - 1) + la * (Math.Log(stretch) + 2 * Math.Log(s));
                double dg = 2 * mu * s + 2 * la / s;
                double next = s - g / dg;
                if (next <= 0)
                    next = 0.5 * s;
                bool done = Math.Abs(next - s) <= 1e-15 * s;
                s = next;
                if (done)
                    break;
            }
            double j = stretch * s * s, lnJ = Math.Log(j);
            return new UniaxialResult
            {
                NominalStress = mu * (stretch - 1 / stretch) + la * lnJ / stretch,
                LateralStretch = s,
                VolumeRatio = j,
                Energy = 0.5 * mu * (stretch * stretch + 2 * s * s - 3) - mu * lnJ + 0.5 * la * lnJ * lnJ,
            };
        }

        /// <summary>The stable law's closed form (class comment); Ψ as in <see cref="FemMaterialLaw.StableNeoHookean"/>, zero at rest.</summary>
        static UniaxialResult Stable(double stretch, double mu, double lambda)
        {
            double jm1 = mu / lambda * (1 - 1 / stretch), j = 1 + jm1;
            return new UniaxialResult
            {
                NominalStress = mu * (stretch - j / (stretch * stretch)),
                LateralStretch = Math.Sqrt(j / stretch),
                VolumeRatio = j,
                Energy = 0.5 * mu * (stretch * stretch + 2 * j / stretch - 3) + 0.5 * lambda * jm1 * jm1 - mu * jm1,
            };
        }
    }
}
