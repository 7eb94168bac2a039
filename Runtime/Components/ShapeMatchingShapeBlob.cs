using System;
using SoftBodyDynamics.Solvers;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Immutable, shareable data of a soft body (blob asset): the shape-matching model (rest shape,
    /// masses, overlapping clusters and their precomputed rest matrices) and the binding of the render
    /// mesh to the particles. Built at bake time by <see cref="ShapeMatchingShapeBlobFactory"/>; every
    /// instance of a prefab shares one blob.
    /// <para>
    /// Always access it in place (<c>ref var shape = ref blob.Value;</c>): blob arrays are relative
    /// pointers and are only valid inside blob storage.
    /// </para>
    /// </summary>
    public struct ShapeMatchingShapeBlob
    {
        /// <summary>Rest positions x⁰ᵢ in mesh space (m), one per particle.</summary>
        public BlobArray<float3> RestPositions;
        /// <summary>Particle masses mᵢ (kg, &gt; 0).</summary>
        public BlobArray<float> Masses;
        /// <summary>1/nᵢ with nᵢ the number of clusters containing particle i (0 for a particle in no cluster).</summary>
        public BlobArray<float> InverseClusterCounts;
        /// <summary>CSR offsets: cluster c owns <c>ClusterParticles[ClusterOffsets[c] .. ClusterOffsets[c + 1])</c>.</summary>
        public BlobArray<int> ClusterOffsets;
        /// <summary>Particle indices of every cluster, concatenated.</summary>
        public BlobArray<int> ClusterParticles;
        /// <summary>Weight wᵢ = mᵢ/nᵢ of each entry of <see cref="ClusterParticles"/> (kg).</summary>
        public BlobArray<float> ClusterWeights;
        /// <summary>Rest data of each cluster.</summary>
        public BlobArray<ClusterRestData> ClusterRest;
        /// <summary>Scaled Ã_qq⁻¹ blocks of the quadratic mode, 9 per cluster; empty when built without it.</summary>
        public BlobArray<float3x3> QuadraticInverse;
        /// <summary>Rest data of the whole body with the plain masses (its rest centre places the mesh).</summary>
        public ClusterRestData BodyRest;
        /// <summary>Particle of each render-mesh vertex (render vertices split at UV seams share a particle).</summary>
        public BlobArray<int> VertexToParticle;
        /// <summary>Triangle list of the render mesh (render-vertex indices, all sub-meshes), for the normals.</summary>
        public BlobArray<int> Triangles;

        /// <summary>Number of particles.</summary>
        public int ParticleCount => RestPositions.Length;
        /// <summary>Number of clusters.</summary>
        public int ClusterCount => ClusterRest.Length;
        /// <summary>Number of render-mesh vertices (0 when the body has no render binding).</summary>
        public int VertexCount => VertexToParticle.Length;

        /// <summary>
        /// The solver's view of this blob (spans over blob memory, no copy). Call it on the blob in place;
        /// the spans live as long as the blob asset.
        /// </summary>
        public ShapeMatchingModel AsModel() => new ShapeMatchingModel(View(ref RestPositions), View(ref Masses),
            View(ref InverseClusterCounts), View(ref ClusterOffsets), View(ref ClusterParticles), View(ref ClusterWeights),
            View(ref ClusterRest), View(ref QuadraticInverse), BodyRest);

        /// <summary>Render vertex → particle binding as a span over blob memory.</summary>
        public ReadOnlySpan<int> VertexToParticleSpan => View(ref VertexToParticle);

        /// <summary>Render triangle list as a span over blob memory.</summary>
        public ReadOnlySpan<int> TrianglesSpan => View(ref Triangles);

        /// <summary>A read-only span over a blob array, in place.</summary>
        public static unsafe ReadOnlySpan<T> View<T>(ref BlobArray<T> array) where T : unmanaged =>
            new ReadOnlySpan<T>(array.GetUnsafePtr(), array.Length);
    }
}
