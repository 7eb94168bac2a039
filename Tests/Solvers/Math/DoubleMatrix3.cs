namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>3 × 3 matrices in float64, as double[row, column], for the tests' reference computations.</summary>
    static class DoubleMatrix3
    {
        /// <summary>a b.</summary>
        public static double[,] Mul(double[,] a, double[,] b)
        {
            var c = new double[3, 3];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    for (int k = 0; k < 3; k++)
                        c[i, j] += a[i, k] * b[k, j];
            return c;
        }

        /// <summary>det m, by cofactors of the first row.</summary>
        public static double Det(double[,] m) =>
            m[0, 0] * (m[1, 1] * m[2, 2] - m[1, 2] * m[2, 1]) - m[0, 1] * (m[1, 0] * m[2, 2] - m[1, 2] * m[2, 0])
            + m[0, 2] * (m[1, 0] * m[2, 1] - m[1, 1] * m[2, 0]);

        /// <summary>cof(m)[i, j] = (−1)^(i+j) minor: the derivative of det m with respect to m[i, j].</summary>
        public static double[,] Cofactor(double[,] m)
        {
            var c = new double[3, 3];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                {
                    int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
                    c[i, j] = m[i1, j1] * m[i2, j2] - m[i1, j2] * m[i2, j1];
                }
            return c;
        }

        /// <summary>m⁻¹ = cof(m)ᵀ / det m.</summary>
        public static double[,] Inverse(double[,] m)
        {
            double[,] c = Cofactor(m);
            double d = Det(m);
            var inv = new double[3, 3];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    inv[i, j] = c[j, i] / d;
            return inv;
        }

        /// <summary>m⁻ᵀ = cof(m) / det m.</summary>
        public static double[,] InverseTranspose(double[,] m)
        {
            double[,] c = Cofactor(m);
            double d = Det(m);
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    c[i, j] /= d;
            return c;
        }
    }
}
