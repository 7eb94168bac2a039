using SoftBodyDynamics.Solvers;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Editor
{
    /// <summary>Fluid entities as the baker makes them, for the system tests.</summary>
    static class FluidTestEntities
    {
        /// <summary>A fluid entity with <paramref name="settings"/>, a fresh <see cref="FluidRuntime"/> and the empty particle buffers.</summary>
        public static Entity Create(EntityManager m, in FluidSettings settings)
        {
            Entity entity = m.CreateEntity();
            FluidArchetype.AddComponents(m, entity, settings);
            return entity;
        }

        /// <summary>Water in a 0.4 m box above the origin (the fluid of the system tests).</summary>
        public static FluidParameters BoxParameters()
        {
            FluidParameters p = FluidParameters.Default;
            p.DomainMin = new float3(-0.2f, 0f, -0.2f);
            p.DomainMax = new float3(0.2f, 0.4f, 0.2f);
            return p;
        }

        /// <summary>A tap 0.3 m up pouring straight down into <paramref name="fluid"/> at <paramref name="rate"/> particles/s.</summary>
        public static Entity CreateTap(EntityManager m, Entity fluid, float rate, float lifetime = 0f)
        {
            FluidTapSettings s = FluidTapSettings.Default;
            s.Position = new float3(0f, 0.3f, 0f);
            s.Rotation = quaternion.AxisAngle(new float3(1f, 0f, 0f), math.PI / 2f);
            s.Rate = rate;
            s.Lifetime = lifetime;
            Entity tap = m.CreateEntity();
            m.AddComponentData(tap, new FluidTap { Settings = s, Fluid = fluid });
            return tap;
        }
    }
}
