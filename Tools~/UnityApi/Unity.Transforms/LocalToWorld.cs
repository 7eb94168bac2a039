using Unity.Entities;
using Unity.Mathematics;

namespace Unity.Transforms
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Transforms.LocalToWorld.html
    // (source: needle-mirror/com.unity.entities 1.4.2, Unity.Transforms/LocalToWorld.cs:
    //  public struct LocalToWorld : IComponentData { public float4x4 Value; ... }). The matrix field is left out (float4x4
    // is not in the stand-in); package code adds the component, lets the transform systems write it and reads its pose.
    public struct LocalToWorld : IComponentData
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Transforms.LocalToWorld.Position.html
        // (source: public float3 Position => new float3(Value.c3.x, Value.c3.y, Value.c3.z);)
        public float3 Position => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Transforms.LocalToWorld.Rotation.html
        // (source: public quaternion Rotation => new quaternion(math.orthonormalize(new float3x3(Value)));)
        public quaternion Rotation => throw null;
    }
}
