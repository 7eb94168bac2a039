// Source: needle-mirror/com.unity.entities 1.4.2, Unity.Entities/EntityManager.cs. The enableable-component methods
// constrain T to IEnableableComponent (plus unmanaged under UNITY_DISABLE_MANAGED_COMPONENTS), as declared there.
using Unity.Collections;

namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.html
    public struct EntityManager
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.CreateEntity.html
        public Entity CreateEntity() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.DestroyEntity.html
        // (source: Unity.Entities/EntityManager.cs, 1.4.2: public void DestroyEntity(Entity entity))
        public void DestroyEntity(Entity entity) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.DestroyEntity.html
        // (source: public void DestroyEntity(NativeArray<Entity> entities))
        public void DestroyEntity(NativeArray<Entity> entities) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.CreateEntityQuery.html
        // (source: public EntityQuery CreateEntityQuery(params ComponentType[] requiredComponents))
        public EntityQuery CreateEntityQuery(params ComponentType[] requiredComponents) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.Instantiate.html
        // (source: public void Instantiate(Entity srcEntity, NativeArray<Entity> outputEntities))
        public void Instantiate(Entity srcEntity, NativeArray<Entity> outputEntities) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.Exists.html
        public bool Exists(Entity entity) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.AddComponent.html
        public bool AddComponent<T>(Entity entity) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.AddComponentData.html
        public bool AddComponentData<T>(Entity entity, T componentData) where T : unmanaged, IComponentData => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.RemoveComponent.html
        public bool RemoveComponent<T>(Entity entity) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.HasComponent.html
        public bool HasComponent<T>(Entity entity) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.HasBuffer.html
        public bool HasBuffer<T>(Entity entity) where T : struct, IBufferElementData => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.GetComponentData.html
        public T GetComponentData<T>(Entity entity) where T : unmanaged, IComponentData => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.SetComponentData.html
        public void SetComponentData<T>(Entity entity, T componentData) where T : unmanaged, IComponentData => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.AddBuffer.html
        public DynamicBuffer<T> AddBuffer<T>(Entity entity) where T : unmanaged, IBufferElementData => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.GetBuffer.html
        public DynamicBuffer<T> GetBuffer<T>(Entity entity, bool isReadOnly = false) where T : unmanaged, IBufferElementData => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.IsComponentEnabled.html
        public bool IsComponentEnabled<T>(Entity entity) where T : IEnableableComponent => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.SetComponentEnabled.html
        public void SetComponentEnabled<T>(Entity entity, bool value) where T : IEnableableComponent => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EntityManager.CompleteAllTrackedJobs.html
        public void CompleteAllTrackedJobs() => throw null;
    }
}
