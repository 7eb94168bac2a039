using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Selections of the nodes of the study's bodies (boxes of <see cref="BoxTetrahedra"/>) and their volume.</summary>
    public static class StudyBox
    {
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

        /// <summary>
        /// Volume (m³) of the body with node positions <paramref name="x"/>: Σ of its tetrahedra's signed volumes. When
        /// <paramref name="x"/> has more nodes than the mesh (a quadratic body: its edge nodes follow, <see cref="QuadraticTetrahedra"/>),
        /// each element is split at its edge nodes into 8 tetrahedra, so a bulging edge counts (the error of the split is
        /// O(h³) of the curvature, against O(h²) for the corners alone).
        /// </summary>
        public static double Volume(TetrahedralMesh mesh, ReadOnlySpan<float3> x)
        {
            double v = 0;
            if (x.Length == mesh.NodeCount)
            {
                foreach (int4 t in mesh.Tetrahedra)
                    v += TetrahedralMesh.SignedVolume(x[t.x], x[t.y], x[t.z], x[t.w]);
                return v;
            }
            int[] nodes = QuadraticNodes(mesh);
            for (int e = 0; e < mesh.TetrahedronCount; e++)
                foreach (int4 s in s_Split)
                    v += TetrahedralMesh.SignedVolume(x[nodes[10 * e + s.x]], x[nodes[10 * e + s.y]], x[nodes[10 * e + s.z]], x[nodes[10 * e + s.w]]);
            return v;
        }

        /// <summary>
        /// The 8 tetrahedra of a 10-node element (local nodes: corners 0–3, edges 4 = 01, 5 = 02, 6 = 03, 7 = 12, 8 = 13, 9 = 23):
        /// one at each corner and four around the 5–8 diagonal of the inner octahedron, each oriented like the element.
        /// </summary>
        static readonly int4[] s_Split =
        {
            new int4(0, 4, 5, 6), new int4(4, 1, 7, 8), new int4(5, 7, 2, 9), new int4(6, 8, 9, 3),
            new int4(4, 5, 6, 8), new int4(4, 7, 5, 8), new int4(5, 7, 9, 8), new int4(5, 9, 6, 8),
        };

        static readonly System.Runtime.CompilerServices.ConditionalWeakTable<TetrahedralMesh, int[]> s_QuadraticNodes =
            new System.Runtime.CompilerServices.ConditionalWeakTable<TetrahedralMesh, int[]>();

        static int[] QuadraticNodes(TetrahedralMesh mesh) => s_QuadraticNodes.GetValue(mesh, m =>
        {
            QuadraticTetrahedra.Build(m, out _, out int[] elementNodes, out _);
            return elementNodes;
        });
    }
}
