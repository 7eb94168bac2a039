using System;

// Source: Oculus-VR/Unity-Graphics at com.unity.render-pipelines.core 17.0.4 (commit 232e88e2),
// Packages/com.unity.render-pipelines.core/Runtime/RenderGraph/IRenderGraphBuilder.cs.
namespace UnityEngine.Rendering.RenderGraphModule
{
    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.IBaseRenderGraphBuilder.html
    public interface IBaseRenderGraphBuilder : IDisposable
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.IBaseRenderGraphBuilder.html#UnityEngine_Rendering_RenderGraphModule_IBaseRenderGraphBuilder_UseTexture_UnityEngine_Rendering_RenderGraphModule_TextureHandle__UnityEngine_Rendering_RenderGraphModule_AccessFlags_
        void UseTexture(in TextureHandle input, AccessFlags flags = AccessFlags.Read);

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.IBaseRenderGraphBuilder.html#UnityEngine_Rendering_RenderGraphModule_IBaseRenderGraphBuilder_UseBuffer_UnityEngine_Rendering_RenderGraphModule_BufferHandle__UnityEngine_Rendering_RenderGraphModule_AccessFlags_
        BufferHandle UseBuffer(in BufferHandle input, AccessFlags flags = AccessFlags.Read);

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.IBaseRenderGraphBuilder.html#UnityEngine_Rendering_RenderGraphModule_IBaseRenderGraphBuilder_AllowPassCulling_System_Boolean_
        void AllowPassCulling(bool value);
    }

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.IComputeRenderGraphBuilder.html
    public interface IComputeRenderGraphBuilder : IBaseRenderGraphBuilder
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.IComputeRenderGraphBuilder.html#UnityEngine_Rendering_RenderGraphModule_IComputeRenderGraphBuilder_SetRenderFunc__1_UnityEngine_Rendering_RenderGraphModule_BaseRenderFunc___0_UnityEngine_Rendering_RenderGraphModule_ComputeGraphContext__
        void SetRenderFunc<PassData>(BaseRenderFunc<PassData, ComputeGraphContext> renderFunc) where PassData : class, new();
    }

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.IRasterRenderGraphBuilder.html
    public interface IRasterRenderGraphBuilder : IBaseRenderGraphBuilder
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.IRasterRenderGraphBuilder.html#UnityEngine_Rendering_RenderGraphModule_IRasterRenderGraphBuilder_SetRenderAttachment_UnityEngine_Rendering_RenderGraphModule_TextureHandle_System_Int32_UnityEngine_Rendering_RenderGraphModule_AccessFlags_
        // (a default interface method in the source, forwarding to the overload with mipLevel 0 and depthSlice -1)
        void SetRenderAttachment(TextureHandle tex, int index, AccessFlags flags = AccessFlags.Write) => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.IRasterRenderGraphBuilder.html#UnityEngine_Rendering_RenderGraphModule_IRasterRenderGraphBuilder_SetRenderFunc__1_UnityEngine_Rendering_RenderGraphModule_BaseRenderFunc___0_UnityEngine_Rendering_RenderGraphModule_RasterGraphContext__
        void SetRenderFunc<PassData>(BaseRenderFunc<PassData, RasterGraphContext> renderFunc) where PassData : class, new();
    }
}
