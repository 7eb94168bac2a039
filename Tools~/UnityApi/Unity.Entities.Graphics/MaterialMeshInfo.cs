using Unity.Entities;
using Unity.Mathematics;
using UnityEngine.Rendering;

// Source: needle-mirror/com.unity.entities.graphics 1.4.21, Unity.Entities.Graphics/RenderMeshArray.cs and
// RenderBoundsComponent.cs.
namespace Unity.Rendering
{
    // https://docs.unity3d.com/Packages/com.unity.entities.graphics@1.4/api/Unity.Rendering.MaterialMeshInfo.html
    public struct MaterialMeshInfo : IComponentData, IEnableableComponent
    {
        // https://docs.unity3d.com/Packages/com.unity.entities.graphics@1.4/api/Unity.Rendering.MaterialMeshInfo.MeshID.html
        public BatchMeshID MeshID { get => throw null; set => throw null; }
        // https://docs.unity3d.com/Packages/com.unity.entities.graphics@1.4/api/Unity.Rendering.MaterialMeshInfo.HasMaterialMeshIndexRange.html
        public bool HasMaterialMeshIndexRange => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities.graphics@1.4/api/Unity.Rendering.RenderBounds.html
    public struct RenderBounds : IComponentData
    {
        // https://docs.unity3d.com/Packages/com.unity.entities.graphics@1.4/api/Unity.Rendering.RenderBounds.Value.html
        public AABB Value;
    }
}
