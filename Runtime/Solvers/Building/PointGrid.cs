using System;
using System.Collections.Generic;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Uniform hash grid of points for "is there a point within r of p" queries at bake time.
    /// Cells are cubes of <see cref="CellSize"/> (m) anchored at an origin; each cell keeps its points in
    /// insertion order, and the dictionary is only looked up, never enumerated, so results do not depend
    /// on hash order. Queries search the 27 cells around p, which is complete for radii up to the cell size.
    /// Cell coordinates are packed into 21 bits each; far-apart cells that share a packed key only add
    /// candidates, which the exact distance test then rejects.
    /// </summary>
    public sealed class PointGrid
    {
        const int k_BitsPerAxis = 21;
        const long k_AxisMask = (1L << k_BitsPerAxis) - 1;

        readonly Dictionary<long, List<int>> m_Cells = new Dictionary<long, List<int>>();
        readonly List<float3> m_Positions = new List<float3>();
        readonly List<int> m_Indices = new List<int>();
        readonly float3 m_Origin;

        /// <summary>Edge length of a cell (m): the largest radius a query may use.</summary>
        public float CellSize { get; }

        /// <param name="origin">Any point near the data, usually the bounds' minimum (m).</param>
        /// <param name="cellSize">Cell edge (m, finite, &gt; 0).</param>
        public PointGrid(float3 origin, float cellSize)
        {
            if (!(cellSize > 0f) || !math.isfinite(cellSize))
                throw new ArgumentOutOfRangeException(nameof(cellSize), cellSize, "The cell size must be finite and positive.");
            m_Origin = origin;
            CellSize = cellSize;
        }

        /// <summary>Adds point <paramref name="position"/> under the caller's <paramref name="index"/>.</summary>
        public void Add(float3 position, int index)
        {
            long key = Key(Cell(position, 0), Cell(position, 1), Cell(position, 2));
            if (!m_Cells.TryGetValue(key, out List<int> bucket))
            {
                bucket = new List<int>();
                m_Cells.Add(key, bucket);
            }
            bucket.Add(m_Positions.Count);
            m_Positions.Add(position);
            m_Indices.Add(index);
        }

        /// <summary>
        /// The smallest index among the points within <paramref name="radius"/> of <paramref name="position"/>
        /// (distance ≤ radius when <paramref name="inclusive"/>, else &lt; radius), or −1 when there is none.
        /// </summary>
        /// <param name="radius">Search radius (m, ≤ <see cref="CellSize"/>).</param>
        public int LowestIndexWithin(float3 position, float radius, bool inclusive)
        {
            if (radius > CellSize)
                throw new ArgumentOutOfRangeException(nameof(radius), radius, "The radius must not exceed the cell size.");
            float radiusSquared = radius * radius;
            long cx = Cell(position, 0), cy = Cell(position, 1), cz = Cell(position, 2);
            int best = -1;
            for (long dz = -1; dz <= 1; dz++)
            for (long dy = -1; dy <= 1; dy++)
            for (long dx = -1; dx <= 1; dx++)
            {
                if (!m_Cells.TryGetValue(Key(cx + dx, cy + dy, cz + dz), out List<int> bucket))
                    continue;
                foreach (int slot in bucket)
                {
                    float d2 = math.distancesq(m_Positions[slot], position);
                    bool within = inclusive ? d2 <= radiusSquared : d2 < radiusSquared;
                    if (within && (best < 0 || m_Indices[slot] < best))
                        best = m_Indices[slot];
                }
            }
            return best;
        }

        long Cell(float3 p, int axis) => (long)Math.Floor(((double)p[axis] - m_Origin[axis]) / CellSize);

        static long Key(long x, long y, long z) =>
            (x & k_AxisMask) | ((y & k_AxisMask) << k_BitsPerAxis) | ((z & k_AxisMask) << (2 * k_BitsPerAxis));
    }
}
