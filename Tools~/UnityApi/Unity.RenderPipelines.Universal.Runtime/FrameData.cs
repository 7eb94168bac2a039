using UnityEngine.Rendering.RenderGraphModule;

// Source: Unity-Technologies/Graphics, Packages/com.unity.render-pipelines.universal/Runtime/FrameData/UniversalResourceData.cs
// and UniversalCameraData.cs.
namespace UnityEngine.Rendering.Universal
{
    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.UniversalResourceDataBase.html
    public abstract class UniversalResourceDataBase : ContextItem
    {
    }

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.UniversalResourceData.html
    // (handles are to be read while recording the render graph, not inside render functions)
    public class UniversalResourceData : UniversalResourceDataBase
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.UniversalResourceData.html#UnityEngine_Rendering_Universal_UniversalResourceData_activeColorTexture
        public TextureHandle activeColorTexture => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.UniversalResourceData.html#UnityEngine_Rendering_Universal_UniversalResourceData_cameraOpaqueTexture
        // (valid only when the CopyColor pass runs: Opaque Texture on in the URP asset, or a pass requesting Color input)
        public TextureHandle cameraOpaqueTexture { get => throw null; set => throw null; }

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.UniversalResourceData.html#UnityEngine_Rendering_Universal_UniversalResourceData_cameraDepthTexture
        // (valid only when the CopyDepth or depth prepass runs)
        public TextureHandle cameraDepthTexture { get => throw null; set => throw null; }

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.UniversalResourceData.html#UnityEngine_Rendering_Universal_UniversalResourceData_Reset
        public override void Reset() => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.UniversalCameraData.html
    public class UniversalCameraData : ContextItem
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.UniversalCameraData.html#UnityEngine_Rendering_Universal_UniversalCameraData_camera
        public Camera camera;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.UniversalCameraData.html#UnityEngine_Rendering_Universal_UniversalCameraData_cameraTargetDescriptor
        // (the size of the intermediate camera targets, render scale applied)
        public RenderTextureDescriptor cameraTargetDescriptor;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.UniversalCameraData.html#UnityEngine_Rendering_Universal_UniversalCameraData_cameraType
        public CameraType cameraType;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.UniversalCameraData.html#UnityEngine_Rendering_Universal_UniversalCameraData_Reset
        public override void Reset() => throw null;
    }
}
