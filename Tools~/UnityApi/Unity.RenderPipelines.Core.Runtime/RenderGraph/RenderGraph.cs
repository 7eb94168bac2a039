using System;
using System.Runtime.CompilerServices;

// Source: Oculus-VR/Unity-Graphics (com.unity.render-pipelines.core 17.0.x),
// Packages/com.unity.render-pipelines.core/Runtime/RenderGraph/RenderGraph.cs.
namespace UnityEngine.Rendering.RenderGraphModule
{
    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.AccessFlags.html
    [Flags]
    public enum AccessFlags
    {
        None = 0,
        Read = 1 << 0,
        Write = 1 << 1,
        Discard = 1 << 2,
        WriteAll = Write | Discard,
        ReadWrite = Read | Write,
    }

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.BaseRenderFunc-2.html
    public delegate void BaseRenderFunc<PassData, ContextType>(PassData data, ContextType renderGraphContext) where PassData : class, new();

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.RasterGraphContext.html
    public struct RasterGraphContext
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.RasterGraphContext.html#UnityEngine_Rendering_RenderGraphModule_RasterGraphContext_cmd
        public RasterCommandBuffer cmd;
    }

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.ComputeGraphContext.html
    public class ComputeGraphContext
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.ComputeGraphContext.html#UnityEngine_Rendering_RenderGraphModule_ComputeGraphContext_cmd
        public ComputeCommandBuffer cmd;
    }

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.RenderGraph.html
    public partial class RenderGraph
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.RenderGraph.html#UnityEngine_Rendering_RenderGraphModule_RenderGraph__ctor_System_String_
        public RenderGraph(string name = "RenderGraph") => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.RenderGraph.html#UnityEngine_Rendering_RenderGraphModule_RenderGraph_CreateTexture_UnityEngine_Rendering_RenderGraphModule_TextureDesc__
        public TextureHandle CreateTexture(in TextureDesc desc) => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.RenderGraph.html#UnityEngine_Rendering_RenderGraphModule_RenderGraph_GetTextureDesc_UnityEngine_Rendering_RenderGraphModule_TextureHandle_
        public TextureDesc GetTextureDesc(TextureHandle texture) => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.RenderGraph.html#UnityEngine_Rendering_RenderGraphModule_RenderGraph_ImportBuffer_UnityEngine_GraphicsBuffer_System_Boolean_
        public BufferHandle ImportBuffer(GraphicsBuffer graphicsBuffer, bool forceRelease = false) => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.RenderGraph.html#UnityEngine_Rendering_RenderGraphModule_RenderGraph_AddRasterRenderPass__1_System_String___0__System_String_System_Int32_
        public IRasterRenderGraphBuilder AddRasterRenderPass<PassData>(string passName, out PassData passData,
            [CallerFilePath] string file = "", [CallerLineNumber] int line = 0) where PassData : class, new() => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.RenderGraph.html#UnityEngine_Rendering_RenderGraphModule_RenderGraph_AddComputePass__1_System_String___0__System_String_System_Int32_
        public IComputeRenderGraphBuilder AddComputePass<PassData>(string passName, out PassData passData,
            [CallerFilePath] string file = "", [CallerLineNumber] int line = 0) where PassData : class, new() => throw null;
    }
}
