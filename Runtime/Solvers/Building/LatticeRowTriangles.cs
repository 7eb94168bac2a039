using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// For every x-row (j, k) of a <see cref="CubicLattice"/>, the triangles whose bounding box, widened by a
    /// margin, may reach the row's line, in CSR form (row r = j + CountY·k), and per row the points whose
    /// segment from the previous point may pass within the margin of a triangle. Conservative: it may flag
    /// points that are clear of the surface, never miss one that is not.
    /// </summary>
    public sealed class LatticeRowTriangles
    {
        /// <summary>Most row entries built (2²⁶); beyond it <see cref="TryBuild"/> gives up and the caller tests every point.</summary>
        public const long MaxEntries = 1L << 26;

        /// <summary>Row r lists <c>Triangles[Offsets[r] .. Offsets[r + 1])</c>.</summary>
        public int[] Offsets;
        /// <summary>Triangle indices, ascending within a row.</summary>
        public int[] Triangles;

        double m_Margin;
        /// <summary>Per triangle: x range widened by the margin (m), then the (y, z) of its three corners (m).</summary>
        double[] m_MinX, m_MaxX, m_CornersYZ;

        /// <summary>Builds the lists, or returns null when they would exceed <see cref="MaxEntries"/>.</summary>
        /// <param name="positions">Particle positions (m).</param>
        /// <param name="triangles">Particle indices, three per triangle.</param>
        /// <param name="margin">Widening (m, &gt; the float32 round-off of the lattice coordinates).</param>
        public static LatticeRowTriangles TryBuild(ReadOnlySpan<float3> positions, ReadOnlySpan<int> triangles, in CubicLattice lattice, double margin)
        {
            int triangleCount = triangles.Length / 3;
            var rangeY = new int[2 * triangleCount];
            var rangeZ = new int[2 * triangleCount];
            var index = new LatticeRowTriangles
            {
                m_Margin = margin,
                m_MinX = new double[triangleCount],
                m_MaxX = new double[triangleCount],
                m_CornersYZ = new double[6 * triangleCount],
            };
            long entries = 0;
            for (int t = 0; t < triangleCount; t++)
            {
                float3 a = positions[triangles[3 * t]], b = positions[triangles[3 * t + 1]], c = positions[triangles[3 * t + 2]];
                float3 min = math.min(a, math.min(b, c)), max = math.max(a, math.max(b, c));
                index.m_MinX[t] = min.x - margin;
                index.m_MaxX[t] = max.x + margin;
                index.m_CornersYZ[6 * t] = a.y;
                index.m_CornersYZ[6 * t + 1] = a.z;
                index.m_CornersYZ[6 * t + 2] = b.y;
                index.m_CornersYZ[6 * t + 3] = b.z;
                index.m_CornersYZ[6 * t + 4] = c.y;
                index.m_CornersYZ[6 * t + 5] = c.z;
                lattice.IndexRange(1, min.y - margin, max.y + margin, out rangeY[2 * t], out rangeY[2 * t + 1]);
                lattice.IndexRange(2, min.z - margin, max.z + margin, out rangeZ[2 * t], out rangeZ[2 * t + 1]);
                entries += (long)Math.Max(0, rangeY[2 * t + 1] - rangeY[2 * t] + 1) * Math.Max(0, rangeZ[2 * t + 1] - rangeZ[2 * t] + 1);
            }
            if (entries > MaxEntries)
                return null;

            int rows = lattice.CountY * lattice.CountZ;
            var counts = new int[rows + 1];
            for (int t = 0; t < triangleCount; t++)
                for (int k = rangeZ[2 * t]; k <= rangeZ[2 * t + 1]; k++)
                    for (int j = rangeY[2 * t]; j <= rangeY[2 * t + 1]; j++)
                        counts[j + lattice.CountY * k + 1]++;
            for (int r = 0; r < rows; r++)
                counts[r + 1] += counts[r];
            index.Offsets = (int[])counts.Clone();
            index.Triangles = new int[entries];
            for (int t = 0; t < triangleCount; t++)
                for (int k = rangeZ[2 * t]; k <= rangeZ[2 * t + 1]; k++)
                    for (int j = rangeY[2 * t]; j <= rangeY[2 * t + 1]; j++)
                        index.Triangles[counts[j + lattice.CountY * k]++] = t;
            return index;
        }

        /// <summary>True when no triangle may reach row (<paramref name="j"/>, <paramref name="k"/>).</summary>
        public bool IsEmpty(int j, int k, in CubicLattice lattice)
        {
            int row = j + lattice.CountY * k;
            return Offsets[row] == Offsets[row + 1];
        }

        /// <summary>
        /// Sets <paramref name="mayCross"/>[i] for every point i of row (<paramref name="j"/>, <paramref name="k"/>)
        /// whose segment from point i − 1 (from x = −∞ for i = 0) may pass within the margin of a listed
        /// triangle: the row's line passes within the margin of the triangle's (y, z) projection, and the
        /// segment meets the triangle's widened x range. Clears the others.
        /// </summary>
        public void MarkRow(int j, int k, in CubicLattice lattice, bool[] mayCross)
        {
            Array.Clear(mayCross, 0, lattice.CountX);
            int row = j + lattice.CountY * k;
            double y = lattice.Coordinate(1, j), z = lattice.Coordinate(2, k);
            for (int e = Offsets[row]; e < Offsets[row + 1]; e++)
            {
                int t = Triangles[e];
                if (!ProjectionWithinMargin(t, y, z))
                    continue;
                // Segments [x_{i−1}, x_i] meeting [minX, maxX] run from the first point ≥ minX to one past the
                // last point ≤ maxX; a box left of x_0 (last < 0) meets the segment from −∞, i = 0.
                lattice.IndexRange(0, m_MinX[t], m_MaxX[t], out int first, out int last);
                int end = Math.Min(lattice.CountX - 1, Math.Max(last, -1) + 1);
                for (int i = first; i <= end; i++)
                    mayCross[i] = true;
            }
        }

        /// <summary>
        /// True when (y, z) lies inside triangle t's projection onto the yz plane or within the margin of
        /// its edges. Evaluated in double; its round-off (≈1e-16 of the coordinates) is far inside the margin.
        /// </summary>
        bool ProjectionWithinMargin(int t, double y, double z)
        {
            int o = 6 * t;
            double ay = m_CornersYZ[o], az = m_CornersYZ[o + 1], by = m_CornersYZ[o + 2], bz = m_CornersYZ[o + 3];
            double cy = m_CornersYZ[o + 4], cz = m_CornersYZ[o + 5];
            double d1 = (by - ay) * (z - az) - (bz - az) * (y - ay);
            double d2 = (cy - by) * (z - bz) - (cz - bz) * (y - by);
            double d3 = (ay - cy) * (z - cz) - (az - cz) * (y - cy);
            bool negative = d1 < 0.0 || d2 < 0.0 || d3 < 0.0, positive = d1 > 0.0 || d2 > 0.0 || d3 > 0.0;
            if (!(negative && positive))
                return true;
            double m2 = m_Margin * m_Margin;
            return SegmentDistanceSquared(y, z, ay, az, by, bz) <= m2
                   || SegmentDistanceSquared(y, z, by, bz, cy, cz) <= m2
                   || SegmentDistanceSquared(y, z, cy, cz, ay, az) <= m2;
        }

        static double SegmentDistanceSquared(double py, double pz, double ay, double az, double by, double bz)
        {
            double uy = by - ay, uz = bz - az, wy = py - ay, wz = pz - az;
            double length2 = uy * uy + uz * uz;
            double s = length2 > 0.0 ? Math.Max(0.0, Math.Min(1.0, (wy * uy + wz * uz) / length2)) : 0.0;
            double dy = wy - s * uy, dz = wz - s * uz;
            return dy * dy + dz * dz;
        }
    }
}
