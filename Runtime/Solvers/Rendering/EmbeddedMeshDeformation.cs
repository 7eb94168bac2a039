using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Deformed render vertices of a tetrahedral body (mass-spring or finite elements): each vertex follows its
    /// tetrahedron's affine map, x = Σₖ wₖ x_{nodes[k]} (<see cref="EmbeddedVertex"/>). The output is in the space of
    /// the node positions given: pass nodes in mesh space (for example Rᵀ(xᵢ − c) + x⁰_cm, as
    /// <see cref="MeshDeformation"/> places shape-matching bodies) to get mesh-space vertices. Weights of a vertex
    /// outside its tetrahedron extrapolate the same affine map, so an affine motion of the nodes moves every vertex
    /// by exactly that motion (up to float round-off), and the rest nodes give back the rest vertices.
    /// <para>
    /// Normals follow Nanson's formula n da = cof(F) N dA, with F = Ds·Dm⁻¹ the tetrahedron's deformation gradient
    /// (Ds, Dm: edge matrices [x₁ − x₀, x₂ − x₀, x₃ − x₀] now and at rest). Since cof(Ds·Dm⁻¹) = cof(Ds)·Dmᵀ / det Dm and
    /// det Dm &gt; 0, n ∝ cof(Ds)·(Dmᵀ N), where cof(Ds) has columns d₂ × d₃, d₃ × d₁, d₁ × d₂ (no inverse, continuous
    /// through inversion). Unlike <see cref="MeshDeformation"/>, which rebuilds smooth normals from the triangles,
    /// this keeps the mesh's authored normals (hard edges stay hard), needs no triangle pass or scratch, and
    /// is independent per vertex, so ranges can run as parallel batches.
    /// </para>
    /// All methods take spans and allocate nothing (Burst-compatible); the range overloads write vertices
    /// start .. end − 1 only.
    /// </summary>
    public static class EmbeddedMeshDeformation
    {
        /// <summary>Vertex positions: vertices[v] = Σₖ wₖ nodePositions[nodes[k]] (m).</summary>
        /// <param name="embedding">One per render vertex.</param>
        /// <param name="nodePositions">Current node positions (m).</param>
        /// <param name="vertices">Output, one per render vertex (m).</param>
        public static void Deform(ReadOnlySpan<EmbeddedVertex> embedding, ReadOnlySpan<float3> nodePositions, Span<float3> vertices) =>
            Deform(embedding, nodePositions, vertices, 0, embedding.Length);

        /// <summary>Vertex positions for render vertices start .. end − 1 (m); see the full overload.</summary>
        public static void Deform(ReadOnlySpan<EmbeddedVertex> embedding, ReadOnlySpan<float3> nodePositions, Span<float3> vertices,
            int start, int end)
        {
            for (int v = start; v < end; v++)
                vertices[v] = Position(embedding[v], nodePositions);
        }

        /// <summary>
        /// Vertex positions and unit normals (Nanson's formula, see the class summary) into the write-back layout.
        /// Returns the bounds of the written vertices (m); a zero box when there are none.
        /// </summary>
        /// <param name="embedding">One per render vertex.</param>
        /// <param name="restNodePositions">Rest node positions (m), those the embedding was built from.</param>
        /// <param name="restNormals">Rest normals of the render mesh, one per render vertex (any length &gt; 0).</param>
        /// <param name="nodePositions">Current node positions (m).</param>
        /// <param name="vertices">Output, one per render vertex: position (m) and unit normal.</param>
        public static AxisAlignedBox Deform(ReadOnlySpan<EmbeddedVertex> embedding, ReadOnlySpan<float3> restNodePositions,
            ReadOnlySpan<float3> restNormals, ReadOnlySpan<float3> nodePositions, Span<DeformedVertex> vertices) =>
            Deform(embedding, restNodePositions, restNormals, nodePositions, vertices, 0, embedding.Length);

        /// <summary>Positions and normals of render vertices start .. end − 1; returns their bounds (merge the batches' bounds with min/max).</summary>
        public static AxisAlignedBox Deform(ReadOnlySpan<EmbeddedVertex> embedding, ReadOnlySpan<float3> restNodePositions,
            ReadOnlySpan<float3> restNormals, ReadOnlySpan<float3> nodePositions, Span<DeformedVertex> vertices, int start, int end) =>
            Deform(embedding, default, restNodePositions, restNormals, nodePositions, vertices, start, end);

        /// <summary>
        /// As above for a body of quadratic elements: <paramref name="edgeNodes"/> holds each vertex's 6 edge nodes
        /// (<see cref="QuadraticTet.EdgeCorners"/> order over its 4 nodes; empty = linear elements), and positions follow
        /// the quadratic shape functions (<see cref="QuadraticPosition"/>). Normals use the corner tetrahedron's F.
        /// </summary>
        public static AxisAlignedBox Deform(ReadOnlySpan<EmbeddedVertex> embedding, ReadOnlySpan<int> edgeNodes,
            ReadOnlySpan<float3> restNodePositions, ReadOnlySpan<float3> restNormals, ReadOnlySpan<float3> nodePositions,
            Span<DeformedVertex> vertices, int start, int end)
        {
            if (end <= start)
                return default;
            float3 min = new float3(float.PositiveInfinity), max = new float3(float.NegativeInfinity);
            for (int v = start; v < end; v++)
            {
                EmbeddedVertex e = embedding[v];
                float3 position = edgeNodes.Length > 0
                    ? QuadraticPosition(e, edgeNodes.Slice(QuadraticTet.EdgeCount * v, QuadraticTet.EdgeCount), nodePositions)
                    : Position(e, nodePositions);
                vertices[v] = new DeformedVertex
                {
                    Position = position,
                    Normal = Normal(e.Nodes, restNodePositions, nodePositions, restNormals[v]),
                };
                min = math.min(min, position);
                max = math.max(max, position);
            }
            return new AxisAlignedBox { Min = min, Max = max };
        }

        /// <summary>Σₖ wₖ x_{nodes[k]} (m).</summary>
        public static float3 Position(in EmbeddedVertex e, ReadOnlySpan<float3> nodePositions) =>
            e.Weights.x * nodePositions[e.Nodes.x] + e.Weights.y * nodePositions[e.Nodes.y]
            + e.Weights.z * nodePositions[e.Nodes.z] + e.Weights.w * nodePositions[e.Nodes.w];

        /// <summary>
        /// Σ N_a(w) x_a over the 10 nodes of a quadratic element, with the vertex's barycentric weights w: the linear position
        /// plus Σ_edges 4 w_a w_b (x_ab − ½(x_a + x_b)) (the corner functions L_a(2L_a − 1) regrouped by edge). Equal to
        /// <see cref="Position"/> while every edge node sits at its edge's midpoint.
        /// </summary>
        public static float3 QuadraticPosition(in EmbeddedVertex e, ReadOnlySpan<int> edgeNodes, ReadOnlySpan<float3> nodePositions)
        {
            float3 x = Position(e, nodePositions);
            for (int k = 0; k < QuadraticTet.EdgeCount; k++)
            {
                int2 ends = QuadraticTet.EdgeCorners(k);
                int a = e.Nodes[ends.x], b = e.Nodes[ends.y];
                x += 4f * Component(e.Weights, ends.x) * Component(e.Weights, ends.y)
                     * (nodePositions[edgeNodes[k]] - 0.5f * (nodePositions[a] + nodePositions[b]));
            }
            return x;
        }

        static float Component(float4 w, int k) => k == 0 ? w.x : k == 1 ? w.y : k == 2 ? w.z : w.w;

        /// <summary>Unit normal cof(Ds)·(Dmᵀ N) / |…| of a rest normal N carried by the tetrahedron (see the class summary).</summary>
        public static float3 Normal(int4 nodes, ReadOnlySpan<float3> restNodePositions, ReadOnlySpan<float3> nodePositions, float3 restNormal)
        {
            float3 x0 = restNodePositions[nodes.x];
            float3 m = new float3(
                math.dot(restNodePositions[nodes.y] - x0, restNormal),
                math.dot(restNodePositions[nodes.z] - x0, restNormal),
                math.dot(restNodePositions[nodes.w] - x0, restNormal));
            float3 y0 = nodePositions[nodes.x];
            float3 d1 = nodePositions[nodes.y] - y0, d2 = nodePositions[nodes.z] - y0, d3 = nodePositions[nodes.w] - y0;
            float3 n = m.x * math.cross(d2, d3) + m.y * math.cross(d3, d1) + m.z * math.cross(d1, d2);
            return math.normalizesafe(n, MeshDeformation.FallbackNormal);
        }
    }
}
