using System;

namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ComponentType.html
    // (source: Unity.Entities/Types/ComponentType.cs, 1.4: public struct ComponentType : IEquatable<ComponentType>)
    public struct ComponentType
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ComponentType.op_Implicit.html
        // (source: public static implicit operator ComponentType(Type type))
        public static implicit operator ComponentType(Type type) => throw null;
    }
}
