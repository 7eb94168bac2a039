using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Float64 reference of the quadratic shape-matching goals of one cluster (Müller et al. 2005,
    /// eq. 11–12, with q̃ centred as the solver does), without the length scaling the float32 solver
    /// uses (scaling changes nothing in exact arithmetic): Ã = Ã_pq Ã_qq⁻¹ by Gaussian elimination with partial pivoting, R from the
    /// float64 SVD, the dilation δ R removed from the linear block, gᵢ = c + (β Ã + (1 − β)[R 0 0]) q̃ᵢ.
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
            // Volume: δ R q̃ with δ = Σ wᵢ pᵢ·R qᵢ / Σ wᵢ |qᵢ|² − 1 is removed from the β part, as the solver does.
            double pq = 0, qq = 0;
            for (int i = 0; i < n; i++)
            {
                double px = x[i].x - cx, py = x[i].y - cy, pz = x[i].z - cz;
                double qx = rest[i].x - rx, qy = rest[i].y - ry, qz = rest[i].z - rz;
                for (int r = 0; r < 3; r++)
                {
                    double rq = rot[r, 0] * qx + rot[r, 1] * qy + rot[r, 2] * qz;
                    pq += w[i] * (r == 0 ? px : r == 1 ? py : pz) * rq;
                }
                qq += w[i] * (qx * qx + qy * qy + qz * qz);
            }
            double dilation = pq / qq - 1.0;
            for (int a = 0; a < 3; a++)
            for (int r = 0; r < 3; r++)
                aT[a, r] -= dilation * rot[r, a];
            var result = new double[n, 3];
            for (int i = 0; i < n; i++)
            for (int r = 0; r < 3; r++)
            {
                double g = 0;
                for (int a = 0; a < 9; a++)
                {
                    double rigid = a < 3 ? rot[r, a] : 0.0;
                    g += (beta * aT[a, r] + (1 - beta) * rigid) * qt[i, a];
                }
                result[i, r] = g + (r == 0 ? cx : r == 1 ? cy : cz);
            }
            return result;
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
