using UnityEngine.Experimental.Rendering;

// Source: Oculus-VR/Unity-Graphics (com.unity.render-pipelines.core 17.0.x),
// Packages/com.unity.render-pipelines.core/Runtime/RenderGraph/RenderGraphResourceTexture.cs.
namespace UnityEngine.Rendering.RenderGraphModule
{
    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.TextureHandle.html
    public struct TextureHandle
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.TextureHandle.html#UnityEngine_Rendering_RenderGraphModule_TextureHandle_IsValid
        public bool IsValid() => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.TextureHandle.html#UnityEngine_Rendering_RenderGraphModule_TextureHandle_op_Implicit_UnityEngine_Rendering_RenderGraphModule_TextureHandle__UnityEngine_Rendering_RTHandle
        // (valid inside a pass's render function only)
        public static implicit operator RTHandle(TextureHandle texture) => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.TextureDesc.html
    public struct TextureDesc
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.TextureDesc.html#UnityEngine_Rendering_RenderGraphModule_TextureDesc_width
        public int width;
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.TextureDesc.html#UnityEngine_Rendering_RenderGraphModule_TextureDesc_height
        public int height;
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.TextureDesc.html#UnityEngine_Rendering_RenderGraphModule_TextureDesc_enableRandomWrite
        public bool enableRandomWrite;
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.TextureDesc.html#UnityEngine_Rendering_RenderGraphModule_TextureDesc_msaaSamples
        public MSAASamples msaaSamples;
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.TextureDesc.html#UnityEngine_Rendering_RenderGraphModule_TextureDesc_name
        public string name;
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.TextureDesc.html#UnityEngine_Rendering_RenderGraphModule_TextureDesc_clearBuffer
        public bool clearBuffer;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.TextureDesc.html#UnityEngine_Rendering_RenderGraphModule_TextureDesc_colorFormat
        // (a property over the 'format' field in the source read; a field of the same name in earlier 17.0 releases.
        // Package code only assigns it, which compiles against either.) // UNCONFIRMED for 17.0.0
        public GraphicsFormat colorFormat { get => throw null; set => throw null; }

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.TextureDesc.html#UnityEngine_Rendering_RenderGraphModule_TextureDesc__ctor_System_Int32_System_Int32_System_Boolean_System_Boolean_
        public TextureDesc(int width, int height, bool dynamicResolution = false, bool xrReady = false) => throw null;
    }
}
