using System;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>Builds <see cref="SoftBodyEmbeddingBlob"/> assets (bake time, managed).</summary>
    public static class SoftBodyEmbeddingBlobFactory
    {
        /// <summary>
        /// Copies the embedding of a render mesh into a new blob asset, welding coincident render vertices for the
        /// normals. The caller owns the result: hand it to the baker (<c>AddBlobAsset</c>) or <c>Dispose</c> it.
        /// </summary>
        /// <param name="embedding">Nodes and weights of each render vertex.</param>
        /// <param name="renderVertices">Rest positions of the render vertices (m, mesh space at the baked scale), for the weld.</param>
        /// <param name="triangles">Render triangle list (a multiple of 3); null or empty when there is none.</param>
        /// <param name="nodeCount">Nodes of the tetrahedral mesh: every embedded node index must be below it.</param>
        /// <param name="restCenter">Rest centre of mass of the nodes (m, mesh space).</param>
        /// <param name="allocator">Allocator of the blob (<see cref="Allocator.Persistent"/> for baking).</param>
        /// <exception cref="ArgumentException">Counts differ, a node or triangle index is out of range, or the triangle list is not a multiple of 3.</exception>
        public static BlobAssetReference<SoftBodyEmbeddingBlob> Create(EmbeddedVertex[] embedding, float3[] renderVertices,
            int[] triangles, int nodeCount, float3 restCenter, Allocator allocator)
        {
            embedding ??= Array.Empty<EmbeddedVertex>();
            renderVertices ??= Array.Empty<float3>();
            triangles ??= Array.Empty<int>();
            Validate(embedding, renderVertices, triangles, nodeCount);
            WeldedVertices welded = MeshWelding.Weld(renderVertices,
                MeshWelding.ResolveTolerance(AxisAlignedBox.Of(renderVertices), MeshWelding.DefaultRelativeTolerance, 0f));

            var builder = new BlobBuilder(Allocator.Temp);
            try
            {
                ref SoftBodyEmbeddingBlob root = ref builder.ConstructRoot<SoftBodyEmbeddingBlob>();
                builder.Construct(ref root.Vertices, embedding);
                builder.Construct(ref root.VertexToWelded, welded.VertexToParticle);
                root.WeldedCount = welded.ParticleCount;
                root.NodeCount = nodeCount;
                builder.Construct(ref root.Triangles, triangles);
                root.RestCenter = restCenter;
                return builder.CreateBlobAssetReference<SoftBodyEmbeddingBlob>(allocator);
            }
            finally
            {
                builder.Dispose();
            }
        }

        static void Validate(EmbeddedVertex[] embedding, float3[] renderVertices, int[] triangles, int nodeCount)
        {
            if (renderVertices.Length != embedding.Length)
                throw new ArgumentException($"{embedding.Length} embedded vertices for {renderVertices.Length} render vertices.", nameof(embedding));
            for (int v = 0; v < embedding.Length; v++)
            {
                int4 n = embedding[v].Nodes;
                if ((uint)n.x >= (uint)nodeCount || (uint)n.y >= (uint)nodeCount || (uint)n.z >= (uint)nodeCount || (uint)n.w >= (uint)nodeCount)
                    throw new ArgumentException($"Render vertex {v} is embedded in nodes {n}, but the mesh has {nodeCount} nodes.", nameof(embedding));
            }
            if (triangles.Length % 3 != 0)
                throw new ArgumentException($"The triangle list has {triangles.Length} indices, not a multiple of 3.", nameof(triangles));
            for (int i = 0; i < triangles.Length; i++)
                if ((uint)triangles[i] >= (uint)embedding.Length)
                    throw new ArgumentException(
                        $"Triangle index {i} refers to render vertex {triangles[i]}, but the mesh has {embedding.Length} embedded vertices.",
                        nameof(triangles));
        }
    }
}
