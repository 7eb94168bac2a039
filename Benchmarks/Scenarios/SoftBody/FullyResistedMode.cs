using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// A displacement field δᵢ = s(xᵢ⁰) e_x (every particle moved along x by an amount that depends only on its rest
    /// x plane) that no cluster's goals can follow, so the goals resist it fully and the body's continuous model
    /// reduces, exactly and for any amplitude, to one damped oscillator ÿ = −ω² y − 2ζω ẏ for its amplitude y.
    /// <para>Why: s is chosen so that in every cluster c, Σ_{i∈c} wᵢ s m(qᵢ) = 0 for each monomial m of the rest offsets q
    /// the goals span (rigid: 1, q_y, q_z; linear: those and q_x; quadratic: every monomial of degree ≤ 2). Then the
    /// cluster's centre does not move (Σ w δ = 0), A_pq = A_qq + y·e_x (Σ w s q)ᵀ gains at most a symmetric x-x entry
    /// (rigid: R stays I), A = A_pq A_qq⁻¹ = I (linear: Ã = R = I) and Ã_pq of the quadratic basis is unchanged
    /// (quadratic: Ã = [I 0 0]), so every goal stays at its rest position and the pull is exactly −ω² δ. The mode
    /// has no momentum or angular momentum (Σ over clusters of Σ w s = Σᵢ mᵢ sᵢ = 0), so uᵢ = 0 and the damping acts
    /// on all of its velocity. Since the solver's substep has exactly the eigenvalues of that oscillator
    /// (<see cref="OscillatorDiscretization"/>), its sampled amplitude is exactly c₁μ₁ⁿ + c₂μ₂ⁿ with μ = e^{s·dt}:
    /// the measured frequency and decay must be the parameters' to float32 round-off, at any step and substep count.</para>
    /// Exists for a lattice with enough x planes per cluster (one cluster of 6 planes: every mode; overlapping
    /// 4-plane clusters: rigid and linear, not quadratic).
    /// </summary>
    public static class FullyResistedMode
    {
        /// <summary>
        /// sᵢ for every particle (max |s| = 1), the null-space vector of the constraints above closest to an
        /// alternating pattern across the x planes (or, when that is orthogonal to them all, the null vector that changes most between planes); null when the constraints leave no such field.
        /// </summary>
        public static double[] Find(ShapeMatchingModelData model, ShapeMatchingMode mode)
        {
            // Rest x planes.
            var planes = new List<double>();
            foreach (var p in model.RestPositions)
                if (!planes.Exists(v => Math.Abs(v - p.x) < 1e-6))
                    planes.Add(p.x);
            planes.Sort();
            int count = planes.Count;
            var plane = new int[model.ParticleCount];
            for (int i = 0; i < plane.Length; i++)
                plane[i] = planes.FindIndex(v => Math.Abs(v - model.RestPositions[i].x) < 1e-6);
            var inverseCount = new double[model.ParticleCount];
            foreach (int i in model.ClusterParticles)
                inverseCount[i] += 1;
            for (int i = 0; i < inverseCount.Length; i++)
                inverseCount[i] = inverseCount[i] > 0 ? 1.0 / inverseCount[i] : 0;

            // CᵀC over every cluster and monomial; its null space holds the admissible patterns.
            var ctc = new double[count, count];
            var row = new double[count];
            var rows = new List<double[]>();
            int monomials = mode == ShapeMatchingMode.Quadratic ? 10 : mode == ShapeMatchingMode.Linear ? 4 : 3;
            for (int c = 0; c < model.ClusterCount; c++)
            {
                int start = model.ClusterOffsets[c], end = model.ClusterOffsets[c + 1];
                double mass = 0;
                Vector3d center = default;
                for (int k = start; k < end; k++)
                {
                    int i = model.ClusterParticles[k];
                    double w = model.Masses[i] * inverseCount[i];
                    mass += w;
                    center += w * (Vector3d)model.RestPositions[i];
                }
                center = center / mass;
                for (int m = 0; m < monomials; m++)
                {
                    Array.Clear(row, 0, count);
                    for (int k = start; k < end; k++)
                    {
                        int i = model.ClusterParticles[k];
                        double w = model.Masses[i] * inverseCount[i];
                        Vector3d q = (Vector3d)model.RestPositions[i] - center;
                        row[plane[i]] += w * Monomial(mode, m, q);
                    }
                    for (int a = 0; a < count; a++)
                    for (int b = 0; b < count; b++)
                        ctc[a, b] += row[a] * row[b];
                    rows.Add((double[])row.Clone());
                }
            }
            SymmetricEigen(ctc, out double[] values, out double[,] vectors);
            double largest = 0;
            foreach (double v in values)
                largest = Math.Max(largest, Math.Abs(v));
            var pattern = new double[count];
            for (int e = 0; e < count; e++)
            {
                if (!(Math.Abs(values[e]) <= 1e-10 * largest))
                    continue;
                double projection = 0;
                for (int j = 0; j < count; j++)
                    projection += vectors[j, e] * ((j & 1) == 0 ? 1 : -1);
                for (int j = 0; j < count; j++)
                    pattern[j] += projection * vectors[j, e];
            }
            double max = MaxAbs(pattern);
            if (!(max > 1e-6))
            {
                // The alternating pattern can be orthogonal to the whole null space (a symmetric lattice): take the
                // null vector that changes most from plane to plane instead.
                double best = 0;
                for (int e = 0; e < count; e++)
                {
                    if (!(Math.Abs(values[e]) <= 1e-10 * largest))
                        continue;
                    double roughness = 0;
                    for (int j = 0; j + 1 < count; j++)
                        roughness += (vectors[j + 1, e] - vectors[j, e]) * (vectors[j + 1, e] - vectors[j, e]);
                    if (roughness > best)
                    {
                        best = roughness;
                        for (int j = 0; j < count; j++)
                            pattern[j] = vectors[j, e];
                    }
                }
                max = MaxAbs(pattern);
                if (!(max > 1e-6))
                    return null;
            }
            // The eigenvectors of CᵀC are null vectors only to √ε; project the constraints' row space out (twice, modified
            // Gram–Schmidt) so every constraint holds to float64 round-off.
            List<double[]> basis = OrthonormalBasis(rows);
            for (int pass = 0; pass < 2; pass++)
                foreach (double[] b in basis)
                {
                    double dot = 0;
                    for (int j = 0; j < count; j++)
                        dot += b[j] * pattern[j];
                    for (int j = 0; j < count; j++)
                        pattern[j] -= dot * b[j];
                }
            max = MaxAbs(pattern);
            if (!(max > 1e-6))
                return null;
            var s = new double[model.ParticleCount];
            for (int i = 0; i < s.Length; i++)
                s[i] = pattern[plane[i]] / max;
            return s;
        }

        /// <summary>An orthonormal basis of the span of <paramref name="rows"/> (modified Gram–Schmidt, applied twice per row).</summary>
        static List<double[]> OrthonormalBasis(List<double[]> rows)
        {
            var basis = new List<double[]>();
            double largest = 0;
            foreach (double[] r in rows)
            {
                double n = 0;
                foreach (double v in r)
                    n += v * v;
                largest = Math.Max(largest, Math.Sqrt(n));
            }
            foreach (double[] r in rows)
            {
                var v = (double[])r.Clone();
                for (int pass = 0; pass < 2; pass++)
                    foreach (double[] b in basis)
                    {
                        double dot = 0;
                        for (int j = 0; j < v.Length; j++)
                            dot += b[j] * v[j];
                        for (int j = 0; j < v.Length; j++)
                            v[j] -= dot * b[j];
                    }
                double norm = 0;
                foreach (double x in v)
                    norm += x * x;
                norm = Math.Sqrt(norm);
                if (!(norm > 1e-9 * largest))
                    continue;
                for (int j = 0; j < v.Length; j++)
                    v[j] /= norm;
                basis.Add(v);
            }
            return basis;
        }

        static double MaxAbs(double[] values)
        {
            double max = 0;
            foreach (double v in values)
                max = Math.Max(max, Math.Abs(v));
            return max;
        }

        /// <summary>Monomial <paramref name="index"/> of the goal space: rigid {1, q_y, q_z}; linear {1, q_x, q_y, q_z}; quadratic adds the six of degree 2.</summary>
        static double Monomial(ShapeMatchingMode mode, int index, Vector3d q)
        {
            if (mode == ShapeMatchingMode.Rigid)
                return index == 0 ? 1 : index == 1 ? q.Y : q.Z;
            switch (index)
            {
                case 0: return 1;
                case 1: return q.X;
                case 2: return q.Y;
                case 3: return q.Z;
                case 4: return q.X * q.X;
                case 5: return q.Y * q.Y;
                case 6: return q.Z * q.Z;
                case 7: return q.X * q.Y;
                case 8: return q.Y * q.Z;
                default: return q.Z * q.X;
            }
        }

        /// <summary>Cyclic Jacobi eigen-decomposition of a small symmetric matrix: eigenvalues and eigenvectors (columns).</summary>
        static void SymmetricEigen(double[,] matrix, out double[] values, out double[,] vectors)
        {
            int n = matrix.GetLength(0);
            var a = (double[,])matrix.Clone();
            vectors = new double[n, n];
            for (int i = 0; i < n; i++)
                vectors[i, i] = 1;
            for (int sweep = 0; sweep < 100; sweep++)
            {
                double off = 0, diag = 0;
                for (int p = 0; p < n; p++)
                {
                    diag += a[p, p] * a[p, p];
                    for (int q = p + 1; q < n; q++)
                        off += a[p, q] * a[p, q];
                }
                if (!(off > 1e-32 * diag))
                    break;
                for (int p = 0; p < n - 1; p++)
                for (int q = p + 1; q < n; q++)
                {
                    if (a[p, q] == 0)
                        continue;
                    double theta = (a[q, q] - a[p, p]) / (2 * a[p, q]);
                    double t = Math.Sign(theta) / (Math.Abs(theta) + Math.Sqrt(theta * theta + 1));
                    if (theta == 0)
                        t = 1;
                    double c = 1 / Math.Sqrt(t * t + 1), s = t * c;
                    for (int k = 0; k < n; k++)
                    {
                        double akp = a[k, p], akq = a[k, q];
                        a[k, p] = c * akp - s * akq;
                        a[k, q] = s * akp + c * akq;
                    }
                    for (int k = 0; k < n; k++)
                    {
                        double apk = a[p, k], aqk = a[q, k];
                        a[p, k] = c * apk - s * aqk;
                        a[q, k] = s * apk + c * aqk;
                    }
                    for (int k = 0; k < n; k++)
                    {
                        double vkp = vectors[k, p], vkq = vectors[k, q];
                        vectors[k, p] = c * vkp - s * vkq;
                        vectors[k, q] = s * vkp + c * vkq;
                    }
                }
            }
            values = new double[n];
            for (int i = 0; i < n; i++)
                values[i] = a[i, i];
        }
    }
}
