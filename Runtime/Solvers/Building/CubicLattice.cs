using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// A cubic lattice of spacing s centred on a box: on an axis of extent E it has n = ⌊E/s⌋ + 1 points
    /// at centre + (i − (n − 1)/2)·s, i = 0..n−1 (evaluated in double, rounded once to float).
    /// </summary>
    public readonly struct CubicLattice
    {
        /// <summary>Spacing (m).</summary>
        public readonly float Spacing;
        /// <summary>Points per axis.</summary>
        public readonly int CountX, CountY, CountZ;
        readonly float3 m_Center;

        /// <param name="bounds">The box to fill (m).</param>
        /// <param name="spacing">Spacing (m, &gt; 0), with at most <see cref="int.MaxValue"/> points per axis.</param>
        public CubicLattice(in AxisAlignedBox bounds, float spacing)
        {
            Spacing = spacing;
            m_Center = bounds.Center;
            float3 extent = bounds.Extent;
            CountX = (int)PointsPerAxis(extent.x, spacing);
            CountY = (int)PointsPerAxis(extent.y, spacing);
            CountZ = (int)PointsPerAxis(extent.z, spacing);
        }

        /// <summary>Points per axis for an extent (m) and spacing (m): ⌊extent/spacing⌋ + 1, in double so that absurd inputs do not overflow.</summary>
        public static double PointsPerAxis(float extent, float spacing) => Math.Floor((double)extent / spacing) + 1.0;

        /// <summary>Points in the lattice of <paramref name="bounds"/> (in double).</summary>
        public static double PointCount(in AxisAlignedBox bounds, float spacing)
        {
            float3 extent = bounds.Extent;
            return PointsPerAxis(extent.x, spacing) * PointsPerAxis(extent.y, spacing) * PointsPerAxis(extent.z, spacing);
        }

        /// <summary>Coordinate i on an axis (0 = x, 1 = y, 2 = z) (m).</summary>
        public float Coordinate(int axis, int i) => (float)(m_Center[axis] + (i - 0.5 * (Count(axis) - 1)) * Spacing);

        /// <summary>Lattice point (i, j, k) (m).</summary>
        public float3 Point(int i, int j, int k) => new float3(Coordinate(0, i), Coordinate(1, j), Coordinate(2, k));

        /// <summary>Points on an axis.</summary>
        public int Count(int axis) => axis == 0 ? CountX : axis == 1 ? CountY : CountZ;

        /// <summary>
        /// The indices on <paramref name="axis"/> whose exact coordinate start + i·s lies in [lo, hi] (m), clamped
        /// to first ∈ [0, n] and last ∈ [−1, n − 1] (empty when first &gt; last). The float32 coordinates differ
        /// from the exact ones by at most ε·|coordinate|: callers widen [lo, hi] by more than that.
        /// </summary>
        public void IndexRange(int axis, double lo, double hi, out int first, out int last)
        {
            double start = m_Center[axis] - 0.5 * (Count(axis) - 1) * (double)Spacing;
            double a = Math.Ceiling((lo - start) / Spacing), b = Math.Floor((hi - start) / Spacing);
            first = (int)Math.Min(Math.Max(a, 0.0), Count(axis));
            last = (int)Math.Max(Math.Min(b, Count(axis) - 1.0), -1.0);
        }
    }
}
