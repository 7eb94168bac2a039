using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Particle position xᵢ of a soft body (m) relative to the body's origin <c>ParticleBodyState.Status.Origin</c>, one
    /// element per particle (tier 3, runtime state). The origin is zero while the body stays within
    /// <see cref="SoftBodyDynamics.Solvers.ShapeMatchingSolver.RebaseDistance"/> of the world origin, so there the
    /// values are world positions; world position = Origin + Value.
    /// </summary>
    [InternalBufferCapacity(0)]
    public struct SoftBodyPosition : IBufferElementData
    {
        /// <summary>Position relative to the body's origin (m).</summary>
        public float3 Value;
    }
}
