using System.Runtime.CompilerServices;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Particle (sphere of radius r) against a static primitive: penetration depth and the outward
    /// normal to push along, and a swept test against planes and boxes so that a fast particle cannot
    /// pass through them between two substeps. A particle near a box edge or corner is pushed along the
    /// direction from the closest point of the box (the box inflated by r has rounded edges), so its
    /// contact normal turns smoothly as it slides over an edge.
    /// </summary>
    public static class ParticleCollision
    {
        /// <summary>
        /// True when a particle at <paramref name="x"/> overlaps <paramref name="shape"/>; then
        /// <paramref name="normal"/> is the unit direction to push it and <paramref name="depth"/> &gt; 0 how far (m).
        /// </summary>
        public static bool Penetration(in ColliderShape shape, float3 x, float radius, out float3 normal, out float depth) =>
            Penetration(shape, x, radius, out normal, out depth, out _);

        /// <summary>
        /// As above; <paramref name="deep"/> is set when the particle's centre is inside a box, where the
        /// nearest face is only a guess at the side it came from (the swept test knows better).
        /// </summary>
        public static bool Penetration(in ColliderShape shape, float3 x, float radius, out float3 normal, out float depth,
            out bool deep)
        {
            deep = false;
            switch (shape.Type)
            {
                case ColliderShapeType.Plane:
                    normal = shape.Axis;
                    depth = radius - math.dot(x - shape.Center, shape.Axis);
                    return depth > 0f;
                case ColliderShapeType.Sphere:
                    return Round(x, shape.Center, shape.Radius + radius, out normal, out depth);
                case ColliderShapeType.Capsule:
                    return Round(x, ClosestOnSegment(x, shape.Center, shape.Axis), shape.Radius + radius, out normal, out depth);
                case ColliderShapeType.Box:
                    return Box(shape, x, radius, out normal, out depth, out deep);
                default:
                    normal = float3.zero;
                    depth = 0f;
                    return false;
            }
        }

        /// <summary>Relative distance (of the larger of the start's coordinate and the slab's half-width) within which a start on a box face counts as on it, not inside (<see cref="Sweep"/>): 8 ulp.</summary>
        public const float SweepTolerance = 1e-6f;

        /// <summary>
        /// Swept test of the motion <paramref name="from"/> → <paramref name="to"/> against a plane or an
        /// inflated box: true when the segment enters the solid, with the entry point and face normal.
        /// Spheres and capsules are tested at the end point only (a substep must move less than their radius).
        /// </summary>
        public static bool Sweep(in ColliderShape shape, float3 from, float3 to, float radius, out float3 entry, out float3 normal)
        {
            entry = to;
            normal = float3.zero;
            if (shape.Type == ColliderShapeType.Plane)
            {
                float d0 = math.dot(from - shape.Center, shape.Axis) - radius;
                float d1 = math.dot(to - shape.Center, shape.Axis) - radius;
                if (!(d0 >= 0f && d1 < 0f))
                    return false;
                entry = math.lerp(from, to, d0 / (d0 - d1));
                normal = shape.Axis;
                return true;
            }
            if (shape.Type != ColliderShapeType.Box)
                return false;
            quaternion inverse = math.conjugate(shape.Rotation);
            float3 a = math.rotate(inverse, from - shape.Center);
            float3 b = math.rotate(inverse, to - shape.Center);
            float3 extent = shape.HalfExtents + radius;
            float3 d = b - a;
            // Slab test. The entry face is the axis whose slab is entered last; a particle resting on a
            // face (entry time 0) counts as outside, so it leaves through that face, not the nearest one.
            float latestEntry = float.NegativeInfinity, tExit = 1f;
            int enterAxis = -1;
            for (int axis = 0; axis < 3; axis++)
            {
                if (math.abs(d[axis]) < 1e-12f)
                {
                    if (math.abs(a[axis]) > extent[axis])
                        return false;
                    continue;
                }
                float inv = 1f / d[axis];
                float t0 = (-extent[axis] - a[axis]) * inv, t1 = (extent[axis] - a[axis]) * inv;
                if (t0 > t1) { float t = t0; t0 = t1; t1 = t; }
                // A start on the entry plane to round-off (where the last substep's projection left a particle) enters at
                // t = 0: the same answer whether the rotation rounded it a few ulp inside or outside.
                if (t0 < 0f && t0 * math.abs(d[axis]) > -SweepTolerance * math.max(math.abs(a[axis]), extent[axis]))
                    t0 = 0f;
                if (t0 > latestEntry) { latestEntry = t0; enterAxis = axis; }
                tExit = math.min(tExit, t1);
            }
            if (enterAxis < 0 || latestEntry < 0f || latestEntry > tExit) // started inside, or missed
                return false;
            float tEnter = latestEntry;
            float3 local = float3.zero;
            local[enterAxis] = d[enterAxis] > 0f ? -1f : 1f;
            normal = math.rotate(shape.Rotation, local);
            entry = from + tEnter * (to - from);
            return true;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        static bool Round(float3 x, float3 center, float reach, out float3 normal, out float depth)
        {
            float3 r = x - center;
            float d2 = math.lengthsq(r);
            if (!(d2 < reach * reach))
            {
                normal = float3.zero;
                depth = 0f;
                return false;
            }
            float d = math.sqrt(d2);
            normal = d > 1e-12f ? r / d : new float3(0f, 1f, 0f); // at the centre: push up
            depth = reach - d;
            return true;
        }

        /// <summary>
        /// Unit direction out of <paramref name="shape"/> at a point <paramref name="x"/> inside or outside it: away from the
        /// closest surface point when outside, through the nearest face (box) or away from the centre or axis (sphere,
        /// capsule) when inside; the plane's normal; up at a sphere's centre or on a capsule's axis.
        /// </summary>
        public static float3 Outward(in ColliderShape shape, float3 x)
        {
            switch (shape.Type)
            {
                case ColliderShapeType.Plane:
                    return shape.Axis;
                case ColliderShapeType.Sphere:
                    return AwayFrom(x, shape.Center);
                case ColliderShapeType.Capsule:
                    return AwayFrom(x, ClosestOnSegment(x, shape.Center, shape.Axis));
                case ColliderShapeType.Box:
                {
                    float3 local = math.rotate(math.conjugate(shape.Rotation), x - shape.Center);
                    float3 offset = local - math.clamp(local, -shape.HalfExtents, shape.HalfExtents);
                    if (math.lengthsq(offset) > 0f)
                        return math.rotate(shape.Rotation, math.normalize(offset));
                    float3 gap = math.abs(local) - shape.HalfExtents;
                    int axis = gap.x > gap.y ? (gap.x > gap.z ? 0 : 2) : (gap.y > gap.z ? 1 : 2);
                    float3 n = float3.zero;
                    n[axis] = local[axis] >= 0f ? 1f : -1f;
                    return math.rotate(shape.Rotation, n);
                }
                default:
                    return new float3(0f, 1f, 0f);
            }
        }

        static float3 AwayFrom(float3 x, float3 center)
        {
            float3 r = x - center;
            float d2 = math.lengthsq(r);
            return d2 > 1e-24f ? r * math.rsqrt(d2) : new float3(0f, 1f, 0f);
        }

        /// <summary>True when <paramref name="x"/> lies in <paramref name="shape"/> or on its surface (a plane's solid is the half-space behind it).</summary>
        public static bool Contains(in ColliderShape shape, float3 x)
        {
            switch (shape.Type)
            {
                case ColliderShapeType.Plane:
                    return !(math.dot(x - shape.Center, shape.Axis) > 0f);
                case ColliderShapeType.Sphere:
                    return !(math.lengthsq(x - shape.Center) > shape.Radius * shape.Radius);
                case ColliderShapeType.Capsule:
                    return !(math.lengthsq(x - ClosestOnSegment(x, shape.Center, shape.Axis)) > shape.Radius * shape.Radius);
                case ColliderShapeType.Box:
                    float3 local = math.rotate(math.conjugate(shape.Rotation), x - shape.Center);
                    return !math.any(math.abs(local) > shape.HalfExtents);
                default:
                    return false;
            }
        }

        /// <summary>Closest point to <paramref name="x"/> on the segment a–b.</summary>
        public static float3 ClosestOnSegment(float3 x, float3 a, float3 b)
        {
            float3 ab = b - a;
            float len2 = math.lengthsq(ab);
            float t = len2 > 0f ? math.saturate(math.dot(x - a, ab) / len2) : 0f;
            return a + t * ab;
        }

        static bool Box(in ColliderShape shape, float3 x, float radius, out float3 normal, out float depth, out bool deep)
        {
            float3 local = math.rotate(math.conjugate(shape.Rotation), x - shape.Center);
            float3 closest = math.clamp(local, -shape.HalfExtents, shape.HalfExtents);
            float3 offset = local - closest;
            float d2 = math.lengthsq(offset);
            normal = float3.zero;
            depth = 0f;
            deep = false;
            if (d2 > 0f)
            {
                // Centre outside the box: push away from the closest point (rounded edges and corners).
                if (!(d2 < radius * radius))
                    return false;
                float d = math.sqrt(d2);
                normal = math.rotate(shape.Rotation, offset / d);
                depth = radius - d;
                return true;
            }
            // Centre inside the box: leave through the nearest face.
            deep = true;
            float3 gap = math.abs(local) - shape.HalfExtents; // ≤ 0 on every axis
            int axis = gap.x > gap.y ? (gap.x > gap.z ? 0 : 2) : (gap.y > gap.z ? 1 : 2);
            float3 n = float3.zero;
            n[axis] = local[axis] >= 0f ? 1f : -1f;
            normal = math.rotate(shape.Rotation, n);
            depth = radius - gap[axis];
            return true;
        }
    }
}
