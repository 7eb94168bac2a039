using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The candidate neighbours of a point as at most 9 ranges of sorted particle slots: one per (y, z) row of the
    /// 3×3×3 cells around it, each row's three cells being contiguous because keys run x fastest. Filled by
    /// <see cref="Find"/>; iterate <c>for r &lt; Count: for j in [Begin(r), End(r))</c>.
    /// </summary>
    public unsafe struct NeighbourRows
    {
        fixed int m_Ranges[18];
        /// <summary>Number of non-empty rows (0–9).</summary>
        public int Count;

        /// <summary>First sorted slot of row <paramref name="row"/>.</summary>
        public int Begin(int row) => m_Ranges[2 * row];
        /// <summary>One past the last sorted slot of row <paramref name="row"/>.</summary>
        public int End(int row) => m_Ranges[2 * row + 1];

        void Add(int begin, int end)
        {
            m_Ranges[2 * Count] = begin;
            m_Ranges[2 * Count + 1] = end;
            Count++;
        }

        /// <summary>The rows around the cell of <paramref name="x"/> in the cell-start table <paramref name="cellStart"/>.</summary>
        public static NeighbourRows Find(in FluidGrid grid, ReadOnlySpan<int> cellStart, float3 x)
        {
            var rows = new NeighbourRows();
            int3 c = grid.Cell(x);
            int3 d = grid.Dimensions;
            int x0 = math.max(c.x - 1, 0), x1 = math.min(c.x + 1, d.x - 1);
            int z0 = math.max(c.z - 1, 0), z1 = math.min(c.z + 1, d.z - 1);
            int y0 = math.max(c.y - 1, 0), y1 = math.min(c.y + 1, d.y - 1);
            for (int z = z0; z <= z1; z++)
            for (int y = y0; y <= y1; y++)
            {
                int row = d.x * (y + d.y * z);
                int begin = cellStart[row + x0], end = cellStart[row + x1 + 1];
                if (end > begin)
                    rows.Add(begin, end);
            }
            return rows;
        }
    }
}
