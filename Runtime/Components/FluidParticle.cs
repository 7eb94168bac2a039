using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>Where a fluid keeps its particles.</summary>
    public enum FluidStorage : byte
    {
        /// <summary>Only in the fluid entity's buffers: cheapest, for 100k+ particles and the GPU backend.</summary>
        Packed = 0,
        /// <summary>
        /// One entity per particle, instantiated from a prefab, so gameplay code can query, tag and destroy particles; the
        /// system packs them into the fluid's buffers before the step and writes them back after it.
        /// </summary>
        Entities = 1,
    }

    /// <summary>
    /// A fluid particle as an entity (Entities storage). The fluid system writes it after every step; gameplay code may
    /// read it, tag the entity or destroy it (the particle leaves the fluid and counts as killed). Writing it from
    /// gameplay takes effect at the next step.
    /// </summary>
    public struct FluidParticle : IComponentData
    {
        /// <summary>Position (m, world).</summary>
        public float3 Position;
        /// <summary>Velocity (m/s).</summary>
        public float3 Velocity;
        /// <summary>Time since spawn (s).</summary>
        public float Age;
        /// <summary>Lifetime (s; 0 = forever; set it negative to have the next step remove the particle).</summary>
        public float Lifetime;
        /// <summary>Attribute (temperature in K or a colour parameter).</summary>
        public float Attribute;
        /// <summary>Stable id within its fluid.</summary>
        public int Id;
        /// <summary>The fluid entity it belongs to.</summary>
        public Entity Fluid;
    }

    /// <summary>Drawing size of a metaball particle (from <c>MetaballParticleAuthoring</c>).</summary>
    public struct MetaballParticle : IComponentData
    {
        /// <summary>Radius (m) of the sphere drawn for the particle (the prefab's scale follows it).</summary>
        public float Radius;
    }
}
