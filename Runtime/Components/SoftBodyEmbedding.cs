using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// The render binding of a mass-spring or finite-element body (tier 1): which tetrahedron nodes move each render
    /// vertex. <see cref="SoftBodyRenderMeshSystem"/> and <see cref="SoftBodyMeshWriteSystem"/> draw a body that has it
    /// with <see cref="SoftBodyRenderMesh"/> exactly like a shape-matching body.
    /// </summary>
    public struct SoftBodyEmbedding : IComponentData
    {
        /// <summary>The blob asset; shared by every instance of a prefab.</summary>
        public BlobAssetReference<SoftBodyEmbeddingBlob> Blob;
    }
}
