namespace SoftBodyDynamics.Rendering
{
    /// <summary>The quality tier whose defaults <see cref="FluidRendererSettings"/> starts from.</summary>
    public enum FluidRendererTier
    {
        /// <summary>Full-resolution depth, filter up to 16 px, refraction up to 48 px (<c>FluidSurfaceSettings.Desktop</c>).</summary>
        Desktop = 0,
        /// <summary>Half-resolution depth and composite, filter up to 8 px, refraction up to 32 px (<c>FluidSurfaceSettings.Mobile</c>).</summary>
        Mobile = 1,
    }

    /// <summary>Resolution of the fluid's depth, smoothing and normals, or of its composite; the value is the divisor of the screen size.</summary>
    public enum FluidDepthResolution
    {
        Full = 1,
        Half = 2,
    }
}
