using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// The components a fluid entity carries, for fluids created from code: <see cref="FluidSettings"/>, a fresh
    /// <see cref="FluidRuntime"/> and the empty particle, scratch and tap buffers, which the first update sizes to the
    /// budget. The <c>FluidAuthoring</c> baker adds the same set. Taps (<see cref="FluidTap"/>) and drains are entities of
    /// their own that name the fluid. Structural change: call it on the main thread.
    /// </summary>
    public static class FluidArchetype
    {
        /// <summary>Makes <paramref name="entity"/> a fluid of <paramref name="settings"/>.</summary>
        public static void AddComponents(EntityManager m, Entity entity, in FluidSettings settings)
        {
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
        }
    }
}
