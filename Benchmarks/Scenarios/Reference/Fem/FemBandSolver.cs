using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Direct solver for a symmetric sparse matrix: A = L D Lᵀ on the band |r − c| ≤ b (Golub &amp; Van Loan,
    /// Matrix Computations, §4.3, band LDLᵀ), unit lower L stored by rows, no pivoting. Symmetric indefinite matrices
    /// factor as long as no pivot vanishes; <see cref="NegativePivots"/> is the number of negative eigenvalues
    /// (Sylvester's law of inertia), zero for a positive definite matrix. Cost n·b² to factor, 4n·b to solve; exact
    /// up to round-off (no iteration tolerance). Only the lower triangle of the CSR matrix is read.
    /// </summary>
    public sealed class FemBandSolver
    {
        readonly int m_Size, m_Band;
        readonly double[] m_L, m_D, m_Work;

        /// <summary>Pivots below zero in the last factorisation.</summary>
        public int NegativePivots { get; private set; }

        /// <param name="size">Matrix size.</param>
        /// <param name="bandwidth">max |r − c| of the entries (see <see cref="FemCsrMatrix.Bandwidth"/>).</param>
        public FemBandSolver(int size, int bandwidth)
        {
            m_Size = size;
            m_Band = bandwidth;
            m_L = new double[(long)size * (bandwidth + 1) > int.MaxValue ? throw new ArgumentOutOfRangeException(nameof(bandwidth)) : size * (bandwidth + 1)];
            m_D = new double[size];
            m_Work = new double[bandwidth + 1];
        }

        /// <summary>Factors A; returns false if a pivot is zero or not finite.</summary>
        public bool Factor(FemCsrMatrix a)
        {
            int n = m_Size, b = m_Band, w = b + 1;
            Array.Clear(m_L, 0, m_L.Length);
            // Row i, column j (i − b ≤ j ≤ i) lives at m_L[i·w + j − i + b].
            for (int r = 0; r < n; r++)
            for (int k = a.RowStart[r]; k < a.RowStart[r + 1]; k++)
            {
                int c = a.Columns[k];
                if (c <= r)
                    m_L[r * w + c - r + b] += a.Values[k];
            }
            NegativePivots = 0;
            double[] l = m_L, d = m_D, t = m_Work;
            for (int i = 0; i < n; i++)
            {
                int j0 = Math.Max(0, i - b);
                int rowI = i * w - i + b;
                // t[j] = L_ij D_j for the columns done so far; L_ij = (A_ij − Σ_{k<j} L_ik D_k L_jk) / D_j.
                for (int j = j0; j < i; j++)
                {
                    int rowJ = j * w - j + b;
                    int k0 = Math.Max(j0, j - b);
                    double s = l[rowI + j];
                    for (int k = k0; k < j; k++)
                        s -= t[k - j0] * l[rowJ + k];
                    t[j - j0] = s;
                    l[rowI + j] = s / d[j];
                }
                double dd = l[rowI + i];
                for (int j = j0; j < i; j++)
                    dd -= t[j - j0] * l[rowI + j];
                if (!(Math.Abs(dd) > 0) || double.IsInfinity(dd))
                    return false;
                if (dd < 0)
                    NegativePivots++;
                d[i] = dd;
                l[rowI + i] = 1;
            }
            return true;
        }

        /// <summary>Solves A x = rhs with the last factorisation (x may alias rhs).</summary>
        public void Solve(ReadOnlySpan<double> rhs, Span<double> x)
        {
            int n = m_Size, b = m_Band, w = b + 1;
            double[] l = m_L, d = m_D;
            if (!rhs.Overlaps(x))
                rhs.CopyTo(x);
            for (int i = 0; i < n; i++)
            {
                int rowI = i * w - i + b;
                double s = x[i];
                for (int j = Math.Max(0, i - b); j < i; j++)
                    s -= l[rowI + j] * x[j];
                x[i] = s;
            }
            for (int i = 0; i < n; i++)
                x[i] /= d[i];
            for (int i = n - 1; i >= 0; i--)
            {
                int rowI = i * w - i + b;
                double xi = x[i];
                for (int j = Math.Max(0, i - b); j < i; j++)
                    x[j] -= l[rowI + j] * xi;
            }
        }
    }
}
