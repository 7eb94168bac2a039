using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    // The packed particle arrays of a fluid entity, one buffer per array (structure of arrays, as the solver reads them),
    // sized to the budget; the first FluidRuntime.Status.Count entries are alive and sorted by grid cell. Capacity 0 keeps
    // them out of the chunk.

    /// <summary>Particle positions (m, world).</summary>
    [InternalBufferCapacity(0)]
    public struct FluidPosition : IBufferElementData { public float3 Value; }

    /// <summary>Particle velocities (m/s).</summary>
    [InternalBufferCapacity(0)]
    public struct FluidVelocity : IBufferElementData { public float3 Value; }

    /// <summary>Particle ages (s).</summary>
    [InternalBufferCapacity(0)]
    public struct FluidAge : IBufferElementData { public float Value; }

    /// <summary>Particle lifetimes (s; 0 = forever; negative = marked for removal).</summary>
    [InternalBufferCapacity(0)]
    public struct FluidLifetime : IBufferElementData { public float Value; }

    /// <summary>Particle attribute (temperature in K or a colour parameter).</summary>
    [InternalBufferCapacity(0)]
    public struct FluidAttribute : IBufferElementData { public float Value; }

    /// <summary>Particle ids (stable identity, spawn order).</summary>
    [InternalBufferCapacity(0)]
    public struct FluidId : IBufferElementData { public int Value; }

    /// <summary>Integer scratch of the step (keys, order, sort ranks, neighbour counts, neighbour lists, cell table).</summary>
    [InternalBufferCapacity(0)]
    public struct FluidScratchInt : IBufferElementData { public int Value; }

    /// <summary>Float scratch of the step (densities, pressures, sort).</summary>
    [InternalBufferCapacity(0)]
    public struct FluidScratchFloat : IBufferElementData { public float Value; }

    /// <summary>Vector scratch of the step (previous positions, two Jacobi buffers).</summary>
    [InternalBufferCapacity(0)]
    public struct FluidScratchVector : IBufferElementData { public float3 Value; }

    /// <summary>The running state of one tap of this fluid, kept with the fluid so the step job owns it.</summary>
    [InternalBufferCapacity(2)]
    public struct FluidTapRuntime : IBufferElementData
    {
        /// <summary>The tap entity.</summary>
        public Entity Tap;
        /// <summary>Its schedule and random state.</summary>
        public Solvers.FluidTapState State;
    }
}
