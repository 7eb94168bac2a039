using System;

namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.TransformUsageFlags.html
    // (source: Unity.Entities.Hybrid/Baking/TransformUsageFlags.cs, 1.4.2; values as in the source)
    [Flags]
    public enum TransformUsageFlags : int
    {
        None = 0,
        Renderable = 1,
        Dynamic = 1 << 1,
        WorldSpace = 1 << 2,
        NonUniformScale = 1 << 3,
        ManualOverride = 1 << 4,
    }
}
