using Unity.Collections;

namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.DynamicBuffer-1.html
    // (source: needle-mirror/com.unity.entities 1.4.2, Unity.Entities/Iterators/DynamicBuffer.cs)
    public struct DynamicBuffer<T> : IQueryTypeParameter where T : unmanaged
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.DynamicBuffer-1.Length.html
        public int Length => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.DynamicBuffer-1.Item.html
        public T this[int index] { get => throw null; set => throw null; }
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.DynamicBuffer-1.ResizeUninitialized.html
        public void ResizeUninitialized(int length) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.DynamicBuffer-1.Add.html
        // (source: Iterators/DynamicBuffer.cs, 1.4.2: public int Add(T elem))
        public int Add(T elem) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.DynamicBuffer-1.Reinterpret.html
        public DynamicBuffer<U> Reinterpret<U>() where U : unmanaged => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.DynamicBuffer-1.AsNativeArray.html
        public NativeArray<T> AsNativeArray() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.DynamicBuffer-1.ToNativeArray.html
        // (source: Iterators/DynamicBuffer.cs, 1.4.2: public NativeArray<T> ToNativeArray(AllocatorManager.AllocatorHandle allocator))
        public NativeArray<T> ToNativeArray(AllocatorManager.AllocatorHandle allocator) => throw null;
    }
}
