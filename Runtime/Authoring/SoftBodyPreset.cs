namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Named material settings for a soft body. Picking a preset sets the mode, frequency, damping ratio, β,
    /// plasticity, friction and restitution (see <see cref="SoftBodyPresets"/>); editing any of those by hand
    /// turns the preset to <see cref="Custom"/>. The values are stable (they are serialized).
    /// </summary>
    public enum SoftBodyPreset
    {
        /// <summary>Soft, wobbly, slightly bouncy; springs back to its shape.</summary>
        Jelly = 1,
        /// <summary>Firm, grippy and bouncy; springs back quickly.</summary>
        Rubber = 2,
        /// <summary>Dents and keeps the dent; no bounce.</summary>
        Clay = 3,
        /// <summary>Values set by hand.</summary>
        Custom = 0,
    }
}
