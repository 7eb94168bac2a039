using System;
using SoftBodyDynamics.Solvers;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Immutable binding of a render mesh to the nodes of a tetrahedral body (blob asset, tier 1), shared by the
    /// mass-spring and finite-element methods: each render vertex sits at fixed barycentric weights in one
    /// tetrahedron, x_v = Σₖ wₖ x_{nₖ}, and its normal follows the tetrahedron's deformation gradient (Nanson's
    /// formula, <see cref="EmbeddedMeshDeformation"/>), so the mesh follows the nodes however coarse the tetrahedra
    /// are and keeps its authored hard edges. Self-contained (it holds its own copy of the rest nodes), so the
    /// write-back does not depend on the method. Built at bake time by <see cref="SoftBodyEmbeddingBlobFactory"/>.
    /// </summary>
    public struct SoftBodyEmbeddingBlob
    {
        /// <summary>Tetrahedron nodes and barycentric weights (sum 1) of each render vertex.</summary>
        public BlobArray<EmbeddedVertex> Vertices;
        /// <summary>Rest unit normal of each render vertex in mesh space.</summary>
        public BlobArray<float3> RestNormals;
        /// <summary>Rest positions of the nodes in mesh space (m): the embedding's reference (a copy of the shape blob's).</summary>
        public BlobArray<float3> RestNodePositions;
        /// <summary>Centre of mass of the rest nodes in mesh space (m): where the body's placement refers to.</summary>
        public float3 RestCenter;
        /// <summary>
        /// Quadratic FEM elements: the 6 edge nodes of each render vertex's tetrahedron, so positions follow the quadratic
        /// shape functions (<see cref="EmbeddedMeshDeformation.QuadraticPosition"/>); empty otherwise.
        /// </summary>
        public BlobArray<int> EdgeNodes;

        /// <summary>Number of render vertices.</summary>
        public int VertexCount => Vertices.Length;
        /// <summary>Number of nodes of the tetrahedral mesh.</summary>
        public int NodeCount => RestNodePositions.Length;

        /// <summary>Render vertices' embedding as a span over blob memory (call on the blob in place).</summary>
        public ReadOnlySpan<EmbeddedVertex> VerticesSpan => ShapeMatchingShapeBlob.View(ref Vertices);
        /// <summary>Rest normals as a span over blob memory.</summary>
        public ReadOnlySpan<float3> RestNormalsSpan => ShapeMatchingShapeBlob.View(ref RestNormals);
        /// <summary>Edge nodes as a span over blob memory (empty unless quadratic).</summary>
        public ReadOnlySpan<int> EdgeNodesSpan => ShapeMatchingShapeBlob.View(ref EdgeNodes);
        /// <summary>Rest nodes as a span over blob memory.</summary>
        public ReadOnlySpan<float3> RestNodePositionsSpan => ShapeMatchingShapeBlob.View(ref RestNodePositions);
    }
}
