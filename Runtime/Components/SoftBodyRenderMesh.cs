using Unity.Entities;
using UnityEngine;

namespace SoftBodyDynamics
{
    /// <summary>
    /// The render mesh a soft body deforms. Each body draws its own copy of it (made at run time by
    /// <see cref="SoftBodyRenderMeshSystem"/>), so this stays the shared source asset. The mesh must have
    /// Read/Write enabled, one vertex per entry of <see cref="ShapeMatchingShapeBlob.VertexToParticle"/>, and the
    /// entity must be rendered by Entities Graphics with a single material (a <c>MaterialMeshInfo</c>).
    /// </summary>
    public struct SoftBodyRenderMesh : IComponentData
    {
        /// <summary>The source mesh (asset).</summary>
        public UnityObjectRef<Mesh> Mesh;
    }
}
