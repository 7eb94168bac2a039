using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Binds render vertices to a tetrahedral mesh (any mesh of positively oriented tetrahedra, built or supplied).
    /// A vertex inside a tetrahedron gets that tetrahedron and its barycentric weights λ (solving
    /// [b − a, c − a, d − a]·(λ₁, λ₂, λ₃) = p − a, λ₀ = 1 − λ₁ − λ₂ − λ₃, in double). Where tetrahedra share the
    /// vertex (on a face, edge or node), the one with the largest smallest weight wins, then the lowest index.
    /// <para>
    /// A vertex outside every tetrahedron (all weights below −<see cref="InsideTolerance"/>) takes the nearest
    /// tetrahedron (Euclidean distance to its closest point; ties: lowest index) and the weights of the vertex itself
    /// in that tetrahedron's affine frame, which lie outside [0, 1]. They equal the closest point's weights plus the
    /// offset from the closest point expressed in the tetrahedron's frame: deformed, the vertex follows the closest
    /// point plus F times the offset (F: the tetrahedron's deformation gradient), and at rest it is reproduced exactly.
    /// </para>
    /// <para>
    /// Candidates come from a uniform grid over the bounds of the nodes and the vertices (about one cell per
    /// tetrahedron, at most 128 per axis) in which each tetrahedron is listed in every cell its bounding box touches;
    /// the nearest-tetrahedron search visits rings of cells outwards and stops once no unvisited cell can hold a
    /// nearer one. Deterministic; managed allocations; a bake-time tool.
    /// </para>
    /// </summary>
    public static class TetrahedralEmbedding
    {
        /// <summary>A vertex counts as inside a tetrahedron when all four weights are at least −1e-6 (float32 round-off of the input).</summary>
        public const double InsideTolerance = 1e-6;

        const int k_MaxCellsPerAxis = 128;

        /// <summary>Embeds every vertex of <paramref name="vertices"/> in <paramref name="mesh"/> (valid: see <see cref="TetrahedralMeshChecks"/>, at least one tetrahedron).</summary>
        /// <param name="mesh">Positively oriented tetrahedra with finite nodes (m).</param>
        /// <param name="vertices">Render-vertex rest positions, in the mesh's space (m).</param>
        public static EmbeddedVertex[] Embed(TetrahedralMesh mesh, ReadOnlySpan<float3> vertices)
        {
            if (mesh == null || mesh.TetrahedronCount == 0)
                throw new ArgumentException("The mesh needs at least one tetrahedron.", nameof(mesh));
            var grid = new Grid(mesh, vertices);
            var stamps = new int[mesh.TetrahedronCount];
            for (int t = 0; t < stamps.Length; t++)
                stamps[t] = -1;
            var result = new EmbeddedVertex[vertices.Length];
            for (int v = 0; v < vertices.Length; v++)
            {
                int tet = Locate(mesh, grid, vertices[v], v, stamps);
                int4 n = mesh.Tetrahedra[tet];
                Barycentric(vertices[v], mesh.Positions[n.x], mesh.Positions[n.y], mesh.Positions[n.z], mesh.Positions[n.w],
                    out double l0, out double l1, out double l2, out double l3);
                result[v] = new EmbeddedVertex { Nodes = n, Weights = new float4((float)l0, (float)l1, (float)l2, (float)l3) };
            }
            return result;
        }

        /// <summary>The barycentric weights of <paramref name="p"/> in the tetrahedron (a, b, c, d) by Cramer's rule, in double.</summary>
        public static void Barycentric(float3 p, float3 a, float3 b, float3 c, float3 d,
            out double l0, out double l1, out double l2, out double l3)
        {
            Double3 o = D(a), e1 = D(b) - o, e2 = D(c) - o, e3 = D(d) - o, q = D(p) - o;
            double det = Double3.Dot(e1, Double3.Cross(e2, e3));
            l1 = Double3.Dot(q, Double3.Cross(e2, e3)) / det;
            l2 = Double3.Dot(e1, Double3.Cross(q, e3)) / det;
            l3 = Double3.Dot(e1, Double3.Cross(e2, q)) / det;
            l0 = 1.0 - l1 - l2 - l3;
        }

        static Double3 D(float3 p) => new Double3(p.x, p.y, p.z);

        static int Locate(TetrahedralMesh mesh, Grid grid, float3 p, int stamp, int[] stamps)
        {
            grid.CellOf(p, out int ci, out int cj, out int ck);
            int best = -1;
            double bestScore = double.NegativeInfinity;
            for (int s = grid.Start[grid.Index(ci, cj, ck)], e = grid.Start[grid.Index(ci, cj, ck) + 1]; s < e; s++)
            {
                int t = grid.Items[s];
                double score = MinWeight(mesh, t, p);
                if (score > bestScore)
                {
                    bestScore = score;
                    best = t;
                }
            }
            if (best >= 0 && bestScore >= -InsideTolerance)
                return best;

            // Nearest tetrahedron: rings of cells at Chebyshev distance r around p's cell. After ring r every
            // unvisited tetrahedron's box misses the (2r + 1)³ block around p, so it is farther than r·h.
            best = -1;
            double bestDistance = double.PositiveInfinity;
            int maxRing = Math.Max(grid.Nx, Math.Max(grid.Ny, grid.Nz));
            for (int r = 0; r <= maxRing; r++)
            {
                for (int k = Math.Max(ck - r, 0); k <= Math.Min(ck + r, grid.Nz - 1); k++)
                for (int j = Math.Max(cj - r, 0); j <= Math.Min(cj + r, grid.Ny - 1); j++)
                for (int i = Math.Max(ci - r, 0); i <= Math.Min(ci + r, grid.Nx - 1); i++)
                {
                    if (Math.Max(Math.Abs(i - ci), Math.Max(Math.Abs(j - cj), Math.Abs(k - ck))) != r)
                        continue;
                    int cell = grid.Index(i, j, k);
                    for (int s = grid.Start[cell]; s < grid.Start[cell + 1]; s++)
                    {
                        int t = grid.Items[s];
                        if (stamps[t] == stamp)
                            continue;
                        stamps[t] = stamp;
                        double distance = Distance(mesh, t, p);
                        if (distance < bestDistance || (distance == bestDistance && t < best))
                        {
                            bestDistance = distance;
                            best = t;
                        }
                    }
                }
                if (best >= 0 && bestDistance <= r * grid.CellSize)
                    break;
            }
            return best;
        }

        static double MinWeight(TetrahedralMesh mesh, int t, float3 p)
        {
            int4 n = mesh.Tetrahedra[t];
            Barycentric(p, mesh.Positions[n.x], mesh.Positions[n.y], mesh.Positions[n.z], mesh.Positions[n.w],
                out double l0, out double l1, out double l2, out double l3);
            return Math.Min(Math.Min(l0, l1), Math.Min(l2, l3));
        }

        /// <summary>Distance (m) from p to the solid tetrahedron t: 0 inside, else the nearest of its four faces.</summary>
        static double Distance(TetrahedralMesh mesh, int t, float3 p)
        {
            if (MinWeight(mesh, t, p) >= 0.0)
                return 0.0;
            int4 n = mesh.Tetrahedra[t];
            Double3 a = D(mesh.Positions[n.x]), b = D(mesh.Positions[n.y]), c = D(mesh.Positions[n.z]), d = D(mesh.Positions[n.w]), q = D(p);
            double best = PointTriangleDistance(q, a, b, c);
            best = Math.Min(best, PointTriangleDistance(q, a, b, d));
            best = Math.Min(best, PointTriangleDistance(q, a, c, d));
            best = Math.Min(best, PointTriangleDistance(q, b, c, d));
            return best;
        }

        /// <summary>Distance from p to the triangle (a, b, c) by the closest-point regions of Ericson, Real-Time Collision Detection §5.1.5.</summary>
        static double PointTriangleDistance(Double3 p, Double3 a, Double3 b, Double3 c)
        {
            Double3 ab = b - a, ac = c - a, ap = p - a;
            double d1 = Double3.Dot(ab, ap), d2 = Double3.Dot(ac, ap);
            if (d1 <= 0 && d2 <= 0)
                return Length(p - a);
            Double3 bp = p - b;
            double d3 = Double3.Dot(ab, bp), d4 = Double3.Dot(ac, bp);
            if (d3 >= 0 && d4 <= d3)
                return Length(p - b);
            double vc = d1 * d4 - d3 * d2;
            if (vc <= 0 && d1 >= 0 && d3 <= 0)
                return Length(p - (a + d1 / (d1 - d3) * ab));
            Double3 cp = p - c;
            double d5 = Double3.Dot(ab, cp), d6 = Double3.Dot(ac, cp);
            if (d6 >= 0 && d5 <= d6)
                return Length(p - c);
            double vb = d5 * d2 - d1 * d6;
            if (vb <= 0 && d2 >= 0 && d6 <= 0)
                return Length(p - (a + d2 / (d2 - d6) * ac));
            double va = d3 * d6 - d5 * d4;
            if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
                return Length(p - (b + (d4 - d3) / (d4 - d3 + (d5 - d6)) * (c - b)));
            double denominator = 1.0 / (va + vb + vc);
            return Length(p - (a + vb * denominator * ab + vc * denominator * ac));
        }

        static double Length(Double3 v) => Math.Sqrt(Double3.Dot(v, v));

        /// <summary>Tetrahedra listed per cell (compressed rows, in tetrahedron order), cells x fastest.</summary>
        sealed class Grid
        {
            public readonly int Nx, Ny, Nz;
            public readonly double CellSize;
            public readonly int[] Start, Items;
            readonly double m_MinX, m_MinY, m_MinZ;

            public Grid(TetrahedralMesh mesh, ReadOnlySpan<float3> vertices)
            {
                AxisAlignedBox bounds = AxisAlignedBox.Of(mesh.Positions);
                if (vertices.Length > 0)
                {
                    AxisAlignedBox v = AxisAlignedBox.Of(vertices);
                    bounds.Min = math.min(bounds.Min, v.Min);
                    bounds.Max = math.max(bounds.Max, v.Max);
                }
                m_MinX = bounds.Min.x;
                m_MinY = bounds.Min.y;
                m_MinZ = bounds.Min.z;
                double ex = (double)bounds.Max.x - m_MinX, ey = (double)bounds.Max.y - m_MinY, ez = (double)bounds.Max.z - m_MinZ;
                double longest = Math.Max(ex, Math.Max(ey, ez));
                int perLongest = (int)Math.Min(k_MaxCellsPerAxis, Math.Max(1.0, Math.Ceiling(Math.Pow(mesh.TetrahedronCount, 1.0 / 3.0))));
                CellSize = longest > 0 ? longest / perLongest : 1.0;
                Nx = Count(ex);
                Ny = Count(ey);
                Nz = Count(ez);

                var lo = new int[3 * mesh.TetrahedronCount];
                var hi = new int[3 * mesh.TetrahedronCount];
                Start = new int[Nx * Ny * Nz + 1];
                for (int pass = 0; pass < 2; pass++)
                {
                    var fill = pass == 1 ? (int[])Start.Clone() : null;
                    if (pass == 1)
                        Items = new int[Start[Start.Length - 1]];
                    for (int t = 0; t < mesh.TetrahedronCount; t++)
                    {
                        if (pass == 0)
                        {
                            int4 n = mesh.Tetrahedra[t];
                            float3 min = math.min(math.min(mesh.Positions[n.x], mesh.Positions[n.y]), math.min(mesh.Positions[n.z], mesh.Positions[n.w]));
                            float3 max = math.max(math.max(mesh.Positions[n.x], mesh.Positions[n.y]), math.max(mesh.Positions[n.z], mesh.Positions[n.w]));
                            CellOf(min, out lo[3 * t], out lo[3 * t + 1], out lo[3 * t + 2]);
                            CellOf(max, out hi[3 * t], out hi[3 * t + 1], out hi[3 * t + 2]);
                        }
                        for (int k = lo[3 * t + 2]; k <= hi[3 * t + 2]; k++)
                        for (int j = lo[3 * t + 1]; j <= hi[3 * t + 1]; j++)
                        for (int i = lo[3 * t]; i <= hi[3 * t]; i++)
                        {
                            if (pass == 0)
                                Start[Index(i, j, k) + 1]++;
                            else
                                Items[fill[Index(i, j, k)]++] = t;
                        }
                    }
                    if (pass == 0)
                        for (int c = 0; c < Nx * Ny * Nz; c++)
                            Start[c + 1] += Start[c];
                }
            }

            int Count(double extent) => (int)Math.Min(k_MaxCellsPerAxis, Math.Max(1.0, Math.Ceiling(extent / CellSize)));

            public int Index(int i, int j, int k) => i + Nx * (j + Ny * k);

            public void CellOf(float3 p, out int i, out int j, out int k)
            {
                i = Cell(p.x, m_MinX, Nx);
                j = Cell(p.y, m_MinY, Ny);
                k = Cell(p.z, m_MinZ, Nz);
            }

            int Cell(double x, double min, int n) => (int)Math.Min(Math.Max(Math.Floor((x - min) / CellSize), 0.0), n - 1);
        }
    }
}
