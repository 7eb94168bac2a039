using Unity.Collections;

namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityQuery.html
    // (source: needle-mirror/com.unity.entities 1.4.2, Unity.Entities/Iterators/EntityQuery.cs)
    public struct EntityQuery
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityQuery.IsEmpty.html
        public bool IsEmpty => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityQuery.ToEntityArray.html
        public NativeArray<Entity> ToEntityArray(AllocatorManager.AllocatorHandle allocator) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityQuery.ToComponentDataArray.html
        public NativeArray<T> ToComponentDataArray<T>(AllocatorManager.AllocatorHandle allocator) where T : unmanaged, IComponentData => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityQuery.CopyFromComponentDataArray.html
        // (source: public void CopyFromComponentDataArray<T>(NativeArray<T> componentDataArray) where T : unmanaged, IComponentData)
        public void CopyFromComponentDataArray<T>(NativeArray<T> componentDataArray) where T : unmanaged, IComponentData => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityQueryBuilder.html
    // (source: needle-mirror/com.unity.entities 1.4.2, Unity.Entities/Iterators/EntityQueryBuilder.cs:
    //  public unsafe ref struct EntityQueryBuilder)
    public ref struct EntityQueryBuilder
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityQueryBuilder.-ctor.html
        // (source: public EntityQueryBuilder(AllocatorManager.AllocatorHandle allocator))
        public EntityQueryBuilder(Unity.Collections.AllocatorManager.AllocatorHandle allocator) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityQueryBuilder.WithAll.html
        // (source: public EntityQueryBuilder WithAll<T1>())
        public EntityQueryBuilder WithAll<T1>() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityQueryBuilder.Build.html
        // (source: public EntityQuery Build(ref SystemState systemState))
        public EntityQuery Build(ref SystemState systemState) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityQueryBuilder.Dispose.html
        public void Dispose() => throw null;
    }
}
