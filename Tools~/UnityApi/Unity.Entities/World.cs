using System;
using Unity.Core;

// Source: needle-mirror/com.unity.entities 1.4.2, Unity.Entities/World.cs and WorldUnmanaged.cs.
namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.html
    public class World : IDisposable
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.-ctor.html
        public World(string name, WorldFlags flags = WorldFlags.Simulation) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.Name.html
        public string Name { get => throw null; }
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.Unmanaged.html
        public WorldUnmanaged Unmanaged => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.EntityManager.html
        public EntityManager EntityManager => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.SetTime.html
        public void SetTime(TimeData newTimeData) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.GetExistingSystemManaged.html
        public T GetExistingSystemManaged<T>() where T : ComponentSystemBase => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.GetOrCreateSystemManaged.html
        public T GetOrCreateSystemManaged<T>() where T : ComponentSystemBase => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.Dispose.html
        public void Dispose() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.DefaultGameObjectInjectionWorld.html
        // (source: World.cs, 1.4.2: public static World DefaultGameObjectInjectionWorld { get; set; })
        public static World DefaultGameObjectInjectionWorld { get => throw null; set => throw null; }
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.Time.html
        // (source: World.cs, 1.4.2: public ref TimeData Time => ref m_Unmanaged.Time;)
        public ref TimeData Time => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.IsCreated.html
        // (source: World.cs, 1.4.2: public bool IsCreated => m_Unmanaged.IsCreated;)
        public bool IsCreated => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.All.html
        // (source: World.cs, 1.4.2: public static NoAllocReadOnlyCollection<World> All { get; })
        public static NoAllocReadOnlyCollection<World> All => throw null;

        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.NoAllocReadOnlyCollection-1.html
        // (source: World.cs, 1.4.2: nested in World; IEnumerable<T> left out: casting it throws, the enumerator is a List's)
        public struct NoAllocReadOnlyCollection<T>
        {
            // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.NoAllocReadOnlyCollection-1.Count.html
            public int Count => throw null;
            // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.World.NoAllocReadOnlyCollection-1.Item.html
            public T this[int index] => throw null;
        }
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.WorldFlags.html (source: Unity.Entities/World.cs)
    [Flags]
    public enum WorldFlags : int
    {
        None = 0,
        Live = 1,
        Editor = 1 << 1 | Live,
        Game = 1 << 2 | Live,
        Simulation = 1 << 3 | Live,
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.WorldExtensions.html
    public static class WorldExtensions
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.WorldExtensions.CreateSystem.html
        public static SystemHandle CreateSystem<T>(this World self) where T : unmanaged, ISystem => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.WorldUnmanaged.html
    public struct WorldUnmanaged
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.WorldUnmanaged.ResolveSystemStateRef.html
        public ref SystemState ResolveSystemStateRef(SystemHandle id) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.WorldUnmanaged.GetExistingUnmanagedSystem.html
        // (source: WorldUnmanaged.cs, 1.4.2: public SystemHandle GetExistingUnmanagedSystem<T>() where T : unmanaged, ISystem)
        public SystemHandle GetExistingUnmanagedSystem<T>() where T : unmanaged, ISystem => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemHandle.html
    public struct SystemHandle
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemHandle.Update.html
        public void Update(WorldUnmanaged world) => throw null;
    }
}
