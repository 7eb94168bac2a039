using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>The hyperelastic law of the float64 finite-element reference.</summary>
    public enum FemMaterialLaw
    {
        /// <summary>Compressible Neo-Hookean: Ψ = μ/2 (I_C − 3) − μ ln J + λ/2 (ln J)².</summary>
        NeoHookean,
        /// <summary>St Venant–Kirchhoff: Ψ = λ/2 (tr E)² + μ E:E, E = (FᵀF − I)/2 (the Turek–Hron CSM law).</summary>
        StVenantKirchhoff,
        /// <summary>
        /// Stable Neo-Hookean, the package's Neo-Hookean law (Smith, de Goes &amp; Kim 2018, eq. 14 without the log term):
        /// Ψ = μ/2 (I_C − 3) + λ'/2 ((J − α)² − (1 − α)²), λ' = λ + μ, α = 1 + μ/λ'. In tension it follows the compressible law
        /// to 0.1 % of the stress up to stretch 1.5; in a 50 % squash its volume is 1.4 % smaller.
        /// </summary>
        StableNeoHookean,
    }

    /// <summary>
    /// Float64 hyperelastic material of the finite-element reference: strain energy density Ψ(F) (J/m³), first
    /// Piola–Kirchhoff stress P = ∂Ψ/∂F (Pa) and its consistent tangent 𝔸 = ∂P/∂F (Pa), given the displacement
    /// gradient H = F − I (3×3, row-major in 9 doubles, H[3i + J] = H_iJ) so that small strains lose no digits to
    /// the cancellation in F − F⁻ᵀ (P is evaluated from H alone: b − I = H + Hᵀ + HHᵀ, J − 1 = tr H + ½((tr H)² −
    /// tr H²) + det H, ln J = log1p(J − 1)). The tangent is stored as A[9(3i + J) + 3k + L] = ∂P_iJ/∂F_kL.
    /// <list type="bullet">
    /// <item>Neo-Hookean: P = μ(F − F⁻ᵀ) + λ ln J F⁻ᵀ = (μ(b − I) + λ ln J I) F⁻ᵀ, b = F Fᵀ;
    /// 𝔸_iJkL = μ δ_ik δ_JL + (μ − λ ln J) F⁻ᵀ_iL F⁻ᵀ_kJ + λ F⁻ᵀ_iJ F⁻ᵀ_kL.</item>
    /// <item>Stable Neo-Hookean: P = μ(F − cof F) + λ'(J − 1) cof F, cof F = J F⁻ᵀ (from H: I − cof F = Hᵀ − tr H I − cof H);
    /// 𝔸_iJkL = μ δ_ik δ_JL + λ' cof_iJ cof_kL + (λ'(J − 1) − μ) ε_ikm ε_JLN F_mN.</item>
    /// <item>St Venant–Kirchhoff: S = λ tr(E) I + 2μE, P = F S;
    /// 𝔸_iJkL = δ_ik S_JL + λ F_iJ F_kL + μ (F Fᵀ)_ik δ_JL + μ F_iL F_kJ.</item>
    /// </list>
    /// All reduce to linear elasticity with Lamé constants (λ, μ) at F = I.
    /// </summary>
    public readonly struct FemMaterial
    {
        /// <summary>The law.</summary>
        public readonly FemMaterialLaw Law;
        /// <summary>Shear modulus μ = E / (2(1 + ν)) (Pa).</summary>
        public readonly double Mu;
        /// <summary>First Lamé constant λ = Eν / ((1 + ν)(1 − 2ν)) (Pa).</summary>
        public readonly double Lambda;

        /// <param name="law">The strain energy.</param>
        /// <param name="youngModulus">E (Pa), &gt; 0.</param>
        /// <param name="poissonRatio">ν, in (−1, 0.5).</param>
        public FemMaterial(FemMaterialLaw law, double youngModulus, double poissonRatio)
        {
            if (!(youngModulus > 0) || !(poissonRatio > -1 && poissonRatio < 0.5))
                throw new ArgumentOutOfRangeException(nameof(poissonRatio), "E must be > 0 and ν in (−1, 0.5).");
            Law = law;
            Mu = youngModulus / (2 * (1 + poissonRatio));
            Lambda = youngModulus * poissonRatio / ((1 + poissonRatio) * (1 - 2 * poissonRatio));
        }

        /// <summary>
        /// Ψ, P and (when <paramref name="tangent"/> is not empty) 𝔸 at F = I + H. Returns false where the energy is undefined
        /// (Neo-Hookean with J ≤ 0); P and 𝔸 are then left unspecified.
        /// </summary>
        /// <param name="h">H = F − I, 9 doubles row-major.</param>
        /// <param name="p">P (Pa), 9 doubles row-major, written.</param>
        /// <param name="tangent">𝔸 (Pa), 81 doubles, written unless empty.</param>
        /// <param name="energy">Ψ (J/m³).</param>
        /// <param name="tangentDimension">3, or 2 to write only the in-plane entries (i, J, k, L &lt; 2) of 𝔸 (plane strain).</param>
        public bool Evaluate(ReadOnlySpan<double> h, Span<double> p, Span<double> tangent, out double energy, int tangentDimension = 3)
        {
            Span<double> f = stackalloc double[9];
            h.CopyTo(f);
            f[0] += 1; f[4] += 1; f[8] += 1;
            switch (Law)
            {
                case FemMaterialLaw.NeoHookean:
                    return NeoHookean(h, f, p, tangent, out energy, tangentDimension);
                case FemMaterialLaw.StableNeoHookean:
                    StableNeoHookean(h, f, p, tangent, out energy, tangentDimension);
                    return true;
                default:
                    return StVenantKirchhoff(h, f, p, tangent, out energy, tangentDimension);
            }
        }

        /// <summary>J − 1 of F = I + H without cancellation: tr H + ½((tr H)² − tr H²) + det H.</summary>
        static double VolumeChange(ReadOnlySpan<double> h)
        {
            double trH = h[0] + h[4] + h[8];
            double trH2 = 0;
            for (int i = 0; i < 3; i++)
            for (int k = 0; k < 3; k++)
                trH2 += h[3 * i + k] * h[3 * k + i];
            double detH = h[0] * (h[4] * h[8] - h[5] * h[7]) - h[1] * (h[3] * h[8] - h[5] * h[6]) + h[2] * (h[3] * h[7] - h[4] * h[6]);
            return trH + 0.5 * (trH * trH - trH2) + detH;
        }

        /// <summary>Cofactor matrix of the 3×3 row-major <paramref name="m"/> into <paramref name="c"/> (cof M = det M · M⁻ᵀ).</summary>
        static void Cofactor(ReadOnlySpan<double> m, Span<double> c)
        {
            c[0] = m[4] * m[8] - m[5] * m[7]; c[1] = m[5] * m[6] - m[3] * m[8]; c[2] = m[3] * m[7] - m[4] * m[6];
            c[3] = m[2] * m[7] - m[1] * m[8]; c[4] = m[0] * m[8] - m[2] * m[6]; c[5] = m[1] * m[6] - m[0] * m[7];
            c[6] = m[1] * m[5] - m[2] * m[4]; c[7] = m[2] * m[3] - m[0] * m[5]; c[8] = m[0] * m[4] - m[1] * m[3];
        }

        /// <summary>ε_ijk (i, j, k in 0..2).</summary>
        static int Permutation(int i, int j, int k) => (i - j) * (j - k) * (k - i) / 2;

        void StableNeoHookean(ReadOnlySpan<double> h, ReadOnlySpan<double> f, Span<double> p, Span<double> a, out double energy, int d)
        {
            double lambda = Lambda + Mu;
            double jm1 = VolumeChange(h);
            double trH = h[0] + h[4] + h[8], hh = 0;
            for (int n = 0; n < 9; n++)
                hh += h[n] * h[n];
            Span<double> cofF = stackalloc double[9];
            Span<double> cofH = stackalloc double[9];
            Cofactor(f, cofF);
            Cofactor(h, cofH);
            // P = μ(H + Hᵀ − tr H I − cof H) + λ'(J − 1) cof F.
            for (int i = 0; i < 3; i++)
            for (int jj = 0; jj < 3; jj++)
                p[3 * i + jj] = Mu * (h[3 * i + jj] + h[3 * jj + i] - (i == jj ? trH : 0) - cofH[3 * i + jj]) + lambda * jm1 * cofF[3 * i + jj];
            // Ψ = μ(tr H + H:H/2) + λ'/2 (J − 1)² − μ(J − 1), zero at rest.
            energy = Mu * (trH + 0.5 * hh) + 0.5 * lambda * jm1 * jm1 - Mu * jm1;
            if (a.IsEmpty)
                return;
            double c = lambda * jm1 - Mu;
            for (int i = 0; i < d; i++)
            for (int jj = 0; jj < d; jj++)
            for (int k = 0; k < d; k++)
            for (int l = 0; l < d; l++)
            {
                double v = lambda * cofF[3 * i + jj] * cofF[3 * k + l];
                if (i == k && jj == l)
                    v += Mu;
                // ∂(cof F)_iJ/∂F_kL = ε_ikm ε_JLN F_mN.
                double dCof = 0;
                for (int m = 0; m < 3; m++)
                for (int nn = 0; nn < 3; nn++)
                    dCof += Permutation(i, k, m) * Permutation(jj, l, nn) * f[3 * m + nn];
                a[9 * (3 * i + jj) + 3 * k + l] = v + c * dCof;
            }
        }

        bool NeoHookean(ReadOnlySpan<double> h, ReadOnlySpan<double> f, Span<double> p, Span<double> a, out double energy, int d)
        {
            double trH = h[0] + h[4] + h[8];
            double trH2 = 0, hh = 0;
            for (int i = 0; i < 3; i++)
            for (int k = 0; k < 3; k++)
            {
                trH2 += h[3 * i + k] * h[3 * k + i];
                hh += h[3 * i + k] * h[3 * i + k];
            }
            double detH = h[0] * (h[4] * h[8] - h[5] * h[7]) - h[1] * (h[3] * h[8] - h[5] * h[6]) + h[2] * (h[3] * h[7] - h[4] * h[6]);
            double jm1 = trH + 0.5 * (trH * trH - trH2) + detH;
            double j = 1 + jm1;
            energy = double.NaN;
            if (!(j > 0))
                return false;
            // F⁻ᵀ = cof(F) / J.
            Span<double> g = stackalloc double[9];
            double ij = 1 / j;
            g[0] = (f[4] * f[8] - f[5] * f[7]) * ij; g[1] = (f[5] * f[6] - f[3] * f[8]) * ij; g[2] = (f[3] * f[7] - f[4] * f[6]) * ij;
            g[3] = (f[2] * f[7] - f[1] * f[8]) * ij; g[4] = (f[0] * f[8] - f[2] * f[6]) * ij; g[5] = (f[1] * f[6] - f[0] * f[7]) * ij;
            g[6] = (f[1] * f[5] - f[2] * f[4]) * ij; g[7] = (f[2] * f[3] - f[0] * f[5]) * ij; g[8] = (f[0] * f[4] - f[1] * f[3]) * ij;
            double lnJ = Log1P(jm1);
            // τ = μ(b − I) + λ ln J I with b − I = H + Hᵀ + H Hᵀ; P = τ F⁻ᵀ.
            Span<double> tau = stackalloc double[9];
            for (int i = 0; i < 3; i++)
            for (int k = 0; k < 3; k++)
            {
                double hht = h[3 * i] * h[3 * k] + h[3 * i + 1] * h[3 * k + 1] + h[3 * i + 2] * h[3 * k + 2];
                tau[3 * i + k] = Mu * (h[3 * i + k] + h[3 * k + i] + hht) + (i == k ? Lambda * lnJ : 0);
            }
            for (int i = 0; i < 3; i++)
            for (int jj = 0; jj < 3; jj++)
                p[3 * i + jj] = tau[3 * i] * g[jj] + tau[3 * i + 1] * g[3 + jj] + tau[3 * i + 2] * g[6 + jj];
            // I_C − 3 = 2 tr H + H:H.
            energy = 0.5 * Mu * (2 * trH + hh) - Mu * lnJ + 0.5 * Lambda * lnJ * lnJ;
            if (a.IsEmpty)
                return true;
            double c = Mu - Lambda * lnJ;
            for (int i = 0; i < d; i++)
            for (int jj = 0; jj < d; jj++)
            for (int k = 0; k < d; k++)
            for (int l = 0; l < d; l++)
            {
                double v = c * g[3 * i + l] * g[3 * k + jj] + Lambda * g[3 * i + jj] * g[3 * k + l];
                if (i == k && jj == l)
                    v += Mu;
                a[9 * (3 * i + jj) + 3 * k + l] = v;
            }
            return true;
        }

        bool StVenantKirchhoff(ReadOnlySpan<double> h, ReadOnlySpan<double> f, Span<double> p, Span<double> a, out double energy, int d)
        {
            Span<double> e = stackalloc double[9];
            Span<double> s = stackalloc double[9];
            // E = ½(H + Hᵀ + HᵀH).
            for (int i = 0; i < 3; i++)
            for (int jj = 0; jj < 3; jj++)
            {
                double c = 0;
                for (int k = 0; k < 3; k++)
                    c += h[3 * k + i] * h[3 * k + jj];
                e[3 * i + jj] = 0.5 * (h[3 * i + jj] + h[3 * jj + i] + c);
            }
            double tr = e[0] + e[4] + e[8];
            double ee = 0;
            for (int n = 0; n < 9; n++)
            {
                ee += e[n] * e[n];
                s[n] = 2 * Mu * e[n];
            }
            s[0] += Lambda * tr; s[4] += Lambda * tr; s[8] += Lambda * tr;
            energy = 0.5 * Lambda * tr * tr + Mu * ee;
            for (int i = 0; i < 3; i++)
            for (int jj = 0; jj < 3; jj++)
                p[3 * i + jj] = f[3 * i] * s[jj] + f[3 * i + 1] * s[3 + jj] + f[3 * i + 2] * s[6 + jj];
            if (a.IsEmpty)
                return true;
            Span<double> b = stackalloc double[9];
            for (int i = 0; i < 3; i++)
            for (int k = 0; k < 3; k++)
                b[3 * i + k] = f[3 * i] * f[3 * k] + f[3 * i + 1] * f[3 * k + 1] + f[3 * i + 2] * f[3 * k + 2];
            for (int i = 0; i < d; i++)
            for (int jj = 0; jj < d; jj++)
            for (int k = 0; k < d; k++)
            for (int l = 0; l < d; l++)
            {
                double v = Lambda * f[3 * i + jj] * f[3 * k + l] + Mu * f[3 * i + l] * f[3 * k + jj];
                if (i == k)
                    v += s[3 * jj + l];
                if (jj == l)
                    v += Mu * b[3 * i + k];
                a[9 * (3 * i + jj) + 3 * k + l] = v;
            }
            return true;
        }

        /// <summary>ln(1 + x) accurate for small x (netstandard2.1 has no Math.Log1P): the correction
        /// ln(u)·x/(u − 1) with u = 1 + x rounded (Goldberg 1991, "What every computer scientist should know about
        /// floating-point arithmetic", Theorem 4).</summary>
        static double Log1P(double x)
        {
            double u = 1 + x;
            return u == 1 ? x : Math.Log(u) * x / (u - 1);
        }
    }
}
