using System.Collections.Generic;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The 10-node connectivity of a linear tetrahedral mesh: one node at the midpoint of every edge, shared by the
    /// tetrahedra around it. The corner nodes keep their indices; edge nodes follow, in order of first appearance
    /// (tetrahedron by tetrahedron, edges in <see cref="QuadraticTet.EdgeCorners"/> order). Managed; bake time.
    /// </summary>
    public static class QuadraticTetrahedra
    {
        /// <summary>
        /// Positions (corners, then edge midpoints), the 10 nodes of every tetrahedron (<see cref="QuadraticTet"/> order) and,
        /// per edge node, the two corner nodes it lies between.
        /// </summary>
        public static void Build(TetrahedralMesh mesh, out float3[] positions, out int[] elementNodes, out int2[] edgeEnds)
        {
            int corners = mesh.NodeCount, tets = mesh.TetrahedronCount;
            var edgeIndex = new Dictionary<long, int>();
            var ends = new List<int2>();
            elementNodes = new int[QuadraticTet.NodeCount * tets];
            for (int t = 0; t < tets; t++)
            {
                int4 c = mesh.Tetrahedra[t];
                for (int a = 0; a < 4; a++)
                    elementNodes[QuadraticTet.NodeCount * t + a] = c[a];
                for (int k = 0; k < 6; k++)
                {
                    int2 e = QuadraticTet.EdgeCorners(k);
                    int i = math.min(c[e.x], c[e.y]), j = math.max(c[e.x], c[e.y]);
                    long key = (long)i * corners + j;
                    if (!edgeIndex.TryGetValue(key, out int node))
                    {
                        node = corners + ends.Count;
                        edgeIndex.Add(key, node);
                        ends.Add(new int2(i, j));
                    }
                    elementNodes[QuadraticTet.NodeCount * t + 4 + k] = node;
                }
            }
            edgeEnds = ends.ToArray();
            positions = new float3[corners + edgeEnds.Length];
            for (int i = 0; i < corners; i++)
                positions[i] = mesh.Positions[i];
            for (int k = 0; k < edgeEnds.Length; k++)
                positions[corners + k] = 0.5f * (mesh.Positions[edgeEnds[k].x] + mesh.Positions[edgeEnds[k].y]);
        }

        /// <summary>
        /// Per render vertex, the 6 edge nodes of its tetrahedron (<see cref="QuadraticTet.EdgeCorners"/> order over its 4 nodes),
        /// for the quadratic skinning of <see cref="EmbeddedMeshDeformation.QuadraticPosition"/>. <paramref name="edgeEnds"/>
        /// from <see cref="Build"/> (edge node k is node <paramref name="cornerCount"/> + k). Throws when a vertex's nodes are not a tetrahedron's.
        /// </summary>
        public static int[] EmbeddingEdgeNodes(EmbeddedVertex[] embedding, int cornerCount, int2[] edgeEnds)
        {
            var index = new Dictionary<long, int>(edgeEnds.Length);
            for (int k = 0; k < edgeEnds.Length; k++)
                index[(long)edgeEnds[k].x * cornerCount + edgeEnds[k].y] = cornerCount + k;
            var nodes = new int[QuadraticTet.EdgeCount * embedding.Length];
            for (int v = 0; v < embedding.Length; v++)
            {
                int4 c = embedding[v].Nodes;
                for (int k = 0; k < QuadraticTet.EdgeCount; k++)
                {
                    int2 e = QuadraticTet.EdgeCorners(k);
                    int i = math.min(c[e.x], c[e.y]), j = math.max(c[e.x], c[e.y]);
                    if (!index.TryGetValue((long)i * cornerCount + j, out int node))
                        throw new System.ArgumentException($"Render vertex {v}: nodes {i} and {j} share no edge of the mesh.", nameof(embedding));
                    nodes[QuadraticTet.EdgeCount * v + k] = node;
                }
            }
            return nodes;
        }
    }
}
