using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// The package's fixed step, ordered like Unity Physics' <c>PhysicsSystemGroup</c>: build the collider world once
    /// (<see cref="ColliderWorldSystem"/>, first), then one thin system per particle-body method
    /// (<see cref="ShapeMatchingInitializationSystem"/> and <see cref="ShapeMatchingSimulationSystem"/> for shape matching,
    /// <see cref="MassSpringSimulationSystem"/>, <see cref="FemSimulationSystem"/>), then the fluids
    /// (<see cref="FluidComputeSystem"/>, then <see cref="FluidSimulationSystem"/>). Each of those systems updates only
    /// while its kind of entity exists, so a scene pays only for what it contains. What the renderer reads (deformed
    /// meshes, fluid particle buffers) is exported once per rendered frame in <c>PresentationSystemGroup</c>, since a
    /// rendered frame runs zero or several fixed steps.
    /// </summary>
    [UpdateInGroup(typeof(FixedStepSimulationSystemGroup))]
    public partial class ParticleSimulationSystemGroup : ComponentSystemGroup
    {
    }
}
