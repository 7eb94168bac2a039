using Object = UnityEngine.Object;

namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.UnityObjectRef-1.html
    // (source: needle-mirror/com.unity.entities 1.4.2, Unity.Entities/Serialization/UnityObjectRef.cs)
    public struct UnityObjectRef<T> where T : Object
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.UnityObjectRef-1.op_Implicit.html
        public static implicit operator UnityObjectRef<T>(T instance) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.UnityObjectRef-1.op_Implicit.html
        public static implicit operator T(UnityObjectRef<T> unityObjectRef) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.UnityObjectRef-1.Value.html
        public T Value { get => throw null; set => throw null; }
    }
}
