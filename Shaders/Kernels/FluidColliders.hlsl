// The soft bodies' static colliders and the drains as the fluid kernels see them: a port of ColliderShape,
// ParticleCollision (Penetration, Sweep) and ContactProjection.Project. Shapes are 5 float4 each in _Shapes
// (FluidComputeStep.PackShapes): the colliders first (ColliderCount of them), then the drains (DrainCount).
#ifndef SBD_FLUID_COLLIDERS_INCLUDED
#define SBD_FLUID_COLLIDERS_INCLUDED
#include "FluidCommon.hlsl"

#define SHAPE_PLANE 0
#define SHAPE_SPHERE 1
#define SHAPE_BOX 2
#define SHAPE_CAPSULE 3
#define SHAPE_FLOAT4S 5
// ContactProjection.OppositeNormals.
#define OPPOSITE_NORMALS 1e-4

struct Shape
{
    uint type;
    float radius;
    float3 centre;       // plane: a point; sphere, box: centre; capsule: first end
    float3 axis;         // plane: unit normal; capsule: second end
    float4 rotation;     // box orientation (quaternion xyzw)
    float3 halfExtents;  // box
};

Shape LoadShape(uint index)
{
    uint b = index * SHAPE_FLOAT4S;
    float4 a = _Shapes[b];
    Shape s;
    s.type = asuint(a.x);
    s.radius = a.y;
    s.centre = _Shapes[b + 1].xyz;
    s.axis = _Shapes[b + 2].xyz;
    s.rotation = _Shapes[b + 3];
    s.halfExtents = _Shapes[b + 4].xyz;
    return s;
}

// math.rotate(q, v) of Unity.Mathematics.
float3 Rotate(float4 q, float3 v)
{
    float3 t = 2.0 * cross(q.xyz, v);
    return v + q.w * t + cross(q.xyz, t);
}

float4 Conjugate(float4 q) { return float4(-q.xyz, q.w); }

bool Round(float3 x, float3 centre, float reach, out float3 normal, out float depth)
{
    float3 r = x - centre;
    float d2 = dot(r, r);
    normal = float3(0.0, 0.0, 0.0);
    depth = 0.0;
    if (!(d2 < reach * reach)) return false;
    float d = sqrt(d2);
    normal = d > 1e-12 ? r / d : float3(0.0, 1.0, 0.0);
    depth = reach - d;
    return true;
}

float3 ClosestOnSegment(float3 x, float3 a, float3 b)
{
    float3 ab = b - a;
    float len2 = dot(ab, ab);
    float t = len2 > 0.0 ? saturate(dot(x - a, ab) / len2) : 0.0;
    return a + t * ab;
}

// ParticleCollision.Contains: x in the shape or on its surface (a plane's solid is the half-space behind it).
bool ContainsPoint(Shape s, float3 x)
{
    if (s.type == SHAPE_PLANE) return !(dot(x - s.centre, s.axis) > 0.0);
    if (s.type == SHAPE_SPHERE) { float3 r = x - s.centre; return !(dot(r, r) > s.radius * s.radius); }
    if (s.type == SHAPE_CAPSULE) { float3 r = x - ClosestOnSegment(x, s.centre, s.axis); return !(dot(r, r) > s.radius * s.radius); }
    if (s.type == SHAPE_BOX) return !any(abs(Rotate(Conjugate(s.rotation), x - s.centre)) > s.halfExtents);
    return false;
}

bool BoxPenetration(Shape s, float3 x, float radius, out float3 normal, out float depth, out bool deep)
{
    float3 local = Rotate(Conjugate(s.rotation), x - s.centre);
    float3 closest = clamp(local, -s.halfExtents, s.halfExtents);
    float3 offset = local - closest;
    float d2 = dot(offset, offset);
    normal = float3(0.0, 0.0, 0.0);
    depth = 0.0;
    deep = false;
    if (d2 > 0.0)
    {
        if (!(d2 < radius * radius)) return false;
        float d = sqrt(d2);
        normal = Rotate(s.rotation, offset / d);
        depth = radius - d;
        return true;
    }
    deep = true;
    float3 gap = abs(local) - s.halfExtents;
    int axis = gap.x > gap.y ? (gap.x > gap.z ? 0 : 2) : (gap.y > gap.z ? 1 : 2);
    float3 n = float3(0.0, 0.0, 0.0);
    n[axis] = local[axis] >= 0.0 ? 1.0 : -1.0;
    normal = Rotate(s.rotation, n);
    depth = radius - gap[axis];
    return true;
}

// ParticleCollision.Penetration.
bool Penetration(Shape s, float3 x, float radius, out float3 normal, out float depth, out bool deep)
{
    deep = false;
    normal = float3(0.0, 0.0, 0.0);
    depth = 0.0;
    if (s.type == SHAPE_PLANE)
    {
        normal = s.axis;
        depth = radius - dot(x - s.centre, s.axis);
        return depth > 0.0;
    }
    if (s.type == SHAPE_SPHERE) return Round(x, s.centre, s.radius + radius, normal, depth);
    if (s.type == SHAPE_CAPSULE) return Round(x, ClosestOnSegment(x, s.centre, s.axis), s.radius + radius, normal, depth);
    if (s.type == SHAPE_BOX) return BoxPenetration(s, x, radius, normal, depth, deep);
    return false;
}

