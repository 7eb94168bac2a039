using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Primitive static collider kinds the particles collide with.</summary>
    public enum ColliderShapeType : byte
    {
        /// <summary>Infinite plane; the solid is the half-space behind the normal.</summary>
        Plane = 0,
        /// <summary>Solid sphere.</summary>
        Sphere = 1,
        /// <summary>Solid oriented box.</summary>
        Box = 2,
        /// <summary>Solid capsule: all points within a radius of a segment.</summary>
        Capsule = 3,
    }

    /// <summary>
    /// A primitive collider in world space (a component or a blob element in ECS). Build it with the factory
    /// methods; the fields a kind does not use stay zero. It is static unless given a velocity (<see cref="Moving"/>):
    /// fluids then see its surface move (their walls' ghosts take its normal velocity); soft bodies collide with its
    /// placement of the step.
    /// </summary>
    public struct ColliderShape
    {
        public ColliderShapeType Type;
        /// <summary>Plane: a point on it. Sphere and box: centre. Capsule: first end of the segment (m).</summary>
        public float3 Center;
        /// <summary>Plane: unit outward normal. Capsule: second end of the segment (m). Unused otherwise.</summary>
        public float3 Axis;
        /// <summary>Box orientation.</summary>
        public quaternion Rotation;
        /// <summary>Box half extents (m, all &gt; 0).</summary>
        public float3 HalfExtents;
        /// <summary>Sphere or capsule radius (m, &gt; 0).</summary>
        public float Radius;
        /// <summary>Velocity of the solid (m/s); zero for a static collider.</summary>
        public float3 Velocity;
        /// <summary>Angular velocity of the solid about <see cref="Center"/> (rad/s); zero for a static collider.</summary>
        public float3 AngularVelocity;

        /// <summary>Velocity (m/s) of the solid's point at <paramref name="point"/> (world): v + ω × (point − centre).</summary>
        public float3 VelocityAt(float3 point) => Velocity + math.cross(AngularVelocity, point - Center);

        /// <summary>The same collider moving with <paramref name="velocity"/> (m/s) and <paramref name="angularVelocity"/> (rad/s, about the centre).</summary>
        public ColliderShape Moving(float3 velocity, float3 angularVelocity)
        {
            ColliderShape c = this;
            c.Velocity = velocity;
            c.AngularVelocity = angularVelocity;
            return c;
        }

        public static ColliderShape Plane(float3 point, float3 normal) => new ColliderShape
            { Type = ColliderShapeType.Plane, Center = point, Axis = math.normalizesafe(normal, new float3(0f, 1f, 0f)), Rotation = quaternion.identity };

        public static ColliderShape Sphere(float3 center, float radius) => new ColliderShape
            { Type = ColliderShapeType.Sphere, Center = center, Radius = radius, Rotation = quaternion.identity };

        public static ColliderShape Box(float3 center, quaternion rotation, float3 halfExtents) => new ColliderShape
            { Type = ColliderShapeType.Box, Center = center, Rotation = math.normalizesafe(rotation), HalfExtents = halfExtents };

        /// <summary>The same collider moved by <paramref name="offset"/> (m): used to see it from a body's origin.</summary>
        public ColliderShape Translated(float3 offset)
        {
            ColliderShape c = this;
            c.Center += offset;
            if (Type == ColliderShapeType.Capsule)
                c.Axis += offset;
            return c;
        }

        public static ColliderShape Capsule(float3 pointA, float3 pointB, float radius) => new ColliderShape
            { Type = ColliderShapeType.Capsule, Center = pointA, Axis = pointB, Radius = radius, Rotation = quaternion.identity };

        /// <summary>
        /// The same collider given in a body's space, seen from the world: x_world = t + R·(s·x) for the body's position
        /// <paramref name="translation"/> (m), rotation <paramref name="rotation"/> and uniform scale <paramref name="scale"/>
        /// (lengths and radii times s; a plane's normal only rotates).
        /// </summary>
        public ColliderShape Transformed(float3 translation, quaternion rotation, float scale)
        {
            ColliderShape c = this;
            c.Center = translation + math.mul(rotation, scale * Center);
            switch (Type)
            {
                case ColliderShapeType.Plane:
                    c.Axis = math.mul(rotation, Axis);
                    break;
                case ColliderShapeType.Capsule:
                    c.Axis = translation + math.mul(rotation, scale * Axis);
                    c.Radius = scale * Radius;
                    break;
                case ColliderShapeType.Box:
                    c.Rotation = math.normalizesafe(math.mul(rotation, Rotation));
                    c.HalfExtents = scale * HalfExtents;
                    break;
                default:
                    c.Radius = scale * Radius;
                    break;
            }
            return c;
        }
    }
}
