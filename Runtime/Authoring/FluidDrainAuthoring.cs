using SoftBodyDynamics.Solvers;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// A drain (kill volume) of a <see cref="FluidAuthoring"/>: every particle whose centre enters the box or sphere is
    /// removed (and counted as killed). Placed by the Transform (position, rotation, scale) at bake time.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("Soft Body Dynamics/Fluid Drain")]
    public sealed class FluidDrainAuthoring : MonoBehaviour
    {
        [Tooltip("The fluid this drain removes particles from.")]
        public FluidAuthoring fluid;

        [Tooltip("Box or Sphere.")]
        public ColliderShapeType shape = ColliderShapeType.Box;

        [Tooltip("Box: full size along local X, Y and Z (m, before scale).")]
        public Vector3 size = new Vector3(0.2f, 0.1f, 0.2f);

        [Tooltip("Sphere: radius (m, before scale).")]
        [Min(0f)]
        public float radius = 0.1f;

        /// <summary>The drain in world space.</summary>
        public FluidDrain ToDrain()
        {
            var definition = new ParticleColliderDefinition
            {
                Shape = shape == ColliderShapeType.Sphere ? ColliderShapeType.Sphere : ColliderShapeType.Box,
                Center = Unity.Mathematics.float3.zero,
                Size = UnityMathConversions.ToFloat3(size),
                Radius = radius,
                Height = 2f * radius,
                Direction = ColliderCapsuleAxis.Y,
            };
            return new FluidDrain
            {
                Shape = ParticleColliderWorldShape.Compute(definition, UnityMathConversions.ToFloat3(transform.position),
                    UnityMathConversions.ToQuaternion(transform.rotation), UnityMathConversions.ToFloat3(transform.lossyScale)),
            };
        }

        void OnDrawGizmos() => ColliderShapeGizmos.Draw(ToDrain().Shape, new Color(0.9f, 0.2f, 0.3f, 0.9f));
    }
}
