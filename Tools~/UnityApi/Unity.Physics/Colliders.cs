using Unity.Mathematics;

namespace Unity.Physics
{
    // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.ColliderType.html
    // (source: Collision/Colliders/Collider.cs, 1.4.6: public enum ColliderType : byte)
    public enum ColliderType : byte
    {
        Convex = 0,
        Sphere = 1,
        Capsule = 2,
        Triangle = 3,
        Quad = 4,
        Box = 5,
        Cylinder = 6,
        Mesh = 7,
        Compound = 8,
        Terrain = 9,
    }

    // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.Collider.html
    // (source: Collision/Colliders/Collider.cs, 1.4.6: public struct Collider : ICompositeCollider; the interfaces and the
    // private header are left out)
    public struct Collider
    {
        // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.Collider.Type.html
        public ColliderType Type => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.SphereGeometry.html
    // (source: Collision/Colliders/SphereCollider.cs, 1.4.6; IEquatable left out)
    public struct SphereGeometry
    {
        public float3 Center { get => throw null; set => throw null; }
        public float Radius { get => throw null; set => throw null; }
    }

    // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.SphereCollider.html
    // (source: Collision/Colliders/SphereCollider.cs, 1.4.6: public struct SphereCollider : IConvexCollider)
    public struct SphereCollider
    {
        // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.SphereCollider.Geometry.html
        public SphereGeometry Geometry { get => throw null; set => throw null; }
    }

    // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.BoxGeometry.html
    // (source: Collision/Colliders/BoxCollider.cs, 1.4.6; IEquatable left out)
    public struct BoxGeometry
    {
        public float3 Center { get => throw null; set => throw null; }
        public quaternion Orientation { get => throw null; set => throw null; }
        public float3 Size { get => throw null; set => throw null; }
        public float BevelRadius { get => throw null; set => throw null; }
    }

    // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.BoxCollider.html
    // (source: Collision/Colliders/BoxCollider.cs, 1.4.6: public struct BoxCollider : IConvexCollider)
    public struct BoxCollider
    {
        // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.BoxCollider.Geometry.html
        public BoxGeometry Geometry { get => throw null; set => throw null; }
    }

    // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.CapsuleGeometry.html
    // (source: Collision/Colliders/CapsuleCollider.cs, 1.4.6; IEquatable left out)
    public struct CapsuleGeometry
    {
        public float3 Vertex0 { get => throw null; set => throw null; }
        public float3 Vertex1 { get => throw null; set => throw null; }
        public float Radius { get => throw null; set => throw null; }
    }

    // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.CapsuleCollider.html
    // (source: Collision/Colliders/CapsuleCollider.cs, 1.4.6: public struct CapsuleCollider : IConvexCollider)
    public struct CapsuleCollider
    {
        // https://docs.unity3d.com/Packages/com.unity.physics@1.4/api/Unity.Physics.CapsuleCollider.Geometry.html
        public CapsuleGeometry Geometry { get => throw null; set => throw null; }
    }
}
