using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Deformed render vertices of a tetrahedral body (mass-spring, FEM) in the space of its render mesh. Each render
    /// vertex is the barycentric combination of its tetrahedron's nodes, x_v = Σₖ wₖ x_{nₖ} (world), drawn with the
    /// body's placement as <see cref="MeshDeformation"/> does: Rᵀ(x_v − c) + x⁰_cm, so the undeformed body gives back
    /// its rest vertices. Normals are area-weighted face normals summed per welded vertex. Burst-compatible (spans,
    /// no allocation).
    /// </summary>
    public static class EmbeddedMeshWriteBack
    {
        /// <summary>Computes the deformed render vertices and their bounds (m, mesh space; a zero box when there are none).</summary>
        /// <param name="nodes">Node positions (m, relative to the body's origin).</param>
        /// <param name="embedding">Nodes and weights of each render vertex.</param>
        /// <param name="vertexToWelded">Welded vertex of each render vertex.</param>
        /// <param name="triangles">Render triangle list (render-vertex indices).</param>
        /// <param name="center">Centre of mass c, relative to the same origin as <paramref name="nodes"/> (m).</param>
        /// <param name="rotation">Best-fit rotation R of the body.</param>
        /// <param name="restCenter">Rest centre of mass x⁰_cm in mesh space (m).</param>
        /// <param name="weldedNormals">Scratch, one per welded vertex (m²).</param>
        /// <param name="vertices">Output, one per render vertex: mesh-space position (m) and unit normal.</param>
        public static AxisAlignedBox Deform(ReadOnlySpan<float3> nodes, ReadOnlySpan<EmbeddedVertex> embedding,
            ReadOnlySpan<int> vertexToWelded, ReadOnlySpan<int> triangles, float3 center, quaternion rotation, float3 restCenter,
            Span<float3> weldedNormals, Span<DeformedVertex> vertices)
        {
            if (vertices.Length == 0)
                return default;
            quaternion inverse = math.conjugate(math.normalizesafe(rotation));
            float3 min = new float3(float.PositiveInfinity), max = new float3(float.NegativeInfinity);
            for (int v = 0; v < vertices.Length; v++)
            {
                EmbeddedVertex e = embedding[v];
                float3 x = e.Weights.x * nodes[e.Nodes.x] + e.Weights.y * nodes[e.Nodes.y]
                           + e.Weights.z * nodes[e.Nodes.z] + e.Weights.w * nodes[e.Nodes.w];
                float3 local = math.rotate(inverse, x - center) + restCenter;
                vertices[v] = new DeformedVertex { Position = local };
                min = math.min(min, local);
                max = math.max(max, local);
            }

            weldedNormals.Clear();
            int triangleEnd = triangles.Length - triangles.Length % 3;
            for (int t = 0; t < triangleEnd; t += 3)
            {
                int a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
                // |(b − a) × (c − a)| = 2 · area: summing it weights each face by its area.
                float3 n = math.cross(vertices[b].Position - vertices[a].Position, vertices[c].Position - vertices[a].Position);
                weldedNormals[vertexToWelded[a]] += n;
                weldedNormals[vertexToWelded[b]] += n;
                weldedNormals[vertexToWelded[c]] += n;
            }
            for (int v = 0; v < vertices.Length; v++)
            {
                DeformedVertex d = vertices[v];
                d.Normal = math.normalizesafe(weldedNormals[vertexToWelded[v]], MeshDeformation.FallbackNormal);
                vertices[v] = d;
            }
            return new AxisAlignedBox { Min = min, Max = max };
        }
    }
}
