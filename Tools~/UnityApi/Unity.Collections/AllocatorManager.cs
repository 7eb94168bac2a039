// Source: needle-mirror/com.unity.collections 2.6.6, Unity.Collections/AllocatorManager.cs.
namespace Unity.Collections
{
    // https://docs.unity3d.com/Packages/com.unity.collections@2.6/api/Unity.Collections.AllocatorManager.html
    public static class AllocatorManager
    {
        // https://docs.unity3d.com/Packages/com.unity.collections@2.6/api/Unity.Collections.AllocatorManager.AllocatorHandle.html
        public struct AllocatorHandle
        {
            // https://docs.unity3d.com/Packages/com.unity.collections@2.6/api/Unity.Collections.AllocatorManager.AllocatorHandle.html#Unity_Collections_AllocatorManager_AllocatorHandle_op_Implicit_Unity_Collections_Allocator__Unity_Collections_AllocatorManager_AllocatorHandle
            public static implicit operator AllocatorHandle(Allocator a) => throw null;
        }
    }
}
