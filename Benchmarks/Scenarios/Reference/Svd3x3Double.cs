using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Float64 reference for the rotational part of a 3×3 matrix, used to measure the float32
    /// solvers. Singular values and V come from a cyclic Jacobi eigen-decomposition of AᵀA
    /// (Golub &amp; Van Loan §8.5), U = A V Σ⁻¹ with missing columns completed by cross products, and
    /// R = U · diag(1, 1, det(U Vᵀ)) · Vᵀ (the sign fix of Irving, Teran &amp; Fedkiw 2004).
    /// Not for use at run time: it allocates and is written for clarity, not speed.
    /// </summary>
    public static class Svd3x3Double
    {
        /// <summary>Result of <see cref="Decompose"/>. Matrices are row-major [row, column].</summary>
        public struct Result
        {
            public double[,] U, V, Rotation;
            /// <summary>Singular values, descending.</summary>
            public double Sigma1, Sigma2, Sigma3;
            public double DeterminantSign;

            /// <summary>max over proper rotations R of tr(Rᵀ A) = σ₁ + σ₂ + sign(det A)·σ₃.</summary>
            public double OptimalTrace => Sigma1 + Sigma2 + DeterminantSign * Sigma3;
            public double SigmaSum => Sigma1 + Sigma2 + Sigma3;
        }

        public static double[,] ToDouble(in float3x3 m) => new double[,]
        {
            { m.c0.x, m.c1.x, m.c2.x },
            { m.c0.y, m.c1.y, m.c2.y },
            { m.c0.z, m.c1.z, m.c2.z },
        };

        public static Result Decompose(in float3x3 a) => Decompose(ToDouble(a));

        public static Result Decompose(double[,] a)
        {
            // AᵀA
            var ata = new double[3, 3];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    for (int k = 0; k < 3; k++)
                        ata[i, j] += a[k, i] * a[k, j];

            JacobiEigen(ata, out double[] lambda, out double[,] v);

            // Sort descending.
            int[] order = { 0, 1, 2 };
            Array.Sort(order, (x, y) => lambda[y].CompareTo(lambda[x]));
            var vs = new double[3, 3];
            var sigma = new double[3];
            for (int c = 0; c < 3; c++)
            {
                sigma[c] = Math.Sqrt(Math.Max(lambda[order[c]], 0.0));
                for (int r = 0; r < 3; r++) vs[r, c] = v[r, order[c]];
            }

            double tol = 1e-12 * Math.Max(sigma[0], 1e-300);
            var u = new double[3, 3];
            int known = 0;
            for (int c = 0; c < 3; c++)
            {
                if (sigma[c] <= tol) break;
                for (int r = 0; r < 3; r++)
                    for (int k = 0; k < 3; k++)
                        u[r, c] += a[r, k] * vs[k, c] / sigma[c];
                known++;
            }
            if (known == 0) { u[0, 0] = 1; known = 1; }
            if (known == 1)
            {
                double[] u0 = Column(u, 0);
                double[] any = Math.Abs(u0[0]) < 0.9 ? new double[] { 1, 0, 0 } : new double[] { 0, 1, 0 };
                double[] u1 = Normalize(Cross(u0, any));
                SetColumn(u, 1, u1);
                known = 2;
            }
            if (known == 2)
                SetColumn(u, 2, Cross(Column(u, 0), Column(u, 1)));

            double detA = Determinant(a);
            double d = Math.Sign(Determinant(u) * Determinant(vs));
            var dm = new double[,] { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, d == 0 ? 1 : d } };
            var rot = Mul(Mul(u, dm), Transpose(vs));
            return new Result
            {
                U = u, V = vs, Rotation = rot,
                Sigma1 = sigma[0], Sigma2 = sigma[1], Sigma3 = sigma[2],
                DeterminantSign = detA < 0 ? -1.0 : 1.0,
            };
        }

        /// <summary>tr(Rᵀ A) in float64.</summary>
        public static double Trace(double[,] rd, double[,] a)
        {
            double t = 0;
            for (int i = 0; i < 3; i++)
                for (int k = 0; k < 3; k++)
                    t += rd[k, i] * a[k, i];
            return t;
        }

        /// <summary>det M of a 3×3 matrix, in float64.</summary>
        public static double Determinant(double[,] m) =>
            m[0, 0] * (m[1, 1] * m[2, 2] - m[1, 2] * m[2, 1])
            - m[0, 1] * (m[1, 0] * m[2, 2] - m[1, 2] * m[2, 0])
            + m[0, 2] * (m[1, 0] * m[2, 1] - m[1, 1] * m[2, 0]);

        public static quaternion RotationQuaternion(in Result res)
        {
            double[,] m = res.Rotation;
            var f = new float3x3((float)m[0, 0], (float)m[0, 1], (float)m[0, 2],
                                 (float)m[1, 0], (float)m[1, 1], (float)m[1, 2],
                                 (float)m[2, 0], (float)m[2, 1], (float)m[2, 2]);
            return new quaternion(f);
        }

        static void JacobiEigen(double[,] s, out double[] lambda, out double[,] v)
        {
            var a = (double[,])s.Clone();
            v = new double[,] { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
            for (int sweep = 0; sweep < 50; sweep++)
            {
                double off = a[0, 1] * a[0, 1] + a[0, 2] * a[0, 2] + a[1, 2] * a[1, 2];
                double diag = a[0, 0] * a[0, 0] + a[1, 1] * a[1, 1] + a[2, 2] * a[2, 2];
                if (off <= 1e-32 * diag || off == 0) break;
                for (int p = 0; p < 2; p++)
                    for (int q = p + 1; q < 3; q++)
                    {
                        if (a[p, q] == 0) continue;
                        double theta = (a[q, q] - a[p, p]) / (2 * a[p, q]);
                        double t = Math.Sign(theta) / (Math.Abs(theta) + Math.Sqrt(theta * theta + 1));
                        if (theta == 0) t = 1;
                        double c = 1 / Math.Sqrt(t * t + 1), sn = t * c;
                        for (int k = 0; k < 3; k++)
                        {
                            double akp = a[k, p], akq = a[k, q];
                            a[k, p] = c * akp - sn * akq;
                            a[k, q] = sn * akp + c * akq;
                        }
                        for (int k = 0; k < 3; k++)
                        {
                            double apk = a[p, k], aqk = a[q, k];
                            a[p, k] = c * apk - sn * aqk;
                            a[q, k] = sn * apk + c * aqk;
                        }
                        for (int k = 0; k < 3; k++)
                        {
                            double vkp = v[k, p], vkq = v[k, q];
                            v[k, p] = c * vkp - sn * vkq;
                            v[k, q] = sn * vkp + c * vkq;
                        }
                    }
            }
            lambda = new[] { a[0, 0], a[1, 1], a[2, 2] };
        }

        static double[] Column(double[,] m, int c) => new[] { m[0, c], m[1, c], m[2, c] };
        static void SetColumn(double[,] m, int c, double[] v) { m[0, c] = v[0]; m[1, c] = v[1]; m[2, c] = v[2]; }
        static double[] Cross(double[] a, double[] b) =>
            new[] { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
        static double[] Normalize(double[] a)
        {
            double l = Math.Sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
            return new[] { a[0] / l, a[1] / l, a[2] / l };
        }
        static double[,] Transpose(double[,] m)
        {
            var t = new double[3, 3];
            for (int i = 0; i < 3; i++) for (int j = 0; j < 3; j++) t[i, j] = m[j, i];
            return t;
        }
        static double[,] Mul(double[,] x, double[,] y)
        {
            var r = new double[3, 3];
            for (int i = 0; i < 3; i++) for (int j = 0; j < 3; j++) for (int k = 0; k < 3; k++) r[i, j] += x[i, k] * y[k, j];
            return r;
        }
    }
}
