namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.Entity.html
    // (source: needle-mirror/com.unity.entities 1.4.2, Unity.Entities/Types/Entity.cs)
    public struct Entity
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.Entity.Index.html
        public int Index;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.Entity.Version.html
        public int Version;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.Entity.Null.html
        public static Entity Null => throw null;

        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.Entity.op_Equality.html
        // (source: public static bool operator ==(Entity lhs, Entity rhs))
        public static bool operator ==(Entity lhs, Entity rhs) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.Entity.op_Inequality.html
        // (source: public static bool operator !=(Entity lhs, Entity rhs))
        public static bool operator !=(Entity lhs, Entity rhs) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.Entity.Equals.html
        public override bool Equals(object compare) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.Entity.GetHashCode.html
        public override int GetHashCode() => throw null;
    }
}
