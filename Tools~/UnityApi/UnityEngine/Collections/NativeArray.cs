using System;
using Unity.Jobs;

// Checked: UnityCsReference 6000.0.22f1 Runtime/Export/NativeArray/NativeArray.cs (Unity.Collections namespace,
// UnityEngine.CoreModule assembly).
namespace Unity.Collections
{
    // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArrayOptions.html
    public enum NativeArrayOptions
    {
        UninitializedMemory = 0,
        ClearMemory = 1,
    }

    // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1.html
    public struct NativeArray<T> : IDisposable where T : struct
    {
        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1-ctor.html
        public NativeArray(int length, Allocator allocator, NativeArrayOptions options = NativeArrayOptions.ClearMemory) => throw null;

        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1-ctor.html (copies the array)
        public NativeArray(T[] array, Allocator allocator) => throw null;

        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1-IsCreated.html
        public bool IsCreated => throw null;

        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1-Length.html
        public int Length => throw null;

        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1.Index_operator.html
        public T this[int index] { get => throw null; set => throw null; }


        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1.Dispose.html
        public void Dispose() => throw null;

        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1.Dispose.html
        public JobHandle Dispose(JobHandle inputDeps) => throw null;

        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1.AsSpan.html
        public readonly Span<T> AsSpan() => throw null;

        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1.AsReadOnlySpan.html
        public readonly ReadOnlySpan<T> AsReadOnlySpan() => throw null;

        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1.GetSubArray.html
        public NativeArray<T> GetSubArray(int start, int length) => throw null;

        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1.Reinterpret.html
        public NativeArray<U> Reinterpret<U>() where U : struct => throw null;

        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1.CopyFrom.html
        public void CopyFrom(NativeArray<T> array) => throw null;

        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1.CopyFrom.html
        public void CopyFrom(T[] array) => throw null;

        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1.Copy.html
        public static void Copy(NativeArray<T> src, int srcIndex, NativeArray<T> dst, int dstIndex, int length) => throw null;

        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1.GetEnumerator.html
        public Enumerator GetEnumerator() => throw null;

        // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1.Enumerator.html
        public struct Enumerator
        {
            // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1.Enumerator-Current.html
            public T Current => throw null;
            // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeArray_1.Enumerator.MoveNext.html
            public bool MoveNext() => throw null;
        }
    }
}
