using Unity.Entities;

namespace Unity.Transforms
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Transforms.LocalToWorld.html
    // (source: needle-mirror/com.unity.entities 1.4.2, Unity.Transforms/LocalToWorld.cs:
    //  public struct LocalToWorld : IComponentData { public float4x4 Value; ... }). Only the type is declared:
    // package code adds the component and lets the transform systems write it (float4x4 is not in the stand-in).
    public struct LocalToWorld : IComponentData
    {
    }
}
