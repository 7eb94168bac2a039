// Normals from the smoothed depth (FluidSurfacePasses.Normals): view-space positions of the pixel and its neighbours;
// along each axis the one-sided difference with the smaller depth step, so a silhouette does not tilt the normal
// towards the background; a side with no usable neighbour faces the camera.
#ifndef SBD_FLUID_SURFACE_NORMALS_INCLUDED
#define SBD_FLUID_SURFACE_NORMALS_INCLUDED
#include "FluidSurfaceCommon.hlsl"

float3 ViewPositionAt(int2 p, float z) { return PixelRay(float2(p) + 0.5, DepthFocal, DepthCentre) * z; }

// The tangent along axis a at p (depth z, position v), or a camera-facing step when neither side is usable.
float3 Tangent(int2 p, int2 a, float z, float3 v)
{
    int2 qf = p + a, qb = p - a;
    float zf = InDepth(qf) ? _Depth[DepthIndex(InDepth(qf) ? qf : p)] : 0.0;
    float zb = InDepth(qb) ? _Depth[DepthIndex(InDepth(qb) ? qb : p)] : 0.0;
    float mu = DepthRange;
    bool useF = zf > 0.0 && abs(zf - z) <= mu;
    bool useB = zb > 0.0 && abs(zb - z) <= mu;
    if (useF && (!useB || abs(zf - z) <= abs(zb - z)))
        return ViewPositionAt(qf, zf) - v;
    if (useB)
        return v - ViewPositionAt(qb, zb);
    return float3(a.x, a.y, 0.0) * (z / DepthFocal.x);
}

[numthreads(SURFACE_TILE_GROUP, SURFACE_TILE_GROUP, 1)]
void Normals(uint3 id : SV_DispatchThreadID)
{
    int2 p = (int2)id.xy;
    if (!InDepth(p))
        return;
    float z = _Depth[DepthIndex(p)];
    if (z <= 0.0)
    {
        _Normals[DepthIndex(p)] = PackNormal(float3(0.0, 0.0, 1.0));
        return;
    }
    float3 v = ViewPositionAt(p, z);
    float3 n = cross(Tangent(p, int2(1, 0), z, v), Tangent(p, int2(0, 1), z, v));
    float len = length(n);
    _Normals[DepthIndex(p)] = PackNormal(len > 0.0 ? n / len : float3(0.0, 0.0, 1.0));
}

#endif
