using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>The shape-matching step (work in progress: signatures fixed).</summary>
    public static class ShapeMatchingSolver
    {
        public static void Initialize(in ShapeMatchingModel model, in ShapeMatchingState state, float3 position,
            quaternion rotation, float3 velocity, out SoftBodyStatus status)
        {
            status = default;
        }

        public static ShapeMatchingStepReport Step(in ShapeMatchingModel model, in ShapeMatchingParameters parameters,
            ReadOnlySpan<ColliderShape> colliders, float dt, in ShapeMatchingState state, ref SoftBodyStatus status)
        {
            return default;
        }
    }
}
