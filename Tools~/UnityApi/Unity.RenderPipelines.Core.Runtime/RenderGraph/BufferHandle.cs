// Source: Unity-Technologies/Graphics, Packages/com.unity.render-pipelines.core/Runtime/RenderGraph/RenderGraphResourceBuffer.cs
// (same members in the 17.x releases found by code search).
namespace UnityEngine.Rendering.RenderGraphModule
{
    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.BufferHandle.html
    public struct BufferHandle
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.BufferHandle.html#UnityEngine_Rendering_RenderGraphModule_BufferHandle_IsValid
        public bool IsValid() => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RenderGraphModule.BufferHandle.html#UnityEngine_Rendering_RenderGraphModule_BufferHandle_op_Implicit_UnityEngine_Rendering_RenderGraphModule_BufferHandle__UnityEngine_GraphicsBuffer
        // (valid inside a pass's render function only)
        public static implicit operator GraphicsBuffer(BufferHandle buffer) => throw null;
    }
}
