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
        /// Copies the embedding of a render mesh into a new blob asset. The caller owns the result: hand it to the baker
        /// (<c>AddBlobAsset</c>) or <c>Dispose</c> it.
        /// </summary>
        /// <param name="embedding">Nodes and weights of each render vertex.</param>
        /// <param name="restNormals">Rest unit normals of the render vertices (mesh space), one per embedded vertex.</param>
        /// <param name="restNodePositions">Rest node positions (m, mesh space) the embedding was built from.</param>
        /// <param name="restCenter">Rest centre of mass of the nodes (m, mesh space).</param>
        /// <param name="allocator">Allocator of the blob (<see cref="Allocator.Persistent"/> for baking).</param>
        /// <param name="edgeNodes">Quadratic FEM: 6 edge nodes per embedded vertex (<see cref="QuadraticTetrahedra.EmbeddingEdgeNodes"/>); null = linear.</param>
        /// <exception cref="ArgumentException">Counts differ or a node index is out of range.</exception>
        public static BlobAssetReference<SoftBodyEmbeddingBlob> Create(EmbeddedVertex[] embedding, float3[] restNormals,
            float3[] restNodePositions, float3 restCenter, Allocator allocator, int[] edgeNodes = null)
        {
            edgeNodes ??= Array.Empty<int>();
            if (edgeNodes.Length != 0 && edgeNodes.Length != QuadraticTet.EdgeCount * (embedding?.Length ?? 0))
                throw new ArgumentException($"{edgeNodes.Length} edge nodes for {embedding?.Length ?? 0} embedded vertices (6 each).", nameof(edgeNodes));
            embedding ??= Array.Empty<EmbeddedVertex>();
            restNormals ??= Array.Empty<float3>();
            restNodePositions ??= Array.Empty<float3>();
            Validate(embedding, restNormals, restNodePositions.Length);

            var builder = new BlobBuilder(Allocator.Temp);
            try
            {
                ref SoftBodyEmbeddingBlob root = ref builder.ConstructRoot<SoftBodyEmbeddingBlob>();
                builder.Construct(ref root.Vertices, embedding);
                builder.Construct(ref root.RestNormals, restNormals);
                builder.Construct(ref root.RestNodePositions, restNodePositions);
                root.RestCenter = restCenter;
                builder.Construct(ref root.EdgeNodes, edgeNodes);
                return builder.CreateBlobAssetReference<SoftBodyEmbeddingBlob>(allocator);
            }
            finally
            {
                builder.Dispose();
            }
        }

        static void Validate(EmbeddedVertex[] embedding, float3[] restNormals, int nodeCount)
        {
            if (restNormals.Length != embedding.Length)
                throw new ArgumentException($"{restNormals.Length} rest normals for {embedding.Length} embedded vertices.", nameof(restNormals));
            for (int v = 0; v < embedding.Length; v++)
            {
                int4 n = embedding[v].Nodes;
                if ((uint)n.x >= (uint)nodeCount || (uint)n.y >= (uint)nodeCount || (uint)n.z >= (uint)nodeCount || (uint)n.w >= (uint)nodeCount)
                    throw new ArgumentException($"Render vertex {v} is embedded in nodes {n}, but the mesh has {nodeCount} nodes.", nameof(embedding));
            }
        }
    }
}
