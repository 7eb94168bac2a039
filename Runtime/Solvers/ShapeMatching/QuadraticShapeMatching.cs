using System;
using System.Runtime.CompilerServices;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Quadratic deformation mode of Müller et al. 2005, §4.4. Each rest offset q is lifted to
    /// q̃ = (qx, qy, qz, qx², qy², qz², qx·qy, qy·qz, qz·qx) ∈ ℝ⁹ minus its weighted mean (the paper's
    /// q̃ is not centred: its squares have a positive mean, so the fit of the centred pᵢ cannot
    /// reproduce even an exact quadratic deformation and the goals' centre drifts from x_cm; centred,
    /// Σ wᵢ Ã q̃ᵢ = 0 and a quadratic deformation is matched exactly), the best 3×9 transform is
    /// Ã = Ã_pq Ã_qq⁻¹ with Ã_pq = Σ wᵢ pᵢ q̃ᵢᵀ and Ã_qq = Σ wᵢ q̃ᵢ q̃ᵢᵀ (eq. 11), and the goals are
    /// gᵢ = x_cm + (β Ã + (1 − β) [R 0 0]) q̃ᵢ (eq. 12).
    /// <para>Conditioning: q and p are divided by the cluster's RMS radius L before lifting, so the
    /// quadratic entries are O(1) like the linear ones and cond(Ã_qq) does not depend on the size of
    /// the body (stability-plan §2.1: ~1e5 at 1 cm unscaled, ~11 at every size scaled). The 9×9 inverse
    /// is computed once, in double precision, by a Jacobi eigen-decomposition that also yields the
    /// condition number; a planar or ill-conditioned cluster (cond &gt; <see cref="MaxCondition"/>)
    /// is marked invalid and the solver falls back to the linear mode.</para>
    /// The 9×9 inverse is stored as nine 3×3 blocks M_jk (j, k ∈ {linear, square, cross}).
    /// </summary>
    public static class QuadraticShapeMatching
    {
        /// <summary>3×3 blocks of the 9×9 Ã_qq⁻¹ stored per cluster.</summary>
        public const int BlocksPerCluster = 9;

        /// <summary>Largest accepted condition number of the scaled Ã_qq (float32 keeps ~7 digits).</summary>
        public const double MaxCondition = 1e6;

        const int k_JacobiSweeps = 60;

        /// <summary>The three parts of the centred q̃: (q, q∘q − mean, q∘q.yzx − mean), q already divided by L.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Lift(float3 q, in ClusterRestData rest, out float3 linear, out float3 square, out float3 cross)
        {
            linear = q;
            square = q * q - rest.QuadraticMeanSquare;
            cross = q * q.yzx - rest.QuadraticMeanCross;
        }

        /// <summary>
        /// Computes the scaled, centred Ã_qq⁻¹ of a cluster whose rest offsets are Sₚ (x⁰ᵢ − centre) / L, into
        /// <paramref name="inverseBlocks"/> (9 blocks), and the means of the quadratic parts. Returns false
        /// (and writes zeros) when Ã_qq is singular or its condition exceeds <see cref="MaxCondition"/>.
        /// </summary>
        /// <param name="restPositions">All rest positions of the body (m).</param>
        /// <param name="indices">Members of the cluster (indices into <paramref name="restPositions"/>).</param>
        /// <param name="weights">Weight wᵢ of each member (kg).</param>
        /// <param name="restCenter">Weighted rest centre of the cluster (m).</param>
        /// <param name="plasticDeformation">Sₚ; identity without plastic flow.</param>
        /// <param name="lengthScale">L (m), &gt; 0.</param>
        /// <param name="condition">λmax/λmin of the scaled Ã_qq (infinity when singular).</param>
        public static bool ComputeRestInverse(ReadOnlySpan<float3> restPositions, ReadOnlySpan<int> indices,
            ReadOnlySpan<float> weights, float3 restCenter, in float3x3 plasticDeformation, float lengthScale,
            Span<float3x3> inverseBlocks, out double condition, out float3 meanSquare, out float3 meanCross)
        {
            Span<double> a = stackalloc double[81];
            Span<double> v = stackalloc double[81];
            Span<double> qt = stackalloc double[9];
            a.Clear();
            condition = double.PositiveInfinity;
            meanSquare = float3.zero;
            meanCross = float3.zero;
            for (int k = 0; k < BlocksPerCluster; k++)
                inverseBlocks[k] = float3x3.zero;
            if (!(lengthScale > 0f) || !math.isfinite(lengthScale))
                return false;
            double invL = 1.0 / lengthScale;
            Span<double> mean = stackalloc double[9];
            mean.Clear();
            double totalWeight = 0.0;
            for (int m = 0; m < indices.Length; m++)
            {
                LiftDouble(math.mul(plasticDeformation, restPositions[indices[m]] - restCenter), invL, qt);
                for (int r = 3; r < 9; r++)
                    mean[r] += weights[m] * qt[r];
                totalWeight += weights[m];
            }
            if (!(totalWeight > 0.0))
                return false;
            for (int r = 3; r < 9; r++)
                mean[r] /= totalWeight;
            meanSquare = new float3((float)mean[3], (float)mean[4], (float)mean[5]);
            meanCross = new float3((float)mean[6], (float)mean[7], (float)mean[8]);
            for (int m = 0; m < indices.Length; m++)
            {
                LiftDouble(math.mul(plasticDeformation, restPositions[indices[m]] - restCenter), invL, qt);
                // Centre with the float32 means the solver subtracts, so both see the same basis.
                qt[3] -= meanSquare.x; qt[4] -= meanSquare.y; qt[5] -= meanSquare.z;
                qt[6] -= meanCross.x; qt[7] -= meanCross.y; qt[8] -= meanCross.z;
                double w = weights[m];
                for (int r = 0; r < 9; r++)
                for (int c = r; c < 9; c++)
                    a[r * 9 + c] += w * qt[r] * qt[c];
            }
            for (int r = 0; r < 9; r++)
            for (int c = 0; c < r; c++)
                a[r * 9 + c] = a[c * 9 + r];
            if (!JacobiEigen(a, v))
                return false;
            double lmax = 0.0, lmin = double.PositiveInfinity;
            for (int i = 0; i < 9; i++)
            {
                lmax = Math.Max(lmax, a[i * 9 + i]);
                lmin = Math.Min(lmin, a[i * 9 + i]);
            }
            if (!(lmax > 0.0) || !(lmin > 0.0))
                return false;
            condition = lmax / lmin;
            if (!(condition <= MaxCondition))
                return false;
            // Ã_qq⁻¹ = V Λ⁻¹ Vᵀ, stored block by block (column-major float3x3: c0 is column 3k).
            for (int bj = 0; bj < 3; bj++)
            for (int bk = 0; bk < 3; bk++)
            {
                float3x3 block = float3x3.zero;
                for (int col = 0; col < 3; col++)
                {
                    float3 column = float3.zero;
                    for (int row = 0; row < 3; row++)
                    {
                        int r = 3 * bj + row, c = 3 * bk + col;
                        double s = 0.0;
                        for (int e = 0; e < 9; e++)
                            s += v[r * 9 + e] * v[c * 9 + e] / a[e * 9 + e];
                        column[row] = (float)s;
                    }
                    block[col] = column;
                }
                inverseBlocks[3 * bj + bk] = block;
            }
            return true;
        }

        static void LiftDouble(float3 q, double invL, Span<double> qt)
        {
            double x = q.x * invL, y = q.y * invL, z = q.z * invL;
            qt[0] = x; qt[1] = y; qt[2] = z;
            qt[3] = x * x; qt[4] = y * y; qt[5] = z * z;
            qt[6] = x * y; qt[7] = y * z; qt[8] = z * x;
        }

        /// <summary>
        /// Cyclic Jacobi eigen-decomposition of a symmetric 9×9 matrix in place: on return the diagonal
        /// of <paramref name="a"/> holds the eigenvalues and the columns of <paramref name="v"/> the eigenvectors.
        /// </summary>
        static bool JacobiEigen(Span<double> a, Span<double> v)
        {
            v.Clear();
            for (int i = 0; i < 9; i++)
                v[i * 9 + i] = 1.0;
            for (int sweep = 0; sweep < k_JacobiSweeps; sweep++)
            {
                double off = 0.0, diag = 0.0;
                for (int r = 0; r < 9; r++)
                {
                    diag += a[r * 9 + r] * a[r * 9 + r];
                    for (int c = r + 1; c < 9; c++)
                        off += a[r * 9 + c] * a[r * 9 + c];
                }
                if (!(off > 1e-30 * diag))
                    return !double.IsNaN(off) && !double.IsNaN(diag);
                for (int p = 0; p < 8; p++)
                for (int q = p + 1; q < 9; q++)
                {
                    double apq = a[p * 9 + q];
                    if (apq == 0.0)
                        continue;
                    double theta = (a[q * 9 + q] - a[p * 9 + p]) / (2.0 * apq);
                    double t = Math.Sign(theta) / (Math.Abs(theta) + Math.Sqrt(theta * theta + 1.0));
                    if (theta == 0.0)
                        t = 1.0;
                    double c = 1.0 / Math.Sqrt(t * t + 1.0), s = t * c;
                    for (int k = 0; k < 9; k++)
                    {
                        double akp = a[k * 9 + p], akq = a[k * 9 + q];
                        a[k * 9 + p] = c * akp - s * akq;
                        a[k * 9 + q] = s * akp + c * akq;
                    }
                    for (int k = 0; k < 9; k++)
                    {
                        double apk = a[p * 9 + k], aqk = a[q * 9 + k];
                        a[p * 9 + k] = c * apk - s * aqk;
                        a[q * 9 + k] = s * apk + c * aqk;
                    }
                    for (int k = 0; k < 9; k++)
                    {
                        double vkp = v[k * 9 + p], vkq = v[k * 9 + q];
                        v[k * 9 + p] = c * vkp - s * vkq;
                        v[k * 9 + q] = s * vkp + c * vkq;
                    }
                }
            }
            return true;
        }

        /// <summary>
        /// The three 3×3 blocks of Ã = Ã_pq Ã_qq⁻¹ from the blocks P_j = Σ wᵢ (pᵢ/L)(part_j of q̃ᵢ)ᵀ.
        /// </summary>
        public static void Transform(in float3x3 p0, in float3x3 p1, in float3x3 p2, ReadOnlySpan<float3x3> inverseBlocks,
            out float3x3 t0, out float3x3 t1, out float3x3 t2)
        {
            t0 = math.mul(p0, inverseBlocks[0]) + math.mul(p1, inverseBlocks[3]) + math.mul(p2, inverseBlocks[6]);
            t1 = math.mul(p0, inverseBlocks[1]) + math.mul(p1, inverseBlocks[4]) + math.mul(p2, inverseBlocks[7]);
            t2 = math.mul(p0, inverseBlocks[2]) + math.mul(p1, inverseBlocks[5]) + math.mul(p2, inverseBlocks[8]);
        }
    }
}
