using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Rendering
{
    /// <summary>
    /// Whether a fluid of a world's <see cref="FluidRenderSources"/> is drawn for a camera: it has particles, a usable buffer of
    /// float4 holding them, a positive radius, and the world bounds of its spheres meet the camera's view frustum.
    /// Nothing here touches the GPU.
    /// </summary>
    public static class FluidRenderVisibility
    {
        /// <summary>Frustum planes per camera (left, right, bottom, top, near, far), as GeometryUtility fills them.</summary>
        public const int PlaneCount = 6;

        /// <summary>Whether <paramref name="source"/> is drawn for the camera whose <paramref name="frustum"/> planes are given.</summary>
        public static bool IsDrawn(FluidRenderSource source, Plane[] frustum)
        {
            if (source == null || source.Particles == null || !source.Particles.IsValid())
                return false;
            if (source.Particles.stride != FluidSurfaceLayout.Stride(FluidSurfaceBuffer.Particles))
                return false;
            return IsDrawn(source.Count, source.Particles.count, source.ParticleRadius, source.WorldBounds, frustum);
        }

        /// <summary>
        /// Whether <paramref name="count"/> particles of radius <paramref name="particleRadius"/> (m), read from a buffer
        /// of <paramref name="bufferLength"/> elements, whose spheres lie inside <paramref name="worldBounds"/>, are drawn
        /// for the camera whose <paramref name="frustum"/> planes are given.
        /// </summary>
        public static bool IsDrawn(int count, int bufferLength, float particleRadius, Bounds worldBounds, Plane[] frustum)
        {
            if (count <= 0 || count > bufferLength)
                return false;
            if (!(particleRadius > 0f) || !math.isfinite(particleRadius))
                return false;
            if (frustum == null || frustum.Length != PlaneCount)
                return false;
            return GeometryUtility.TestPlanesAABB(frustum, worldBounds);
        }

        /// <summary>
        /// Whether any of <paramref name="sources"/> (<see cref="FluidRenderSources.CollectAll"/>) is drawn for
        /// <paramref name="camera"/>; <paramref name="frustum"/> (length 6) receives the camera's planes, so nothing is allocated.
        /// </summary>
        public static bool AnyDrawn(Camera camera, Plane[] frustum, List<FluidRenderSource> sources)
        {
            if (camera == null || sources.Count == 0)
                return false;
            GeometryUtility.CalculateFrustumPlanes(camera, frustum);
            foreach (FluidRenderSource source in sources)
                if (IsDrawn(source, frustum))
                    return true;
            return false;
        }
    }
}
