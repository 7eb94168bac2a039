using Unity.Entities;

namespace Unity.Physics
{
    // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.PhysicsCollider.html
    // (source: ECS/Base/Components/PhysicsComponents.cs, 1.4.6: public struct PhysicsCollider : IComponentData)
    public struct PhysicsCollider : IComponentData
    {
        // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.PhysicsCollider.Value.html
        public BlobAssetReference<Collider> Value;
        // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.PhysicsCollider.IsValid.html
        public bool IsValid => throw null;
        // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.PhysicsCollider.ColliderPtr.html
        // (source: public unsafe Collider* ColliderPtr => (Collider*)Value.GetUnsafePtr();)
        public unsafe Collider* ColliderPtr => throw null;
    }
}
