using SoftBodyDynamics.Solvers;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Deformed render vertex (mesh-space position and normal), one per render-mesh vertex: the vertex
    /// stream uploaded to the body's own mesh. Runtime only, added with <see cref="SoftBodyMeshInstance"/>.
    /// </summary>
    [InternalBufferCapacity(0)]
    public struct SoftBodyMeshVertex : IBufferElementData
    {
        /// <summary>Position (m) and unit normal in mesh space.</summary>
        public DeformedVertex Value;
    }
}
