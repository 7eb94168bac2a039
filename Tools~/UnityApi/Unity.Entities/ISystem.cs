using Unity.Collections;
using Unity.Core;
using Unity.Jobs;

// Source: needle-mirror/com.unity.entities 1.4.2, Unity.Entities/ISystem.cs and SystemState.cs.
namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ISystem.html
    public interface ISystem
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ISystem.OnCreate.html
        void OnCreate(ref SystemState state) { }
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ISystem.OnDestroy.html
        void OnDestroy(ref SystemState state) { }
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ISystem.OnUpdate.html
        void OnUpdate(ref SystemState state) { }
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemState.html
    // Declared as in the source (Unity.Entities/SystemState.cs, 1.4.2): `public unsafe ref struct SystemState`.
    // A ref struct cannot be boxed, captured by a lambda or stored in a class field, as in Unity.
    public unsafe ref struct SystemState
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemState.EntityManager.html
        public EntityManager EntityManager => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemState.World.html
        public World World => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemState.Dependency.html
        public JobHandle Dependency { get => throw null; set => throw null; }
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemState.CompleteDependency.html
        public void CompleteDependency() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemState.Enabled.html
        public bool Enabled { get => throw null; set => throw null; }
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemState.LastSystemVersion.html
        // (source: SystemState.cs, 1.4.2: public uint LastSystemVersion => m_LastSystemVersion;)
        public uint LastSystemVersion => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemState.ShouldRunSystem.html
        public bool ShouldRunSystem() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemState.RequireForUpdate.html
        public void RequireForUpdate<T>() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemState.RequireForUpdate.html
        public void RequireForUpdate(EntityQuery query) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemState.RequireAnyForUpdate.html
        public void RequireAnyForUpdate(params EntityQuery[] queries) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemState.RequireAnyForUpdate.html
        // (source: SystemState.cs, 1.4.2: [GenerateTestsForBurstCompatibility] public void RequireAnyForUpdate(NativeArray<EntityQuery> queries))
        public void RequireAnyForUpdate(NativeArray<EntityQuery> queries) => throw null;
    }
}

namespace Unity.Core
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Core.TimeData.html
    // (source: needle-mirror/com.unity.entities 1.4.2, Unity.Core/TimeData.cs, compiled into Unity.Entities by an asmref)
    public readonly struct TimeData
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Core.TimeData.ElapsedTime.html
        public readonly double ElapsedTime;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Core.TimeData.DeltaTime.html
        public readonly float DeltaTime;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Core.TimeData.-ctor.html
        public TimeData(double elapsedTime, float deltaTime) => throw null;
    }
}
