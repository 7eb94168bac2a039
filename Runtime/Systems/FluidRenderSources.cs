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
    /// The fluids one world's renderer hand-off holds, by fluid entity: held by the world's
    /// <see cref="FluidSurfaceSourceSystem"/> (<see cref="Of"/>), filled by it (CPU fluids) and by
    /// <see cref="FluidComputeSystem"/> (GPU fluids) for fluids with a <see cref="FluidSurface"/>, read by the URP Fluid
    /// Renderer Feature through <see cref="CollectAll"/>. Entities of different worlds never share an entry, and a disposed
    /// world takes its sources with it. The buffers belong to the systems that set them.
    /// </summary>
    public sealed class FluidRenderSources
    {
        readonly Dictionary<Entity, FluidRenderSource> m_Sources = new Dictionary<Entity, FluidRenderSource>();

        /// <summary>Adds or replaces the fluid's source.</summary>
        public void Set(Entity fluid, FluidRenderSource source) => m_Sources[fluid] = source;

        public void Remove(Entity fluid) => m_Sources.Remove(fluid);

        /// <summary>The fluid's source, or null.</summary>
        public FluidRenderSource Get(Entity fluid) => m_Sources.TryGetValue(fluid, out FluidRenderSource s) ? s : null;

        /// <summary>Every registered source.</summary>
        public Dictionary<Entity, FluidRenderSource>.ValueCollection All => m_Sources.Values;

        public int Count => m_Sources.Count;

        /// <summary>The sources of <paramref name="world"/>, or null when it has no <see cref="FluidSurfaceSourceSystem"/>.</summary>
        public static FluidRenderSources Of(World world) =>
            world != null && world.IsCreated ? world.GetExistingSystemManaged<FluidSurfaceSourceSystem>()?.Sources : null;

        /// <summary>Replaces the content of <paramref name="into"/> with the sources of every live world (no allocation once it has grown).</summary>
        public static void CollectAll(List<FluidRenderSource> into)
        {
            into.Clear();
            World.NoAllocReadOnlyCollection<World> worlds = World.All;
            for (int w = 0; w < worlds.Count; w++)
            {
                FluidRenderSources sources = Of(worlds[w]);
                if (sources == null)
                    continue;
                foreach (FluidRenderSource source in sources.All)
                    into.Add(source);
            }
        }
    }
}
