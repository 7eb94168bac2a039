using System;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>Builds <see cref="ShapeMatchingShapeBlob"/> assets from a shape-matching model (bake time, managed).</summary>
    public static class ShapeMatchingShapeBlobFactory
    {
        /// <summary>
        /// Copies <paramref name="model"/> and the render binding into a new blob asset. The caller owns
        /// the result: hand it to the baker (<c>AddBlobAsset</c>) or <c>Dispose</c> it.
        /// </summary>
        /// <param name="model">The precomputed model (<see cref="ShapeMatchingModelData.Create"/>).</param>
        /// <param name="vertexToParticle">Particle of each render vertex; null or empty for a body without a render binding.</param>
        /// <param name="triangles">Render triangle list (render-vertex indices, a multiple of 3); null or empty when unbound.</param>
        /// <param name="allocator">Allocator of the blob (<see cref="Allocator.Persistent"/> for baking).</param>
        /// <exception cref="ArgumentException">A binding index is out of range, or the triangle list is not a multiple of 3.</exception>
        public static BlobAssetReference<ShapeMatchingShapeBlob> Create(ShapeMatchingModelData model, int[] vertexToParticle,
            int[] triangles, Allocator allocator)
        {
            if (model == null)
                throw new ArgumentNullException(nameof(model));
            vertexToParticle ??= Array.Empty<int>();
            triangles ??= Array.Empty<int>();
            Validate(model.ParticleCount, vertexToParticle, triangles);

            // A plain local, not a using variable: BlobBuilder is a mutable struct.
            var builder = new BlobBuilder(Allocator.Temp);
            try
            {
                ref ShapeMatchingShapeBlob root = ref builder.ConstructRoot<ShapeMatchingShapeBlob>();
                builder.Construct(ref root.RestPositions, model.RestPositions);
                builder.Construct(ref root.Masses, model.Masses);
                builder.Construct(ref root.InverseClusterCounts, model.InverseClusterCounts);
                builder.Construct(ref root.ClusterOffsets, model.ClusterOffsets);
                builder.Construct(ref root.ClusterParticles, model.ClusterParticles);
                builder.Construct(ref root.ClusterWeights, model.ClusterWeights);
                builder.Construct(ref root.ClusterRest, model.ClusterRest);
                builder.Construct(ref root.QuadraticInverse, model.QuadraticInverse ?? Array.Empty<float3x3>());
                root.BodyRest = model.BodyRest;
                builder.Construct(ref root.VertexToParticle, vertexToParticle);
                builder.Construct(ref root.Triangles, triangles);
                return builder.CreateBlobAssetReference<ShapeMatchingShapeBlob>(allocator);
            }
            finally
            {
                builder.Dispose();
            }
        }

        static void Validate(int particleCount, int[] vertexToParticle, int[] triangles)
        {
            for (int v = 0; v < vertexToParticle.Length; v++)
                if ((uint)vertexToParticle[v] >= (uint)particleCount)
                    throw new ArgumentException(
                        $"Render vertex {v} is bound to particle {vertexToParticle[v]}, but the body has {particleCount} particles.",
                        nameof(vertexToParticle));
            if (triangles.Length % 3 != 0)
                throw new ArgumentException($"The triangle list has {triangles.Length} indices, not a multiple of 3.", nameof(triangles));
            for (int i = 0; i < triangles.Length; i++)
                if ((uint)triangles[i] >= (uint)vertexToParticle.Length)
                    throw new ArgumentException(
                        $"Triangle index {i} refers to render vertex {triangles[i]}, but the mesh has {vertexToParticle.Length} bound vertices.",
                        nameof(triangles));
        }
    }
}
