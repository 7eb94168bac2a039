using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The candidate neighbours of a point as at most 25 ranges of sorted particle slots: one per (y, z) row of the
    /// 5×5×5 cells of size h/2 around it (every point within h of it lies in them), each row's five cells being
    /// contiguous because keys run x fastest. Half-kernel cells scan (2.5h)³ instead of the (3h)³ of kernel-sized
    /// cells, 42 % fewer candidates. Filled by <see cref="Find"/>; iterate <c>for r &lt; Count: for j in [Begin(r), End(r))</c>.
    /// </summary>
    public unsafe struct NeighbourRows
    {
        fixed int m_Ranges[2 * MaxRows];
        /// <summary>Most rows: (2·<see cref="FluidGrid.SearchRange"/> + 1)².</summary>
        public const int MaxRows = (2 * FluidGrid.SearchRange + 1) * (2 * FluidGrid.SearchRange + 1);

        /// <summary>Number of non-empty rows (0–25).</summary>
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
            const int R = FluidGrid.SearchRange;
            int x0 = math.max(c.x - R, 0), x1 = math.min(c.x + R, d.x - 1);
            int z0 = math.max(c.z - R, 0), z1 = math.min(c.z + R, d.z - 1);
            int y0 = math.max(c.y - R, 0), y1 = math.min(c.y + R, d.y - 1);
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
