// The walls of the domain box and the colliders as the SPH sums see them: a port of FluidGhostWalls (mirror planes for
// the weakly compressible ghosts), of FluidBoundary (Sample for position-based fluids, ClampToDomain) and of the
// half-space integrals of SphKernels.
#ifndef SBD_FLUID_WALLS_INCLUDED
#define SBD_FLUID_WALLS_INCLUDED
#include "FluidColliders.hlsl"

// FluidGhostWalls.MaxWalls and SameWallCosine.
#define MAX_GHOST_WALLS 4
#define SAME_WALL_COSINE 0.99

// The walls within h of one particle: unit normals into the fluid and distances (FluidGhostWalls).
struct GhostWalls
{
    float3 n[MAX_GHOST_WALLS];
    float d[MAX_GHOST_WALLS];
    int collider[MAX_GHOST_WALLS]; // index in the colliders, −1 for a face
    uint count;
};

// FluidGhostWalls.Add: of two walls facing the same way only the nearer counts.
void AddGhostWall(inout GhostWalls w, float3 n, float d, int collider)
{
    if (!(d >= -FLOAT_MAX)) return;
    d = max(d, 0.0);
    for (uint k = 0; k < w.count; k++)
    {
        if (!(dot(n, w.n[k]) > SAME_WALL_COSINE)) continue;
        if (d < w.d[k]) { w.n[k] = n; w.d[k] = d; w.collider[k] = collider; }
        return;
    }
    if (w.count >= MAX_GHOST_WALLS) return;
    w.n[w.count] = n;
    w.d[w.count] = d;
    w.collider[w.count] = collider;
    w.count++;
}

// FluidGhostWalls.Near: the faces (none on a periodic axis; x, y, z, below then above), then the colliders' tangent planes.
GhostWalls NearWalls(float3 xi)
{
    GhostWalls w;
    [unroll] for (uint k = 0; k < MAX_GHOST_WALLS; k++) { w.n[k] = float3(0.0, 0.0, 0.0); w.d[k] = 0.0; w.collider[k] = -1; }
    w.count = 0;
    float h = SmoothingLength;
    [unroll] for (int a = 0; a < 3; a++)
    {
        if (Period[a] > 0.0) continue;
        float3 axis = float3(0.0, 0.0, 0.0);
        axis[a] = 1.0;
        float below = xi[a] - DomainMin[a], above = DomainMax[a] - xi[a];
        if (below < h) AddGhostWall(w, axis, below, -1);
        if (above < h) AddGhostWall(w, -axis, above, -1);
    }
    for (uint c = 0; c < ColliderCount && w.count < MAX_GHOST_WALLS; c++)
    {
        // Penetration with radius h reports depth = h − d for every point closer than h to the surface.
        float3 normal; float depth; bool deep;
        if (Penetration(LoadShape(c), xi, h, normal, depth, deep)) AddGhostWall(w, normal, h - depth, (int)c);
    }
    return w;
}

// FluidGhostWalls.Mirror: the source offset y (xⱼ − xᵢ) and its velocity mirrored through every wall of the subset (a bit
// mask), in wall order; false when the source is not strictly on the fluid side of one of them, or when the subset is one
// collider's wall and the image (at xi + y) lies outside that collider.
bool MirrorGhost(GhostWalls w, uint subset, float3 xi, inout float3 y, inout float3 v)
{
    for (uint k = 0; k < w.count; k++)
    {
        if ((subset & (1u << k)) == 0) continue;
        float3 n = w.n[k];
        float s = dot(y, n) + w.d[k];
        if (!(s > 0.0)) return false;
        y -= 2.0 * s * n;
        v -= 2.0 * dot(v, n) * n;
    }
    if ((subset & (subset - 1u)) != 0u) return true;
    uint single = firstbitlow(subset);
    if (w.collider[single] < 0) return true;
    Shape s = LoadShape((uint)w.collider[single]);
    return s.type == SHAPE_PLANE || ContainsPoint(s, xi + y);
}

// SphKernels.WallDensityFraction: ∫W dV of poly6 beyond a plane at distance d, as a fraction of ρ₀.
float WallDensityFraction(float d)
{
    if (d >= SmoothingLength) return 0.0;
    float u = max(d, 0.0) / SmoothingLength;
    float u2 = u * u;
    float f = u * (1.0 + u2 * (-4.0 / 3.0 + u2 * (6.0 / 5.0 + u2 * (-4.0 / 7.0 + u2 * (1.0 / 9.0)))));
    return 0.5 - 315.0 / 256.0 * f;
}

