using Unity.Entities;
using Unity.Mathematics;

namespace Unity.Transforms
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Transforms.LocalTransform.html
    // (source: needle-mirror/com.unity.entities 1.4.2, Unity.Transforms/LocalTransform.cs)
    public struct LocalTransform : IComponentData
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Transforms.LocalTransform.Position.html
        public float3 Position;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Transforms.LocalTransform.Scale.html
        public float Scale;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Transforms.LocalTransform.Rotation.html
        public quaternion Rotation;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Transforms.LocalTransform.Identity.html
        public static readonly LocalTransform Identity;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Transforms.LocalTransform.FromPositionRotation.html
        public static LocalTransform FromPositionRotation(float3 position, quaternion rotation) => throw null;
    }
}
