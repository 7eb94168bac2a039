using System;
using System.Collections.Generic;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Overlapping region clusters as in lattice shape matching (Rivers &amp; James 2007). With cluster
    /// size d, cluster centres lie on a cubic lattice of spacing h = d/2 centred on the particle bounds
    /// (n = ⌈E/h⌉ + 1 centres on an axis of extent E, so the lattice spans the bounds), and a cluster is
    /// every particle inside the axis-aligned cube of half-size h around its centre (|x − c|∞ ≤ h): a
    /// cube, like the 3×3×3 lattice regions of Rivers &amp; James. Each particle lies within h/2 of a
    /// centre on every axis, so every particle is covered; away from the boundary it is in 2 or 3
    /// clusters per axis (8 to 27 in all), which is the overlap that lets the clusters bend.
    /// <para>
    /// Only centres that hold a particle make clusters. Then, in lattice order (z-major, then y, then x),
    /// a cluster equal to an earlier one is dropped, and a weak cluster (fewer than 4 particles, or a planar rest shape by
    /// <see cref="ShapeMatching.PlanarRestShapeThreshold"/>) is dropped when every one of its particles
    /// is still in another cluster. Weak clusters that remain are counted in <see cref="ClusterSet.WeakClusterCount"/>.
    /// </para>
    /// </summary>
    public static class ClusterBuilder
    {
        /// <summary>Fewest particles a cluster needs for a non-planar rest shape.</summary>
        public const int MinStrongClusterSize = 4;

        /// <summary>Most cluster centres on one axis (2²⁰): a smaller cluster size is rejected.</summary>
        public const double MaxCentresPerAxis = 1 << 20;

        /// <summary>True when <paramref name="clusterSize"/> (m) yields one cluster of every particle: d ≤ 0 or d ≥ the longest extent.</summary>
        public static bool IsSingleCluster(in AxisAlignedBox bounds, float clusterSize) =>
            clusterSize <= 0f || clusterSize >= bounds.LongestExtent;

        /// <summary>Cluster centres on an axis of <paramref name="extent"/> (m): ⌈extent / (d/2)⌉ + 1.</summary>
        public static double CentresPerAxis(float extent, float clusterSize) => Math.Ceiling(extent / (0.5 * clusterSize)) + 1.0;

        /// <summary>True when the lattice of centres would exceed <see cref="MaxCentresPerAxis"/> on some axis.</summary>
        public static bool IsTooFine(in AxisAlignedBox bounds, float clusterSize) =>
            !IsSingleCluster(bounds, clusterSize) && CentresPerAxis(bounds.LongestExtent, clusterSize) > MaxCentresPerAxis;

        /// <summary>Builds the clusters of <paramref name="positions"/> (finite) for cluster size <paramref name="clusterSize"/> (m, finite).</summary>
        public static ClusterSet Build(ReadOnlySpan<float3> positions, float clusterSize)
        {
            if (!math.isfinite(clusterSize))
                throw new ArgumentOutOfRangeException(nameof(clusterSize), clusterSize, "The cluster size must be finite.");
            AxisAlignedBox bounds = AxisAlignedBox.Of(positions);
            if (IsTooFine(bounds, clusterSize))
                throw new ArgumentOutOfRangeException(nameof(clusterSize), clusterSize, "The cluster size is too small for these bounds.");

            List<int[]> clusters;
            if (IsSingleCluster(bounds, clusterSize))
                clusters = new List<int[]> { Everything(positions.Length) };
            else
            {
                clusters = LatticeClusters(positions, bounds, clusterSize);
                DropDuplicates(clusters);
            }
            int weak = DropCoveredWeakClusters(positions, clusters);
            return ToCsr(clusters, weak);
        }

        static int[] Everything(int count)
        {
            var all = new int[count];
            for (int i = 0; i < count; i++)
                all[i] = i;
            return all;
        }

        static List<int[]> LatticeClusters(ReadOnlySpan<float3> positions, in AxisAlignedBox bounds, float clusterSize)
        {
            double h = 0.5 * clusterSize;
            float3 extent = bounds.Extent, center = bounds.Center;
            long nx = (long)CentresPerAxis(extent.x, clusterSize);
            long ny = (long)CentresPerAxis(extent.y, clusterSize);
            long nz = (long)CentresPerAxis(extent.z, clusterSize);
            double sx = center.x - 0.5 * (nx - 1) * h, sy = center.y - 0.5 * (ny - 1) * h, sz = center.z - 0.5 * (nz - 1) * h;

            var byCentre = new Dictionary<long, List<int>>();
            var keys = new List<long>();
            for (int p = 0; p < positions.Length; p++)
            {
                float3 x = positions[p];
                Range(x.x, sx, h, nx, out long x0, out long x1);
                Range(x.y, sy, h, ny, out long y0, out long y1);
                Range(x.z, sz, h, nz, out long z0, out long z1);
                for (long k = z0; k <= z1; k++)
                for (long j = y0; j <= y1; j++)
                for (long i = x0; i <= x1; i++)
                {
                    long key = i + nx * (j + ny * k);
                    if (!byCentre.TryGetValue(key, out List<int> list))
                    {
                        list = new List<int>();
                        byCentre.Add(key, list);
                        keys.Add(key);
                    }
                    list.Add(p);
                }
            }
            long[] ordered = keys.ToArray();
            Array.Sort(ordered);
            var clusters = new List<int[]>(ordered.Length);
            foreach (long key in ordered)
                clusters.Add(byCentre[key].ToArray());
            return clusters;
        }

        /// <summary>Centre indices i in [0, n) whose cube holds coordinate x: |x − (start + i·h)| ≤ h, tested exactly per candidate.</summary>
        static void Range(float x, double start, double h, long n, out long first, out long last)
        {
            long cell = (long)Math.Floor((x - start) / h);
            long lo = Math.Max(0L, cell - 2);
            long hi = Math.Min(n - 1, cell + 2);
            first = long.MaxValue;
            last = long.MinValue;
            for (long i = lo; i <= hi; i++)
            {
                if (!(Math.Abs(x - (start + i * h)) <= h))
                    continue;
                first = Math.Min(first, i);
                last = Math.Max(last, i);
            }
        }

        static void DropDuplicates(List<int[]> clusters)
        {
            var byHash = new Dictionary<ulong, List<int[]>>();
            var kept = new List<int[]>(clusters.Count);
            foreach (int[] cluster in clusters)
            {
                ulong hash = Hash(cluster);
                if (!byHash.TryGetValue(hash, out List<int[]> same))
                {
                    same = new List<int[]>();
                    byHash.Add(hash, same);
                }
                bool duplicate = false;
                foreach (int[] other in same)
                    duplicate |= SameMembers(cluster, other);
                if (duplicate)
                    continue;
                same.Add(cluster);
                kept.Add(cluster);
            }
            clusters.Clear();
            clusters.AddRange(kept);
        }

        /// <summary>FNV-1a over the member indices.</summary>
        static ulong Hash(int[] cluster)
        {
            ulong hash = 14695981039346656037UL;
            foreach (int p in cluster)
                hash = (hash ^ (uint)p) * 1099511628211UL;
            return hash;
        }

        static bool SameMembers(int[] a, int[] b)
        {
            if (a.Length != b.Length)
                return false;
            for (int i = 0; i < a.Length; i++)
                if (a[i] != b[i])
                    return false;
            return true;
        }

        /// <summary>Drops weak clusters whose particles all stay covered; returns how many weak clusters remain.</summary>
        static int DropCoveredWeakClusters(ReadOnlySpan<float3> positions, List<int[]> clusters)
        {
            var coverage = new int[positions.Length];
            foreach (int[] cluster in clusters)
                foreach (int p in cluster)
                    coverage[p]++;

            var kept = new List<int[]>(clusters.Count);
            int weakKept = 0;
            foreach (int[] cluster in clusters)
            {
                if (!IsWeak(positions, cluster))
                {
                    kept.Add(cluster);
                    continue;
                }
                bool covered = true;
                foreach (int p in cluster)
                    covered &= coverage[p] > 1;
                if (covered)
                {
                    foreach (int p in cluster)
                        coverage[p]--;
                    continue;
                }
                kept.Add(cluster);
                weakKept++;
            }
            clusters.Clear();
            clusters.AddRange(kept);
            return weakKept;
        }

        /// <summary>
        /// Fewer than <see cref="MinStrongClusterSize"/> particles, or a planar rest shape: det C ≤ τ·(tr C / 3)³
        /// for the unweighted second moment C = Σ qᵢqᵢᵀ, τ = <see cref="ShapeMatching.PlanarRestShapeThreshold"/>
        /// (the solver's own test, on uniform weights), evaluated in double.
        /// </summary>
        public static bool IsWeak(ReadOnlySpan<float3> positions, int[] cluster)
        {
            if (cluster.Length < MinStrongClusterSize)
                return true;
            double mx = 0, my = 0, mz = 0;
            foreach (int p in cluster)
            {
                mx += positions[p].x;
                my += positions[p].y;
                mz += positions[p].z;
            }
            mx /= cluster.Length;
            my /= cluster.Length;
            mz /= cluster.Length;
            double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
            foreach (int p in cluster)
            {
                double qx = positions[p].x - mx, qy = positions[p].y - my, qz = positions[p].z - mz;
                xx += qx * qx; xy += qx * qy; xz += qx * qz;
                yy += qy * qy; yz += qy * qz; zz += qz * qz;
            }
            double det = xx * (yy * zz - yz * yz) - xy * (xy * zz - yz * xz) + xz * (xy * yz - yy * xz);
            double meanDiagonal = (xx + yy + zz) / 3.0;
            return !(meanDiagonal > 0.0 && det > ShapeMatching.PlanarRestShapeThreshold * meanDiagonal * meanDiagonal * meanDiagonal);
        }

        static ClusterSet ToCsr(List<int[]> clusters, int weak)
        {
            var offsets = new int[clusters.Count + 1];
            int total = 0;
            for (int c = 0; c < clusters.Count; c++)
            {
                total += clusters[c].Length;
                offsets[c + 1] = total;
            }
            var particles = new int[total];
            for (int c = 0; c < clusters.Count; c++)
                Array.Copy(clusters[c], 0, particles, offsets[c], clusters[c].Length);
            return new ClusterSet { Offsets = offsets, Particles = particles, WeakClusterCount = weak };
        }
    }
}
