namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Problems of a collider's shape, size or transform (<c>ParticleColliderValidation</c>, at authoring and bake time).
    /// The numbers are unique across domains and stable (they may be stored); new codes take new numbers. An
    /// <see cref="IssueCode"/> carries any domain's code.
    /// </summary>
    public enum ColliderIssueCode
    {
        /// <summary>The collider shape is not one of plane, sphere, box or capsule.</summary>
        ShapeInvalid = 100,
        /// <summary>A collider size, radius, height or centre is NaN or infinite.</summary>
        SizeNotFinite = 101,
        /// <summary>A collider box size or radius is zero or negative, or a capsule height is negative.</summary>
        SizeNotPositive = 102,
        /// <summary>The collider transform's position, rotation or scale is NaN or infinite.</summary>
        TransformNotFinite = 103,
        /// <summary>A scale factor the collider shape depends on is zero: it would have no volume.</summary>
        ScaleZero = 104,
        /// <summary>Warning: a sphere (or a capsule across its axis) is scaled non-uniformly; the largest factor is used.</summary>
        NonUniformScale = 105,
        /// <summary>Warning: a capsule's height is less than its diameter, so it is a sphere.</summary>
        CapsuleShorterThanDiameter = 106,
    }
}
