using UnityEngine;

namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IBaker.html
    // (source: Unity.Entities.Hybrid/Baking/Baker.cs, 1.4.2: public abstract unsafe class IBaker)
    public abstract class IBaker
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IBaker.GetComponent.html
        public T GetComponent<T>() where T : Component => throw null;

        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IBaker.GetEntity.html
        public Entity GetEntity(TransformUsageFlags flags) => throw null;

        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IBaker.GetEntity.html
        // (source: Unity.Entities.Hybrid/Baking/Baker.cs, 1.4: public Entity GetEntity(Component authoring, TransformUsageFlags flags))
        public Entity GetEntity(Component authoring, TransformUsageFlags flags) => throw null;

        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IBaker.DependsOn.html
        public T DependsOn<T>(T dependency) where T : Object => throw null;

        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IBaker.AddBlobAsset.html
        public void AddBlobAsset<T>(ref BlobAssetReference<T> blobAssetReference, out Hash128 objectHash) where T : unmanaged => throw null;

        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IBaker.AddComponent.html
        // source: public void AddComponent<T>(Entity entity) (no constraint)
        public void AddComponent<T>(Entity entity) => throw null;

        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IBaker.AddComponent.html
        public void AddComponent<T>(Entity entity, in T component) where T : unmanaged, IComponentData => throw null;

        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IBaker.AddBuffer.html
        public DynamicBuffer<T> AddBuffer<T>(Entity entity) where T : unmanaged, IBufferElementData => throw null;

        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IBaker.SetComponentEnabled.html
        public void SetComponentEnabled<T>(Entity entity, bool enabled) where T : struct, IEnableableComponent => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.Baker-1.html
    // (source: public abstract unsafe class Baker<TAuthoringType> : IBaker where TAuthoringType : Component)
    public abstract class Baker<TAuthoringType> : IBaker where TAuthoringType : Component
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.Baker-1.Bake.html
        public abstract void Bake(TAuthoringType authoring);
    }
}
