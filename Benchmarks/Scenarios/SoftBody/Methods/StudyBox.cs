using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>The study's bodies: boxes of hexahedral cells, each split into 6 tetrahedra, and selections of their nodes.</summary>
    public static class StudyBox
    {
        /// <summary>A box of <paramref name="size"/> (m) centred on <paramref name="center"/>, <paramref name="cells"/> cells per axis, 6 tetrahedra per cell.</summary>
        public static TetrahedralMesh Create(float3 size, int3 cells, float3 center) => BoxMesh(size, cells, center);

        /// <summary>
        /// Nodes on a lattice of (cells + 1) points per axis; each cell split into the 6 tetrahedra around its diagonal
        /// from corner (0,0,0) to (1,1,1) (Kuhn's subdivision: neighbouring cells share the split of every face, so the
        /// mesh is conforming), each oriented positively.
        /// </summary>
        static TetrahedralMesh BoxMesh(float3 size, int3 cells, float3 center)
        {
            var n = new int3(cells.x + 1, cells.y + 1, cells.z + 1);
            var x = new float3[n.x * n.y * n.z];
            float3 h = size / new float3(cells.x, cells.y, cells.z), origin = center - 0.5f * size;
            for (int k = 0; k < n.z; k++)
            for (int j = 0; j < n.y; j++)
            for (int i = 0; i < n.x; i++)
                x[i + n.x * (j + n.y * k)] = origin + h * new float3(i, j, k);
            int Node(int3 p) => p.x + n.x * (p.y + n.y * p.z);
            var axes = new[] { new int3(1, 0, 0), new int3(0, 1, 0), new int3(0, 0, 1) };
            var perms = new[] { new int3(0, 1, 2), new int3(0, 2, 1), new int3(1, 0, 2), new int3(1, 2, 0), new int3(2, 0, 1), new int3(2, 1, 0) };
            var tets = new int4[cells.x * cells.y * cells.z * 6];
            int t = 0;
            for (int k = 0; k < cells.z; k++)
            for (int j = 0; j < cells.y; j++)
            for (int i = 0; i < cells.x; i++)
            {
                var c = new int3(i, j, k);
                foreach (int3 p in perms)
                {
                    int3 a = c, b = a + axes[p.x], d = b + axes[p.y], e = new int3(c.x + 1, c.y + 1, c.z + 1);
                    var tet = new int4(Node(a), Node(b), Node(d), Node(e));
                    if (TetrahedralMesh.SignedVolume(x[tet.x], x[tet.y], x[tet.z], x[tet.w]) < 0f)
                        tet = new int4(tet.x, tet.z, tet.y, tet.w);
                    tets[t++] = tet;
                }
            }
            return new TetrahedralMesh(x, tets);
        }

        /// <summary>Flags of the nodes whose coordinate <paramref name="axis"/> is within a hundredth of a cell of <paramref name="value"/>.</summary>
        public static bool[] NodesAt(TetrahedralMesh mesh, int axis, float value, float tolerance)
        {
            var flags = new bool[mesh.NodeCount];
            for (int i = 0; i < flags.Length; i++)
                flags[i] = Math.Abs(mesh.Positions[i][axis] - value) <= tolerance;
            return flags;
        }

        /// <summary>Index of the node nearest to <paramref name="point"/>.</summary>
        public static int Nearest(TetrahedralMesh mesh, float3 point)
        {
            int best = 0;
            for (int i = 1; i < mesh.NodeCount; i++)
                if (math.distancesq(mesh.Positions[i], point) < math.distancesq(mesh.Positions[best], point))
                    best = i;
            return best;
        }

        /// <summary>Σ of the tetrahedra's signed volumes at positions <paramref name="x"/> (m³).</summary>
        public static double Volume(TetrahedralMesh mesh, ReadOnlySpan<float3> x)
        {
            double v = 0;
            foreach (int4 t in mesh.Tetrahedra)
                v += TetrahedralMesh.SignedVolume(x[t.x], x[t.y], x[t.z], x[t.w]);
            return v;
        }
    }
}
