using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Float64 reference of the quadratic shape-matching goals of one cluster (Müller et al. 2005,
    /// eq. 11–12, with q̃ centred as the solver does), without the length scaling the float32 solver
    /// uses (scaling changes nothing in exact arithmetic): Ã = Ã_pq Ã_qq⁻¹ by Gaussian elimination with partial pivoting, R from the
    /// float64 SVD, gᵢ = c + (β' Ã + (1 − β')[R 0 0]) q̃ᵢ − κ (J − 1) cof(A) (M L² A_qq⁻¹) qᵢ with β' = β·fade, κ = β'/9
    /// and J = det A of the plain linear fit (the volume energy of the solver's quadratic mode). No strain limit.
    /// </summary>
    public static class QuadraticGoalsDouble
    {
        /// <returns>Goals, n × 3.</returns>
        public static double[,] Goals(float3[] rest, float3[] x, float[] w, float beta)
        {
            int n = rest.Length;
            double m = 0, cx = 0, cy = 0, cz = 0, rx = 0, ry = 0, rz = 0;
            for (int i = 0; i < n; i++)
            {
                m += w[i];
                cx += w[i] * (double)x[i].x; cy += w[i] * (double)x[i].y; cz += w[i] * (double)x[i].z;
                rx += w[i] * (double)rest[i].x; ry += w[i] * (double)rest[i].y; rz += w[i] * (double)rest[i].z;
            }
            cx /= m; cy /= m; cz /= m; rx /= m; ry /= m; rz /= m;
            var apq = new double[3, 9];
            var aqq = new double[9, 9];
            var qt = new double[n, 9];
            var apqLinear = new double[3, 3];
            var mean = new double[9];
            for (int i = 0; i < n; i++)
            {
                double qx = rest[i].x - rx, qy = rest[i].y - ry, qz = rest[i].z - rz;
                double[] q = { qx, qy, qz, qx * qx, qy * qy, qz * qz, qx * qy, qy * qz, qz * qx };
                for (int a = 0; a < 9; a++)
                    mean[a] += w[i] * q[a] / m;
            }
            for (int i = 0; i < n; i++)
            {
                double qx = rest[i].x - rx, qy = rest[i].y - ry, qz = rest[i].z - rz;
                double[] q = { qx, qy, qz, qx * qx, qy * qy, qz * qz, qx * qy, qy * qz, qz * qx };
                for (int a = 0; a < 9; a++)
                    q[a] -= mean[a];
                double[] p = { x[i].x - cx, x[i].y - cy, x[i].z - cz };
                for (int a = 0; a < 9; a++)
                {
                    qt[i, a] = q[a];
                    for (int r = 0; r < 3; r++)
                        apq[r, a] += w[i] * p[r] * q[a];
                    for (int b = 0; b < 9; b++)
                        aqq[a, b] += w[i] * q[a] * q[b];
                }
            }
            for (int r = 0; r < 3; r++)
            for (int a = 0; a < 3; a++)
                apqLinear[r, a] = apq[r, a];
            double[,] rot = Svd3x3Double.Decompose(apqLinear).Rotation;
            // Ã = Ã_pq Ã_qq⁻¹  ⇔  Ã_qq Ãᵀ = Ã_pqᵀ (Ã_qq symmetric).
            var rhs = new double[9, 3];
            for (int a = 0; a < 9; a++)
            for (int r = 0; r < 3; r++)
                rhs[a, r] = apq[r, a];
            double[,] aT = Solve(aqq, rhs);
            // β fade on the relative determinant of the linear block, as the solver does.
            var t0 = new double[3, 3];
            double maxAbs = 0;
            for (int r = 0; r < 3; r++)
            for (int a = 0; a < 3; a++)
            {
                t0[r, a] = aT[a, r];
                maxAbs = Math.Max(maxAbs, Math.Abs(t0[r, a]));
            }
            double relativeDeterminant = maxAbs > 0 ? Det(t0) / (maxAbs * maxAbs * maxAbs) : 0;
            double floor = VolumePreservation.DefaultRelativeDeterminantFloor;
            double fade = Math.Min(1, Math.Max(0, (relativeDeterminant - floor) / (VolumePreservation.FadeEnd - floor)));
            double betaFaded = beta * fade;
            // Volume energy ½ω²κML²(J − 1)², J = det A of the plain linear fit A = A_pq A_qq⁻¹, κ = β·fade/9: the goal
            // of particle i moves by −κ (J − 1) cof(A) (M L² A_qq⁻¹) qᵢ, as the solver does.
            var apqL = new double[3, 3];
            var aqqL = new double[3, 3];
            double ml2 = 0;
            for (int i = 0; i < n; i++)
            {
                double[] q = { rest[i].x - rx, rest[i].y - ry, rest[i].z - rz };
                double[] p = { x[i].x - cx, x[i].y - cy, x[i].z - cz };
                for (int r = 0; r < 3; r++)
                for (int a = 0; a < 3; a++)
                {
                    apqL[r, a] += w[i] * p[r] * q[a];
                    aqqL[r, a] += w[i] * q[r] * q[a];
                }
                ml2 += w[i] * (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
            }
            double[,] aqqInv = Inverse(aqqL);
            double[,] aLin = Mul(apqL, aqqInv);
            double j = Det(aLin);
            double[,] volume = new double[3, 3];
            if (relativeDeterminant > floor)
            {
                double[,] aInv = Inverse(aLin);
                var cof = new double[3, 3];
                for (int r = 0; r < 3; r++)
                for (int a = 0; a < 3; a++)
                    cof[r, a] = j * aInv[a, r];
                double[,] k = Mul(cof, aqqInv);
                double scale = -(betaFaded / 9.0) * (j - 1.0) * ml2;
                for (int r = 0; r < 3; r++)
                for (int a = 0; a < 3; a++)
                    volume[r, a] = scale * k[r, a];
            }
            var result = new double[n, 3];
            for (int i = 0; i < n; i++)
            for (int r = 0; r < 3; r++)
            {
                double g = 0;
                for (int a = 0; a < 9; a++)
                {
                    double rigid = a < 3 ? rot[r, a] : 0.0;
                    g += (betaFaded * aT[a, r] + (1 - betaFaded) * rigid) * qt[i, a];
                }
                double[] q = { rest[i].x - rx, rest[i].y - ry, rest[i].z - rz };
                for (int a = 0; a < 3; a++)
                    g += volume[r, a] * q[a];
                result[i, r] = g + (r == 0 ? cx : r == 1 ? cy : cz);
            }
            return result;
        }

        static double Det(double[,] m) =>
            m[0, 0] * (m[1, 1] * m[2, 2] - m[1, 2] * m[2, 1])
            - m[0, 1] * (m[1, 0] * m[2, 2] - m[1, 2] * m[2, 0])
            + m[0, 2] * (m[1, 0] * m[2, 1] - m[1, 1] * m[2, 0]);

        static double[,] Mul(double[,] a, double[,] b)
        {
            var c = new double[3, 3];
            for (int r = 0; r < 3; r++)
            for (int col = 0; col < 3; col++)
            for (int k = 0; k < 3; k++)
                c[r, col] += a[r, k] * b[k, col];
            return c;
        }

        static double[,] Inverse(double[,] m)
        {
            double d = Det(m);
            var inv = new double[3, 3];
            inv[0, 0] = (m[1, 1] * m[2, 2] - m[1, 2] * m[2, 1]) / d;
            inv[0, 1] = (m[0, 2] * m[2, 1] - m[0, 1] * m[2, 2]) / d;
            inv[0, 2] = (m[0, 1] * m[1, 2] - m[0, 2] * m[1, 1]) / d;
            inv[1, 0] = (m[1, 2] * m[2, 0] - m[1, 0] * m[2, 2]) / d;
            inv[1, 1] = (m[0, 0] * m[2, 2] - m[0, 2] * m[2, 0]) / d;
            inv[1, 2] = (m[0, 2] * m[1, 0] - m[0, 0] * m[1, 2]) / d;
            inv[2, 0] = (m[1, 0] * m[2, 1] - m[1, 1] * m[2, 0]) / d;
            inv[2, 1] = (m[0, 1] * m[2, 0] - m[0, 0] * m[2, 1]) / d;
            inv[2, 2] = (m[0, 0] * m[1, 1] - m[0, 1] * m[1, 0]) / d;
            return inv;
        }

        static double[,] Solve(double[,] a, double[,] b)
        {
            int n = a.GetLength(0), k = b.GetLength(1);
            var m = (double[,])a.Clone();
            var x = (double[,])b.Clone();
            for (int col = 0; col < n; col++)
            {
                int pivot = col;
                for (int r = col + 1; r < n; r++)
                    if (Math.Abs(m[r, col]) > Math.Abs(m[pivot, col])) pivot = r;
                for (int c = 0; c < n; c++) (m[col, c], m[pivot, c]) = (m[pivot, c], m[col, c]);
                for (int c = 0; c < k; c++) (x[col, c], x[pivot, c]) = (x[pivot, c], x[col, c]);
                for (int r = 0; r < n; r++)
                {
                    if (r == col) continue;
                    double f = m[r, col] / m[col, col];
                    for (int c = col; c < n; c++) m[r, c] -= f * m[col, c];
                    for (int c = 0; c < k; c++) x[r, c] -= f * x[col, c];
                }
            }
            for (int r = 0; r < n; r++)
            for (int c = 0; c < k; c++)
                x[r, c] /= m[r, r];
            return x;
        }
    }

}
