using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Entities;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics
{
    /// <summary>One fluid as the screen-space renderer reads it.</summary>
    public sealed class FluidRenderSource
    {
        /// <summary>float4 per slot: xyz world position (m), w attribute (temperature, K). Slots that are not finite are not drawn.</summary>
        public GraphicsBuffer Particles;
        /// <summary>Slots to read from <see cref="Particles"/>.</summary>
        public int Count;
        /// <summary>World bounds of the spheres (for culling against the camera).</summary>
        public Bounds WorldBounds;
        /// <summary>Sphere radius per particle (m).</summary>
        public float ParticleRadius;
        public FluidLook Look;

        /// <summary>Bounds of spheres of <paramref name="radius"/> whose centres lie in [<paramref name="lo"/>, <paramref name="hi"/>].</summary>
        public static Bounds SphereBounds(float3 lo, float3 hi, float radius)
        {
            float3 centre = 0.5f * (lo + hi), size = hi - lo + 2f * radius;
            return new Bounds(new Vector3(centre.x, centre.y, centre.z), new Vector3(size.x, size.y, size.z));
        }
    }

    /// <summary>
    /// The fluids the renderer draws this frame, by fluid entity: filled by <see cref="FluidSurfaceSourceSystem"/> (CPU
    /// fluids) and <see cref="FluidComputeSystem"/> (GPU fluids) for fluids with a <see cref="FluidSurface"/>, read by the
    /// URP Fluid Renderer Feature. The buffers belong to the systems that set them.
    /// </summary>
    public static class FluidRenderSources
    {
        static readonly Dictionary<Entity, FluidRenderSource> s_Sources = new Dictionary<Entity, FluidRenderSource>();

        /// <summary>Adds or replaces the fluid's source.</summary>
        public static void Set(Entity fluid, FluidRenderSource source) => s_Sources[fluid] = source;

        public static void Remove(Entity fluid) => s_Sources.Remove(fluid);

        /// <summary>The fluid's source, or null.</summary>
        public static FluidRenderSource Get(Entity fluid) => s_Sources.TryGetValue(fluid, out FluidRenderSource s) ? s : null;

        /// <summary>Every registered source.</summary>
        public static Dictionary<Entity, FluidRenderSource>.ValueCollection All => s_Sources.Values;

        public static int Count => s_Sources.Count;
    }
}
