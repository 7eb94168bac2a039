using System;

// Source: Unity-Technologies/Graphics, Packages/com.unity.render-pipelines.core/Runtime/Common/ContextContainer.cs.
namespace UnityEngine.Rendering
{
    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.ContextContainer.html
    public class ContextContainer : IDisposable
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.ContextContainer.html#UnityEngine_Rendering_ContextContainer_Get__1
        // (throws InvalidOperationException when no item of type T was created this frame)
        public T Get<T>() where T : ContextItem, new() => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.ContextContainer.html#UnityEngine_Rendering_ContextContainer_Dispose
        public void Dispose() => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.ContextItem.html
    public abstract class ContextItem
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.ContextItem.html#UnityEngine_Rendering_ContextItem_Reset
        public abstract void Reset();
    }
}
