using System;
using Unity.Collections;

// Source: needle-mirror/com.unity.entities 1.4.2, Unity.Entities/Blobs.cs and BlobBuilder.cs.
namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BlobAssetReference-1.html
    public unsafe struct BlobAssetReference<T> : IDisposable where T : unmanaged
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BlobAssetReference-1.IsCreated.html
        public bool IsCreated => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BlobAssetReference-1.Value.html
        public ref T Value => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BlobAssetReference-1.Dispose.html
        public void Dispose() => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BlobArray-1.html
    public unsafe struct BlobArray<T> where T : struct
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BlobArray-1.Length.html
        public int Length => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BlobArray-1.GetUnsafePtr.html
        public void* GetUnsafePtr() => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BlobBuilder.html
    public struct BlobBuilder : IDisposable
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BlobBuilder.-ctor.html
        public BlobBuilder(AllocatorManager.AllocatorHandle allocator, int chunkSize = 65536) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BlobBuilder.ConstructRoot.html
        public ref T ConstructRoot<T>() where T : struct => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BlobBuilder.Construct.html
        public BlobBuilderArray<T> Construct<T>(ref BlobArray<T> blobArray, params T[] data) where T : struct => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BlobBuilder.CreateBlobAssetReference.html
        public BlobAssetReference<T> CreateBlobAssetReference<T>(AllocatorManager.AllocatorHandle allocator) where T : unmanaged => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BlobBuilder.Dispose.html
        public void Dispose() => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BlobBuilderArray-1.html
    public ref struct BlobBuilderArray<T> where T : struct
    {
    }
}
