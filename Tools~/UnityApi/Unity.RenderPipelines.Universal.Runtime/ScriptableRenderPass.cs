using System;
using UnityEngine.Rendering.RenderGraphModule;

// Source: Unity-Technologies/Graphics, Packages/com.unity.render-pipelines.universal/Runtime/Passes/ScriptableRenderPass.cs
// (enums and ConfigureInput); RecordRenderGraph as listed in the 17.x sources found by code search, where Execute is a
// virtual, obsolete Compatibility Mode method that only logs a warning when not overridden.
namespace UnityEngine.Rendering.Universal
{
    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.ScriptableRenderPassInput.html
    [Flags]
    public enum ScriptableRenderPassInput
    {
        None = 0,
        Depth = 1 << 0,
        Normal = 1 << 1,
        Color = 1 << 2,
        Motion = 1 << 3,
    }

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.RenderPassEvent.html
    // (only the event package code uses; value as in the source)
    public enum RenderPassEvent
    {
        BeforeRenderingTransparents = 450,
    }

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.ScriptableRenderPass.html
    public abstract partial class ScriptableRenderPass
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.ScriptableRenderPass.html#UnityEngine_Rendering_Universal_ScriptableRenderPass_renderPassEvent
        public RenderPassEvent renderPassEvent { get => throw null; set => throw null; }

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.ScriptableRenderPass.html#UnityEngine_Rendering_Universal_ScriptableRenderPass_ConfigureInput_UnityEngine_Rendering_Universal_ScriptableRenderPassInput_
        public void ConfigureInput(ScriptableRenderPassInput passInput) => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.ScriptableRenderPass.html#UnityEngine_Rendering_Universal_ScriptableRenderPass_RecordRenderGraph_UnityEngine_Rendering_RenderGraphModule_RenderGraph_UnityEngine_Rendering_ContextContainer_
        public virtual void RecordRenderGraph(RenderGraph renderGraph, ContextContainer frameData) => throw null;
    }
}