// SphKernels.WallGradientMagnitude: |∫∇W dV| of spiky beyond a plane at distance d (1/m).
float WallGradientMagnitude(float d)
{
    if (d >= SmoothingLength) return 0.0;
    float s = 1.0 - max(d, 0.0) / SmoothingLength;
    float s4 = s * s * s * s;
    return 30.0 / SmoothingLength * (s4 / 4.0 - s4 * s / 5.0);
}

// FluidBoundary.Sample (position-based): the six faces of the domain box and the colliders (each its tangent plane at
// the closest point) as static boundary matter: the kernel's share outside the fluid and the push Σ κG(d)·n.
void SampleWalls(float3 x, out float densityFraction, out float3 push)
{
    float h = SmoothingLength, kappa = WallScale;
    float3 below = x - DomainMin;
    float3 above = DomainMax - x;
    // A periodic axis has no faces.
    below = Period > 0.0 ? FLOAT_MAX : below;
    above = Period > 0.0 ? FLOAT_MAX : above;
    float inside = 1.0;
    push = float3(0.0, 0.0, 0.0);
    densityFraction = 0.0;
    float nearest = min(min(min(below.x, below.y), below.z), min(min(above.x, above.y), above.z));
    if (nearest >= h && ColliderCount == 0) return;
    [unroll] for (int axis = 0; axis < 3; axis++)
    {
        float dBelow = below[axis], dAbove = above[axis];
        float3 n = float3(axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0);
        if (dBelow < h)
        {
            inside *= 1.0 - kappa * WallDensityFraction(dBelow);
            push += kappa * WallGradientMagnitude(dBelow) * n;
        }
        if (dAbove < h)
        {
            inside *= 1.0 - kappa * WallDensityFraction(dAbove);
            push -= kappa * WallGradientMagnitude(dAbove) * n;
        }
    }
    for (uint c = 0; c < ColliderCount; c++)
    {
        // Penetration with radius h reports depth = h − d for every point closer than h to the surface.
        float3 normal; float depth; bool deep;
        if (!Penetration(LoadShape(c), x, h, normal, depth, deep)) continue;
        float d = h - depth;
        inside *= 1.0 - kappa * WallDensityFraction(d);
        push += kappa * WallGradientMagnitude(d) * normal;
    }
    densityFraction = 1.0 - inside;
}

// FluidBoundary.ClampToDomain: keeps x a wall distance inside the box, removes the velocity into a face it touches and,
// with the faces' friction μ per axis, cancels the motion along them since start by at most Σ μ_axis × depth_axis (and the velocity by that share).
void ClampToDomain(inout float3 x, inout float3 v, float3 start)
{
    float3 lo = DomainMin + WallDistance;
    float3 hi = DomainMax - WallDistance;
    if (IsPeriodic != 0.0)
    {
        // Periodic axes wrap by whole periods (FluidConstants.Wrap) instead; the motion since start is the nearest image's.
        float3 wrapped = x;
        [unroll] for (int p = 0; p < 3; p++)
            if (Period[p] > 0.0) wrapped[p] -= Period[p] * floor((x[p] - DomainMin[p]) * InversePeriod[p]);
        start += wrapped - x;
        x = wrapped;
        lo = Period > 0.0 ? -FLOAT_MAX : lo;
        hi = Period > 0.0 ? FLOAT_MAX : hi;
    }
    float3 clamped = clamp(x, lo, hi);
    if (all(clamped == x)) return;
    float3 depth = max(lo - x, 0.0) + max(x - hi, 0.0);
    [unroll] for (int a = 0; a < 3; a++)
    {
        if (x[a] < lo[a]) v[a] = max(v[a], 0.0);
        else if (x[a] > hi[a]) v[a] = min(v[a], 0.0);
    }
    x = clamped;
    float limit = dot(DomainFriction, depth);
    if (limit > 0.0)
    {
        float3 along = float3(depth.x > 0.0 ? 0.0 : 1.0, depth.y > 0.0 ? 0.0 : 1.0, depth.z > 0.0 ? 0.0 : 1.0);
        float3 tangential = (x - start) * along;
        float slide = length(tangential);
        if (slide > 0.0)
        {
            float cut = min(1.0, limit / slide);
            x -= tangential * cut;
            v -= v * along * cut;
        }
    }
}

#endif
