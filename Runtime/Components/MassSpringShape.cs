using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// The shared, immutable shape of a mass-spring body (tier 1). <see cref="MassSpringSimulationSystem"/> runs only
    /// while some entity has it.
    /// </summary>
    public struct MassSpringShape : IComponentData
    {
        /// <summary>The blob asset; shared by every instance of a prefab.</summary>
        public BlobAssetReference<MassSpringShapeBlob> Blob;
    }
}
