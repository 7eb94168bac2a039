using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Turns an authored collider and its transform (position, rotation, lossy scale) into the world-space
    /// <see cref="ColliderShape"/> the solver collides with. Scale is taken by magnitude (a mirrored box is the
    /// same box). A sphere takes the largest of the three scale factors, a capsule the larger of its two radial
    /// ones (as Unity's own colliders do); validation warns when that loses information. A plane passes through
    /// the transformed centre with the GameObject's up axis as its outward normal; its scale does not matter.
    /// </summary>
    public static class ParticleColliderWorldShape
    {
        /// <summary>The plane's local normal: the GameObject's up axis.</summary>
        public static readonly float3 LocalPlaneNormal = new float3(0f, 1f, 0f);

        public static ColliderShape Compute(in ParticleColliderDefinition collider, float3 position, quaternion rotation,
            float3 lossyScale)
        {
            float3 scale = math.abs(lossyScale);
            float3 center = position + math.mul(rotation, collider.Center * lossyScale);
            switch (collider.Shape)
            {
                case ColliderShapeType.Plane:
                    return ColliderShape.Plane(center, math.mul(rotation, LocalPlaneNormal));
                case ColliderShapeType.Sphere:
                    return ColliderShape.Sphere(center, collider.Radius * math.cmax(scale));
                case ColliderShapeType.Box:
                    return ColliderShape.Box(center, rotation, 0.5f * math.abs(collider.Size) * scale);
                case ColliderShapeType.Capsule:
                {
                    int axis = (int)collider.Direction;
                    float axialScale = scale[axis];
                    float radius = collider.Radius * RadialScale(scale, collider.Direction);
                    float halfSegment = math.max(0f, 0.5f * collider.Height * axialScale - radius);
                    float3 localAxis = default;
                    localAxis[axis] = 1f;
                    float3 offset = math.mul(rotation, localAxis) * halfSegment;
                    return ColliderShape.Capsule(center - offset, center + offset, radius);
                }
                default:
                    return default;
            }
        }

        /// <summary>The larger of the two scale factors across a capsule's axis.</summary>
        public static float RadialScale(float3 absoluteScale, ColliderCapsuleAxis direction)
        {
            float2 radial = RadialScales(absoluteScale, direction);
            return math.max(radial.x, radial.y);
        }

        /// <summary>The two scale factors across a capsule's axis, in X, Y, Z order.</summary>
        public static float2 RadialScales(float3 absoluteScale, ColliderCapsuleAxis direction)
        {
            switch (direction)
            {
                case ColliderCapsuleAxis.X: return new float2(absoluteScale.y, absoluteScale.z);
                case ColliderCapsuleAxis.Z: return new float2(absoluteScale.x, absoluteScale.y);
                default: return new float2(absoluteScale.x, absoluteScale.z);
            }
        }
    }
}
