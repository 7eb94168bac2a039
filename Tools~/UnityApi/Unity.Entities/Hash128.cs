using System;

namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.Hash128.html
    // (source: needle-mirror/com.unity.entities 1.4.2, Unity.Entities/Types/Hash128.cs:
    //  public struct Hash128 : IEquatable<Hash128>, IComparable<Hash128>). Declared for IBaker.AddBlobAsset's out parameter.
    public struct Hash128 : IEquatable<Hash128>, IComparable<Hash128>
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.Hash128.Equals.html
        public bool Equals(Hash128 obj) => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.Hash128.CompareTo.html
        public int CompareTo(Hash128 other) => throw null;
    }
}
