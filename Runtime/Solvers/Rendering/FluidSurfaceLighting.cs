using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>The light and sky the lit looks reflect (world space, linear RGB).</summary>
    public struct FluidSurfaceLighting
    {
        /// <summary>Unit vector towards the main light.</summary>
        public float3 LightDirection;
        public float3 LightColour;
        /// <summary>Sky colour straight up and at the horizon (what the Fresnel reflection shows).</summary>
        public float3 SkyZenith, SkyHorizon;
        /// <summary>World up (unit).</summary>
        public float3 Up;

        /// <summary>A sun high in a pale blue sky.</summary>
        public static FluidSurfaceLighting Default => new FluidSurfaceLighting
        {
            LightDirection = math.normalize(new float3(0.35f, 0.8f, 0.45f)),
            LightColour = new float3(1f, 0.96f, 0.9f),
            SkyZenith = new float3(0.25f, 0.45f, 0.85f),
            SkyHorizon = new float3(0.75f, 0.82f, 0.9f),
            Up = new float3(0f, 1f, 0f),
        };
    }
}
