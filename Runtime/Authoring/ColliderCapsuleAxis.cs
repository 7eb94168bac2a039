namespace SoftBodyDynamics.Authoring
{
    /// <summary>The local axis a capsule collider runs along (as on Unity's CapsuleCollider).</summary>
    public enum ColliderCapsuleAxis : byte
    {
        X = 0,
        Y = 1,
        Z = 2,
    }
}
