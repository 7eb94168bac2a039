using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>The shared, immutable shape of a soft body (tier 1: rest shape, clusters, render binding).</summary>
    public struct ShapeMatchingShape : IComponentData
    {
        /// <summary>The blob asset; shared by every instance of a prefab.</summary>
        public BlobAssetReference<ShapeMatchingShapeBlob> Blob;
    }
}
