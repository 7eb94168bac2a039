namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Problems of a fluid surface's rendering settings (the fluid surface baker).
    /// The numbers are unique across domains and stable (they may be stored); new codes take new numbers. An
    /// <see cref="IssueCode"/> carries any domain's code.
    /// </summary>
    public enum FluidSurfaceIssueCode
    {
        /// <summary>The fluid surface has no fluid to draw, or its sphere radius (in particle spacings) is not positive and finite.</summary>
        SettingsInvalid = 237,
        /// <summary>Warning: a value of the fluid surface's custom look was out of range and replaced.</summary>
        LookReplaced = 238,
        /// <summary>Warning: the sphere radius leaves gaps between neighbouring particles (below 0.5 spacing) or blurs the fluid (above 2).</summary>
        RadiusUnusual = 239,
    }
}
