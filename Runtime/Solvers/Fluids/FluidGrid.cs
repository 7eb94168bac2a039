using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The uniform grid over a fluid's domain box, cell size = half the kernel radius h, so every neighbour of a
    /// particle lies in the 5×5×5 cells around its own (<see cref="SearchRange"/> = 2). Cells are numbered x fastest: key = x + Nx·(y + Ny·z); a particle outside
    /// the box counts in the nearest boundary cell. Key <see cref="DeadKey"/> marks a particle to drop: the counting
    /// sort puts it after every live one. Because x is fastest, the three cells of a row (x − 1 … x + 1) are one
    /// contiguous range of the sorted particles, so a neighbour search reads 25 ranges (<see cref="NeighbourRows"/>).
    /// </summary>
    public readonly struct FluidGrid
    {
        /// <summary>Lower corner of the grid (m).</summary>
        public readonly float3 Origin;
        /// <summary>Cell edge (m), at least h / <see cref="SearchRange"/>.</summary>
        public readonly float CellSize;
        /// <summary>1 / <see cref="CellSize"/> (1/m).</summary>
        public readonly float InverseCellSize;
        /// <summary>Cells along x, y, z (each ≥ 1).</summary>
        public readonly int3 Dimensions;
        /// <summary>Periodic axes (<see cref="FluidParameters.Periodic"/>): the neighbour search wraps around them.</summary>
        public readonly bool3 Periodic;
        /// <summary>The box's extent in cells (not rounded; the last cell of an axis may be partial).</summary>
        public readonly float3 ExtentInCells;

        /// <summary>Cells searched on each side of a particle's own: the cell edge is h / SearchRange.</summary>
        public const int SearchRange = 2;

        /// <summary>Most cells a grid may have (the cell-start table is 4 bytes per cell).</summary>
        public const int MaxCells = 1 << 24;

        /// <summary>The grid over [<paramref name="min"/>, <paramref name="max"/>] for kernel radius <paramref name="kernelRadius"/>: cells of h / <see cref="SearchRange"/>, coarsened while the grid has more than <see cref="MaxCells"/>.</summary>
        public FluidGrid(float3 min, float3 max, float kernelRadius) : this(min, max, kernelRadius, new bool3(false, false, false)) { }

        /// <summary>The grid of <see cref="FluidGrid(float3, float3, float)"/> with the periodic axes <paramref name="periodic"/>.</summary>
        public FluidGrid(float3 min, float3 max, float kernelRadius, bool3 periodic)
        {
            float cellSize = kernelRadius / SearchRange;
            float3 extent = math.max(max - min, new float3(cellSize));
            int3 dims = CellsAcross(extent, cellSize);
            // A domain too large for the table gets coarser cells (still correct: a cell larger than h only adds candidates).
            while ((long)dims.x * dims.y * dims.z > MaxCells)
            {
                cellSize *= 1.25f;
                dims = CellsAcross(extent, cellSize);
            }
            Origin = min;
            CellSize = cellSize;
            InverseCellSize = 1f / cellSize;
            Dimensions = dims;
            Periodic = periodic;
            ExtentInCells = extent / cellSize;
        }

        static int3 CellsAcross(float3 extent, float cellSize) => new int3(
            math.max(1, (int)math.ceil(extent.x / cellSize)),
            math.max(1, (int)math.ceil(extent.y / cellSize)),
            math.max(1, (int)math.ceil(extent.z / cellSize)));

        /// <summary>Number of cells.</summary>
        public int CellCount => Dimensions.x * Dimensions.y * Dimensions.z;

        /// <summary>The key that sorts a particle past every cell (dropped by the sort).</summary>
        public int DeadKey => CellCount;

        /// <summary>Integer cell of a point, clamped into the grid.</summary>
        public int3 Cell(float3 x)
        {
            float3 c = (x - Origin) * InverseCellSize;
            // Clamp in float first so that a huge coordinate cannot overflow the integer conversion.
            return new int3(
                (int)math.clamp(math.floor(c.x), 0f, Dimensions.x - 1),
                (int)math.clamp(math.floor(c.y), 0f, Dimensions.y - 1),
                (int)math.clamp(math.floor(c.z), 0f, Dimensions.z - 1));
        }

        /// <summary>Key of a cell (x fastest).</summary>
        public int Key(int3 cell) => cell.x + Dimensions.x * (cell.y + Dimensions.y * cell.z);

        /// <summary>Key of the cell holding <paramref name="x"/>.</summary>
        public int Key(float3 x) => Key(Cell(x));
    }
}
