using System;
using Unity.Collections;

namespace UnityEngine.Rendering
{
    // https://docs.unity3d.com/ScriptReference/Rendering.AsyncGPUReadback.html
    public static class AsyncGPUReadback
    {
        // https://docs.unity3d.com/ScriptReference/Rendering.AsyncGPUReadback.Request.html
        public static AsyncGPUReadbackRequest Request(GraphicsBuffer src, Action<AsyncGPUReadbackRequest> callback = null) => throw null;

        // https://docs.unity3d.com/ScriptReference/Rendering.AsyncGPUReadback.WaitAllRequests.html
        public static void WaitAllRequests() => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/Rendering.AsyncGPUReadbackRequest.html
    public struct AsyncGPUReadbackRequest
    {
        // https://docs.unity3d.com/ScriptReference/Rendering.AsyncGPUReadbackRequest-done.html
        public bool done => throw null;

        // https://docs.unity3d.com/ScriptReference/Rendering.AsyncGPUReadbackRequest-hasError.html
        public bool hasError => throw null;

        // https://docs.unity3d.com/ScriptReference/Rendering.AsyncGPUReadbackRequest.GetData.html
        public NativeArray<T> GetData<T>(int layer = 0) where T : struct => throw null;

        // https://docs.unity3d.com/ScriptReference/Rendering.AsyncGPUReadbackRequest.WaitForCompletion.html
        public void WaitForCompletion() => throw null;
    }
}
