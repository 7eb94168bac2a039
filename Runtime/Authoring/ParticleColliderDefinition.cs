using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// A collider as authored, in the local space of its GameObject before the transform's scale: what
    /// <see cref="ParticleColliderAuthoring"/> serializes, as plain data that conversion and validation work on.
    /// </summary>
    public struct ParticleColliderDefinition
    {
        /// <summary>Plane, sphere, box or capsule.</summary>
        public ColliderShapeType Shape;
        /// <summary>Centre in local space (m). Plane: a point on the plane.</summary>
        public float3 Center;
        /// <summary>Box: full size along local X, Y, Z (m).</summary>
        public float3 Size;
        /// <summary>Sphere and capsule radius (m).</summary>
        public float Radius;
        /// <summary>Capsule: total height from tip to tip, both caps included (m).</summary>
        public float Height;
        /// <summary>Capsule: the local axis it runs along.</summary>
        public ColliderCapsuleAxis Direction;
    }
}
