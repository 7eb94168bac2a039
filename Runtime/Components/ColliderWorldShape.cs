using SoftBodyDynamics.Solvers;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// One collider of the fixed step's collider world, in world space (m): a buffer on one singleton entity, rebuilt from
    /// every <see cref="ParticleCollider"/> by <see cref="ColliderWorldSystem"/> at the start of
    /// <see cref="ParticleSimulationSystemGroup"/> and read by every particle-body and fluid system of the step, so the
    /// colliders are gathered once per step whatever the number of methods. Capacity 0 keeps it out of the chunk.
    /// </summary>
    [InternalBufferCapacity(0)]
    public struct ColliderWorldShape : IBufferElementData
    {
        public ColliderShape Shape;
    }
}
