using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Enabled on a soft body whose particles have not been placed yet (baked prefabs and bodies created
    /// from code). <see cref="ShapeMatchingInitializationSystem"/> sizes the buffers, places the rest shape at
    /// the entity's <c>LocalTransform</c> and disables it; enable it again to reset a body to its rest
    /// shape at its current transform.
    /// </summary>
    public struct SoftBodyUninitialized : IComponentData, IEnableableComponent
    {
    }
}
