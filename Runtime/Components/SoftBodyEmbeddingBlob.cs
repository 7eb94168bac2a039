using System;
using SoftBodyDynamics.Solvers;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Immutable binding of a render mesh to the nodes of a tetrahedral body (blob asset, tier 1), shared by the
    /// mass-spring and finite-element methods: each render vertex sits at fixed barycentric weights in one
    /// tetrahedron, x_v = Σₖ wₖ x_{nₖ}, so the mesh follows the nodes however coarse the tetrahedra are. Normals are
    /// summed per welded vertex (<see cref="VertexToWelded"/>), so UV seams and split vertices stay smooth. Built at
    /// bake time by <see cref="SoftBodyEmbeddingBlobFactory"/>.
    /// </summary>
    public struct SoftBodyEmbeddingBlob
    {
        /// <summary>Tetrahedron nodes and barycentric weights (sum 1) of each render vertex.</summary>
        public BlobArray<EmbeddedVertex> Vertices;
        /// <summary>Welded vertex of each render vertex (render vertices at one position share one).</summary>
        public BlobArray<int> VertexToWelded;
        /// <summary>Number of welded vertices (scratch the write-back needs per body).</summary>
        public int WeldedCount;
        /// <summary>Nodes of the tetrahedral mesh the embedding refers to (every node index is below it).</summary>
        public int NodeCount;
        /// <summary>Triangle list of the render mesh (render-vertex indices, all sub-meshes), for the normals.</summary>
        public BlobArray<int> Triangles;
        /// <summary>Centre of mass of the rest nodes in mesh space (m): where the body's placement refers to.</summary>
        public float3 RestCenter;

        /// <summary>Number of render vertices.</summary>
        public int VertexCount => Vertices.Length;

        /// <summary>Render vertices' embedding as a span over blob memory (call on the blob in place).</summary>
        public ReadOnlySpan<EmbeddedVertex> VerticesSpan => SoftBodyShapeBlob.View(ref Vertices);
        /// <summary>Render vertex → welded vertex as a span over blob memory.</summary>
        public ReadOnlySpan<int> VertexToWeldedSpan => SoftBodyShapeBlob.View(ref VertexToWelded);
        /// <summary>Render triangle list as a span over blob memory.</summary>
        public ReadOnlySpan<int> TrianglesSpan => SoftBodyShapeBlob.View(ref Triangles);
    }
}
