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
    }
}
