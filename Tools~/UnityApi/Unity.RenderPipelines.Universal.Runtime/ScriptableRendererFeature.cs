using System;

// Source: Unity-Technologies/Graphics, Packages/com.unity.render-pipelines.universal/Runtime/ScriptableRendererFeature.cs.
namespace UnityEngine.Rendering.Universal
{
    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.ScriptableRendererFeature.html
    // (its private OnEnable and OnValidate call Create once a URP pipeline exists)
    public abstract class ScriptableRendererFeature : ScriptableObject, IDisposable
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.ScriptableRendererFeature.html#UnityEngine_Rendering_Universal_ScriptableRendererFeature_Create
        public abstract void Create();

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.ScriptableRendererFeature.html#UnityEngine_Rendering_Universal_ScriptableRendererFeature_AddRenderPasses_UnityEngine_Rendering_Universal_ScriptableRenderer_UnityEngine_Rendering_Universal_RenderingData__
        public abstract void AddRenderPasses(ScriptableRenderer renderer, ref RenderingData renderingData);

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.ScriptableRendererFeature.html#UnityEngine_Rendering_Universal_ScriptableRendererFeature_Dispose
        public void Dispose() => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.ScriptableRendererFeature.html#UnityEngine_Rendering_Universal_ScriptableRendererFeature_Dispose_System_Boolean_
        protected virtual void Dispose(bool disposing) => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.ScriptableRenderer.html
    public abstract partial class ScriptableRenderer
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.ScriptableRenderer.html#UnityEngine_Rendering_Universal_ScriptableRenderer_EnqueuePass_UnityEngine_Rendering_Universal_ScriptableRenderPass_
        public void EnqueuePass(ScriptableRenderPass pass) => throw null;
    }
}
