using Unity.Entities;
using UnityEngine;
using UnityEngine.Rendering;

// Source: needle-mirror/com.unity.entities.graphics 1.4.21, Unity.Entities.Graphics/EntitiesGraphicsSystem.cs,
// StructuralChangePresentationSystemGroup.cs, UpdatePresentationSystemGroup.cs.
namespace Unity.Rendering
{
    // https://docs.unity3d.com/Packages/com.unity.entities.graphics@1.4/api/Unity.Rendering.EntitiesGraphicsSystem.html
    public partial class EntitiesGraphicsSystem : SystemBase
    {
        // https://docs.unity3d.com/Packages/com.unity.entities.graphics@1.4/api/Unity.Rendering.EntitiesGraphicsSystem.EntitiesGraphicsEnabled.html
        // (false when HYBRID_RENDERER_DISABLED is defined, else EntitiesGraphicsUtils.IsEntitiesGraphicsSupportedOnSystem():
        // a render pipeline asset, a graphics device that is not Null, compute shaders; OnCreate returns early and sets
        // Enabled = false when it is false, leaving no BatchRendererGroup)
        public static bool EntitiesGraphicsEnabled => throw null;
        // (source: EntitiesGraphicsSystem.cs, 1.4.21: protected override void OnUpdate())
        protected override void OnUpdate() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities.graphics@1.4/api/Unity.Rendering.EntitiesGraphicsSystem.RegisterMesh.html
        public BatchMeshID RegisterMesh(Mesh mesh) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities.graphics@1.4/api/Unity.Rendering.EntitiesGraphicsSystem.UnregisterMesh.html
        public void UnregisterMesh(BatchMeshID meshID) => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities.graphics@1.4/api/Unity.Rendering.StructuralChangePresentationSystemGroup.html
    public partial class StructuralChangePresentationSystemGroup : ComponentSystemGroup
    {
    }

    // https://docs.unity3d.com/Packages/com.unity.entities.graphics@1.4/api/Unity.Rendering.UpdatePresentationSystemGroup.html
    public partial class UpdatePresentationSystemGroup : ComponentSystemGroup
    {
    }
}
