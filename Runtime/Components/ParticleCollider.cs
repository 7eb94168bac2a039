using SoftBodyDynamics.Solvers;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// A static primitive collider (plane, sphere, box or capsule) in world space that every soft body
    /// collides with. The simulation gathers all of them once per step.
    /// </summary>
    public struct ParticleCollider : IComponentData
    {
        /// <summary>The shape, in world space (m).</summary>
        public ColliderShape Shape;
    }
}
