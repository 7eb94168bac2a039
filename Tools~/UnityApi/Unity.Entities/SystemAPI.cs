using Unity.Core;

// Source: needle-mirror/com.unity.entities 1.4.2, Unity.Entities/SystemAPI.cs and SystemAPIQueryBuilder.cs.
// These members are replaced by the Entities source generators at compile time in Unity.
namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemAPI.html
    public static class SystemAPI
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemAPI.Time.html
        public static ref readonly TimeData Time => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemAPI.QueryBuilder.html
        public static SystemAPIQueryBuilder QueryBuilder() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemAPI.GetBufferLookup.html
        public static BufferLookup<T> GetBufferLookup<T>(bool isReadOnly = false) where T : unmanaged, IBufferElementData => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemAPI.TryGetSingleton.html
        public static bool TryGetSingleton<T>(out T value) where T : unmanaged, IComponentData => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemAPI.GetSingletonBuffer.html
        // (source: SystemAPI.cs, 1.4.2: public static DynamicBuffer<T> GetSingletonBuffer<T>(bool isReadOnly = false) where T : unmanaged, IBufferElementData)
        public static DynamicBuffer<T> GetSingletonBuffer<T>(bool isReadOnly = false) where T : unmanaged, IBufferElementData => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemAPIQueryBuilder.html
    public struct SystemAPIQueryBuilder
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemAPIQueryBuilder.WithAll.html
        public SystemAPIQueryBuilder WithAll<T1>() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemAPIQueryBuilder.WithAll.html
        public SystemAPIQueryBuilder WithAll<T1, T2>() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemAPIQueryBuilder.WithAll.html
        public SystemAPIQueryBuilder WithAll<T1, T2, T3>() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemAPIQueryBuilder.WithNone.html
        public SystemAPIQueryBuilder WithNone<T1>() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemAPIQueryBuilder.WithPresent.html
        public SystemAPIQueryBuilder WithPresent<T1>() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemAPIQueryBuilder.Build.html
        public EntityQuery Build() => throw null;
    }
}