// ParticleCollision.Sweep against a plane or an inflated box.
bool Sweep(Shape s, float3 from, float3 to, float radius, out float3 entry, out float3 normal)
{
    entry = to;
    normal = float3(0.0, 0.0, 0.0);
    if (s.type == SHAPE_PLANE)
    {
        float d0 = dot(from - s.centre, s.axis) - radius;
        float d1 = dot(to - s.centre, s.axis) - radius;
        if (!(d0 >= 0.0 && d1 < 0.0)) return false;
        entry = lerp(from, to, d0 / (d0 - d1));
        normal = s.axis;
        return true;
    }
    if (s.type != SHAPE_BOX) return false;
    float4 inverse = Conjugate(s.rotation);
    float3 a = Rotate(inverse, from - s.centre);
    float3 b = Rotate(inverse, to - s.centre);
    float3 extent = s.halfExtents + radius;
    float3 d = b - a;
    float latestEntry = -FLOAT_MAX, tExit = 1.0;
    int enterAxis = -1;
    [unroll] for (int axis = 0; axis < 3; axis++)
    {
        if (abs(d[axis]) < 1e-12)
        {
            if (abs(a[axis]) > extent[axis]) return false;
            continue;
        }
        float inv = 1.0 / d[axis];
        float t0 = (-extent[axis] - a[axis]) * inv, t1 = (extent[axis] - a[axis]) * inv;
        if (t0 > t1) { float t = t0; t0 = t1; t1 = t; }
        // A start on the entry plane to round-off enters at t = 0 (ParticleCollision.SweepTolerance).
        if (t0 < 0.0 && t0 * abs(d[axis]) > -1e-6 * max(abs(a[axis]), extent[axis])) t0 = 0.0;
        if (t0 > latestEntry) { latestEntry = t0; enterAxis = axis; }
        tExit = min(tExit, t1);
    }
    if (enterAxis < 0 || latestEntry < 0.0 || latestEntry > tExit) return false;
    float3 local = float3(0.0, 0.0, 0.0);
    local[enterAxis] = d[enterAxis] > 0.0 ? -1.0 : 1.0;
    normal = Rotate(s.rotation, local);
    entry = from + latestEntry * (to - from);
    return true;
}

// FluidDrain.Apply: a live particle whose centre is inside a drain gets lifetime −1 (the next sort removes it).
[numthreads(FLUID_GROUP, 1, 1)]
void Drain(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    float4 vl = _Velocities[i];
    if (vl.w < 0.0) return;
    float3 x = _Positions[i].xyz;
    for (uint d = 0; d < DrainCount; d++)
    {
        float3 n; float depth; bool deep;
        if (Penetration(LoadShape(ColliderCount + d), x, 0.0, n, depth, deep))
        {
            _Velocities[i] = float4(vl.xyz, -1.0);
            return;
        }
    }
}

// FluidPasses.Collide: ContactProjection.Project with the particle as a sphere of the wall distance, no bounce,
// Coulomb friction, the overlap carried from the substep's start removed at most max speed · h per substep.
// The contact normal goes to _VectorsA.
[numthreads(FLUID_GROUP, 1, 1)]
void Collide(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    float radius = WallDistance, h = SubstepSeconds, friction = ColliderFriction, maxDepenetration = MaxSpeed * h;
    float4 xa = _Positions[i];
    float3 start = xa.xyz, x = start, previous = _Previous[i].xyz;
    float3 contactNormal = float3(0.0, 0.0, 0.0);
    for (uint c = 0; c < ColliderCount; c++)
    {
        Shape s = LoadShape(c);
        float3 n; float depth; bool deep;
        bool hit = Penetration(s, x, radius, n, depth, deep);
        float3 entry, face;
        if (s.type == SHAPE_BOX && Sweep(s, previous, x, radius, entry, face) && (!hit || deep || dot(n, face) < -OPPOSITE_NORMALS))
        {
            n = face;
            depth = dot(entry - x, face);
        }
        else if (!hit)
            continue;
        float3 n0; float startDepth; bool deep0;
        if (Penetration(s, previous, radius, n0, startDepth, deep0) && startDepth > maxDepenetration)
            depth = min(depth, max(0.0, depth - (startDepth - maxDepenetration)));
        if (!(depth > 0.0)) continue;
        x += depth * n;
        float3 motion = x - previous;
        float3 tangential = motion - dot(motion, n) * n;
        float slide = length(tangential);
        float limit = friction * depth;
        if (slide > 0.0) x -= tangential * min(1.0, limit / slide);
        contactNormal = n;
    }
    _VectorsA[i] = float4(contactNormal, 0.0);
    if (dot(contactNormal, contactNormal) == 0.0) return;
    InterlockedAdd(_Stats[STAT_CONTACTS], 1);
    // Restitution 0 and an infinite bounce threshold: the push becomes velocity, nothing bounces.
    float invH = 1.0 / h;
    float4 vl = _Velocities[i];
    _Velocities[i] = float4(vl.xyz + (x - start) * invH, vl.w);
    _Positions[i] = float4(x, xa.w);
}

#endif
