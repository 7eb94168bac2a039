using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// The shared, immutable shape of a finite-element body (tier 1). <see cref="FemSimulationSystem"/> runs only while
    /// some entity has it.
    /// </summary>
    public struct FemShape : IComponentData
    {
        /// <summary>The blob asset; shared by every instance of a prefab.</summary>
        public BlobAssetReference<FemShapeBlob> Blob;
    }
}
