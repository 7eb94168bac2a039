namespace Unity.Mathematics
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Mathematics.AABB.html
    // (source: needle-mirror/com.unity.entities 1.4.2, Unity.Mathematics.Extensions/AABB.cs)
    public struct AABB
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Mathematics.AABB.Center.html
        public float3 Center;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Mathematics.AABB.Extents.html
        public float3 Extents;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Mathematics.AABB.Size.html
        public float3 Size => throw null;
    }
}
