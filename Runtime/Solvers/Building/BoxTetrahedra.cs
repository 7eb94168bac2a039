using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>A box of nx × ny × nz cells (not necessarily cubes), each split into 6 tetrahedra by <see cref="KuhnSplit"/>.</summary>
    public static class BoxTetrahedra
    {
        /// <summary>
        /// Nodes on the (nx + 1)(ny + 1)(nz + 1) lattice points, numbered x fastest, then y, then z; node (i, j, k) is at
        /// center − size/2 + (i, j, k) ∘ size / cells (in double, rounded once). Cells are visited in the same order, 6
        /// positively oriented tetrahedra each: nx·ny·nz·6 in all, total volume size.x·size.y·size.z.
        /// </summary>
        /// <param name="size">Box size (m, each &gt; 0 and finite).</param>
        /// <param name="cells">Cells per axis (each ≥ 1; at most 2²⁴ nodes).</param>
        /// <param name="center">Box centre (m).</param>
        public static TetrahedralMesh Create(float3 size, int3 cells, float3 center)
        {
            if (!(size.x > 0f && size.y > 0f && size.z > 0f) || !math.all(math.isfinite(size)))
                throw new ArgumentOutOfRangeException(nameof(size), size, "The box size must be finite and positive on every axis.");
            if (cells.x < 1 || cells.y < 1 || cells.z < 1 || (double)(cells.x + 1) * (cells.y + 1) * (cells.z + 1) > 1 << 24)
                throw new ArgumentOutOfRangeException(nameof(cells), cells, "Each axis needs at least one cell, and the box at most 2^24 nodes.");

            int px = cells.x + 1, py = cells.y + 1, pz = cells.z + 1;
            var positions = new float3[px * py * pz];
            for (int k = 0; k < pz; k++)
            for (int j = 0; j < py; j++)
            for (int i = 0; i < px; i++)
                positions[i + px * (j + py * k)] = new float3(
                    Coordinate(center.x, size.x, i, cells.x),
                    Coordinate(center.y, size.y, j, cells.y),
                    Coordinate(center.z, size.z, k, cells.z));

            var tetrahedra = new int4[cells.x * cells.y * cells.z * KuhnSplit.TetrahedraPerBox];
            var corner = new int[8];
            int t = 0;
            for (int k = 0; k < cells.z; k++)
            for (int j = 0; j < cells.y; j++)
            for (int i = 0; i < cells.x; i++)
            {
                for (int c = 0; c < 8; c++)
                    corner[c] = (i + (c & 1)) + px * ((j + ((c >> 1) & 1)) + py * (k + ((c >> 2) & 1)));
                for (int s = 0; s < KuhnSplit.TetrahedraPerBox; s++)
                    tetrahedra[t++] = new int4(corner[KuhnSplit.Corners[4 * s]], corner[KuhnSplit.Corners[4 * s + 1]],
                        corner[KuhnSplit.Corners[4 * s + 2]], corner[KuhnSplit.Corners[4 * s + 3]]);
            }
            return new TetrahedralMesh(positions, tetrahedra);
        }

        static float Coordinate(float center, float size, int i, int n) => (float)(center + size * ((double)i / n - 0.5));
    }
}
