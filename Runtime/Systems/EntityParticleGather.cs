using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;
using Unity.Transforms;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Packs one fluid's particle entities into its buffers and writes the result back (Entities storage), through
    /// <see cref="FluidGatherIds"/>. The query arrays (particle data, transforms, entities) are in query order and are
    /// written back in place, so one copy per component type returns them to the entities.
    /// </summary>
    struct EntityParticleGather
    {
        /// <summary>Gather index → query index.</summary>
        NativeArray<int> m_QueryOf;
        NativeArray<int> m_RealIds;
        int m_Gathered;
        int m_RealNext;

        /// <summary>Copies the particles of <paramref name="fluid"/> (in query order) into slots [0, n) and starts the id tracking.</summary>
        public static EntityParticleGather Pack(Entity fluid, NativeArray<FluidParticle> data, FluidParticles p, ref FluidStatus status, Allocator allocator)
        {
            var g = new EntityParticleGather
            {
                m_QueryOf = new NativeArray<int>(data.Length, allocator),
                m_RealIds = new NativeArray<int>(data.Length, allocator),
            };
            int n = 0;
            int capacity = p.Capacity;
            for (int q = 0; q < data.Length && n < capacity; q++)
            {
                FluidParticle d = data[q];
                if (d.Fluid != fluid)
                    continue;
                p.Positions[n] = d.Position;
                p.Velocities[n] = d.Velocity;
                p.Ages[n] = d.Age;
                p.Lifetimes[n] = d.Lifetime;
                p.Attributes[n] = d.Attribute;
                p.Ids[n] = d.Id;
                g.m_QueryOf[n] = q;
                n++;
            }
            g.m_Gathered = n;
            g.m_RealNext = FluidGatherIds.Begin(p, g.m_RealIds.AsSpan(), n, ref status);
            return g;
        }

        /// <summary>
        /// Writes every surviving particle back into <paramref name="data"/> and <paramref name="transforms"/> at its query
        /// index, returns the entities of removed particles (to destroy in one batch) and the slots of new particles
        /// (to instantiate in one batch) in <paramref name="newSlots"/>.
        /// </summary>
        public NativeArray<Entity> Unpack(Entity fluid, FluidParticles p, ref FluidStatus status, NativeArray<FluidParticle> data,
            NativeArray<LocalTransform> transforms, NativeArray<Entity> entities, Allocator allocator, out NativeArray<int> newSlots, out int created)
        {
            var gatherOfSlot = new NativeArray<int>(math.max(1, status.Count), Allocator.Temp);
            var survived = new NativeArray<byte>(math.max(1, m_Gathered), Allocator.Temp);
            created = FluidGatherIds.End(p, m_RealIds.AsReadOnlySpan(), m_Gathered, m_RealNext, gatherOfSlot.AsSpan(), survived.AsSpan(), ref status);
            newSlots = new NativeArray<int>(math.max(1, created), allocator);
            int c = 0;
            for (int s = 0; s < status.Count; s++)
            {
                int g = gatherOfSlot[s];
                if (g < 0)
                {
                    newSlots[c++] = s;
                    continue;
                }
                int q = m_QueryOf[g];
                data[q] = ToComponent(p, s, fluid);
                LocalTransform t = transforms[q];
                t.Position = p.Positions[s];
                transforms[q] = t;
            }
            int dead = 0;
            for (int g = 0; g < m_Gathered; g++)
                dead += survived[g] == 0 ? 1 : 0;
            var removed = new NativeArray<Entity>(dead, allocator);
            dead = 0;
            for (int g = 0; g < m_Gathered; g++)
                if (survived[g] == 0)
                    removed[dead++] = entities[m_QueryOf[g]];
            gatherOfSlot.Dispose();
            survived.Dispose();
            return removed;
        }

        /// <summary>The particle in slot <paramref name="s"/> as a component.</summary>
        public static FluidParticle ToComponent(FluidParticles p, int s, Entity fluid) => new FluidParticle
        {
            Position = p.Positions[s],
            Velocity = p.Velocities[s],
            Age = p.Ages[s],
            Lifetime = p.Lifetimes[s],
            Attribute = p.Attributes[s],
            Id = p.Ids[s],
            Fluid = fluid,
        };

        public void Dispose()
        {
            m_QueryOf.Dispose();
            m_RealIds.Dispose();
        }
    }
}
