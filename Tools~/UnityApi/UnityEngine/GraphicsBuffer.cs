using System;
using Unity.Collections;

namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/GraphicsBuffer.html
    public sealed class GraphicsBuffer : IDisposable
    {
        // https://docs.unity3d.com/ScriptReference/GraphicsBuffer.Target.html
        [Flags]
        public enum Target
        {
            Vertex = 1, Index = 2, CopySource = 4, CopyDestination = 8, Structured = 16, Raw = 32, Append = 64, Counter = 128,
            IndirectArguments = 256, Constant = 512,
        }

        // https://docs.unity3d.com/ScriptReference/GraphicsBuffer-ctor.html
        public GraphicsBuffer(Target target, int count, int stride) => throw null;

        // https://docs.unity3d.com/ScriptReference/GraphicsBuffer-count.html
        public int count => throw null;

        // https://docs.unity3d.com/ScriptReference/GraphicsBuffer-stride.html
        public int stride => throw null;

        // https://docs.unity3d.com/ScriptReference/GraphicsBuffer.SetData.html
        public void SetData<T>(NativeArray<T> data, int nativeBufferStartIndex, int graphicsBufferStartIndex, int count) where T : struct => throw null;

        // https://docs.unity3d.com/ScriptReference/GraphicsBuffer.IsValid.html
        public bool IsValid() => throw null;

        // https://docs.unity3d.com/ScriptReference/GraphicsBuffer.Release.html
        public void Release() => throw null;

        // https://docs.unity3d.com/ScriptReference/GraphicsBuffer.Dispose.html
        public void Dispose() => throw null;
    }
}
