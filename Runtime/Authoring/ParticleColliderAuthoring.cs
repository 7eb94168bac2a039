using SoftBodyDynamics.Solvers;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// A static collider that soft-body particles collide with: an infinite plane, a sphere, a box or a capsule,
    /// placed by this GameObject's Transform (position, rotation and scale). Baked once into a world-space
    /// <see cref="ParticleCollider"/>; moving the GameObject at runtime does not move the collider.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("Soft Body Dynamics/Particle Collider")]
    public sealed class ParticleColliderAuthoring : MonoBehaviour
    {
        [Tooltip("Plane: infinite, solid below this GameObject's up axis. Sphere, Box, Capsule: solid primitives.")]
        public ColliderShapeType shape = ColliderShapeType.Box;

        [Tooltip("Centre of the shape in this GameObject's local space (m, scaled by the Transform). Plane: a point on the plane.")]
        public Vector3 center = Vector3.zero;

        [Tooltip("Box: full size along local X, Y and Z (m, before the Transform's scale). Every component > 0. Default 1 m, like Unity's cube.")]
        public Vector3 size = Vector3.one;

        [Tooltip("Sphere and capsule: radius (m, before the Transform's scale). > 0. Default 0.5 m, like Unity's sphere.")]
        [Min(0f)]
        public float radius = 0.5f;

        [Tooltip("Capsule: total height from tip to tip, both caps included (m, before the Transform's scale). At least 2 × radius. Default 2 m, like Unity's capsule.")]
        [Min(0f)]
        public float height = 2f;

        [Tooltip("Capsule: the local axis it runs along.")]
        public ColliderCapsuleAxis direction = ColliderCapsuleAxis.Y;

        /// <summary>The serialized fields as plain data.</summary>
        public ParticleColliderDefinition Definition => new ParticleColliderDefinition
        {
            Shape = shape,
            Center = UnityMathConversions.ToFloat3(center),
            Size = UnityMathConversions.ToFloat3(size),
            Radius = radius,
            Height = height,
            Direction = direction,
        };

        /// <summary>The world-space shape for the current Transform (what the baker stores).</summary>
        public ColliderShape ToWorldShape() => ParticleColliderWorldShape.Compute(Definition,
            UnityMathConversions.ToFloat3(transform.position), UnityMathConversions.ToQuaternion(transform.rotation),
            UnityMathConversions.ToFloat3(transform.lossyScale));

        void OnDrawGizmos()
        {
            ColliderShapeGizmos.Draw(ToWorldShape(), new Color(1f, 0.6f, 0.1f, 0.9f));
        }
    }
}
