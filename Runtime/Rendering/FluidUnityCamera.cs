using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Rendering
{
    /// <summary>The fluid passes' camera and lighting, taken from Unity's camera and scene.</summary>
    public static class FluidUnityCamera
    {
        /// <summary>
        /// The camera of the fluid passes from Unity's world → camera matrix (right-handed view space looking down −z,
        /// the convention of <c>Camera.worldToCameraMatrix</c>): rotation = its upper 3 × 3, translation = its last
        /// column (m); <paramref name="width"/> × <paramref name="height"/> target pixels, vertical field of view
        /// (degrees) and near plane (m).
        /// </summary>
        public static FluidSurfaceCamera From(Matrix4x4 worldToCamera, int width, int height, float fieldOfView, float near)
        {
            Matrix4x4 m = worldToCamera;
            return new FluidSurfaceCamera
            {
                Rotation = new float3x3(
                    m[0, 0], m[0, 1], m[0, 2],
                    m[1, 0], m[1, 1], m[1, 2],
                    m[2, 0], m[2, 1], m[2, 2]),
                Translation = new float3(m[0, 3], m[1, 3], m[2, 3]),
                Width = width,
                Height = height,
                FieldOfView = fieldOfView,
                Near = near,
            };
        }

        /// <summary>
        /// The light and sky of the lit looks: the direction toward <paramref name="sun"/> (−its forward axis) and its
        /// colour (linear) times its intensity, or <see cref="FluidSurfaceLighting.Default"/>'s sun when there is none;
        /// the sky colours as picked (sRGB), converted to linear.
        /// </summary>
        public static FluidSurfaceLighting Lighting(Light sun, Color skyZenith, Color skyHorizon)
        {
            FluidSurfaceLighting lighting = FluidSurfaceLighting.Default;
            if (sun != null)
            {
                Vector3 forward = sun.transform.forward;
                float3 toLight = -new float3(forward.x, forward.y, forward.z);
                if (math.lengthsq(toLight) > 0f)
                    lighting.LightDirection = math.normalize(toLight);
                Color c = sun.color.linear;
                lighting.LightColour = new float3(c.r, c.g, c.b) * sun.intensity;
            }
            lighting.SkyZenith = Linear(skyZenith);
            lighting.SkyHorizon = Linear(skyHorizon);
            return lighting;
        }

        static float3 Linear(Color srgb)
        {
            Color c = srgb.linear;
            return new float3(c.r, c.g, c.b);
        }
    }
}
