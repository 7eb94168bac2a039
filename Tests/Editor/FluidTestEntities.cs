using Unity.Entities;

namespace SoftBodyDynamics.Tests.Editor
{
    /// <summary>Fluid entities as the baker makes them, for the system tests.</summary>
    static class FluidTestEntities
    {
        /// <summary>A fluid entity with <paramref name="settings"/>, a fresh <see cref="FluidRuntime"/> and the empty particle buffers.</summary>
        public static Entity Create(EntityManager m, in FluidSettings settings)
        {
            Entity entity = m.CreateEntity();
            m.AddComponentData(entity, settings);
            m.AddComponentData(entity, new FluidRuntime());
            m.AddBuffer<FluidPosition>(entity);
            m.AddBuffer<FluidVelocity>(entity);
            m.AddBuffer<FluidAge>(entity);
            m.AddBuffer<FluidLifetime>(entity);
            m.AddBuffer<FluidAttribute>(entity);
            m.AddBuffer<FluidId>(entity);
            m.AddBuffer<FluidScratchInt>(entity);
            m.AddBuffer<FluidScratchFloat>(entity);
            m.AddBuffer<FluidScratchVector>(entity);
            m.AddBuffer<FluidTapRuntime>(entity);
            return entity;
        }
    }
}
