// Depth and thickness splats (FluidSurfacePasses.SplatDepth / SplatThickness): one group per tile; the group loads the
// tile's particles in chunks into groupshared memory and every thread intersects its pixels' rays with them. A pixel
// keeps the nearest hit (depth) or the sum of the chords (thickness, in integer quanta so the sum does not depend on
// the order the tile lists were filled in). No atomics, so the images are the same bits on every run.
#ifndef SBD_FLUID_SURFACE_SPLAT_INCLUDED
#define SBD_FLUID_SURFACE_SPLAT_INCLUDED
#include "FluidSurfaceCommon.hlsl"

#define SURFACE_CHUNK (SURFACE_TILE_GROUP * SURFACE_TILE_GROUP)
groupshared float4 gs_Spheres[SURFACE_CHUNK];  // xyz view centre (m), w normalised attribute

// Loads entries [base, base + SURFACE_CHUNK) of the tile into gs_Spheres; returns how many are valid.
uint LoadChunk(uint flat, uint base, uint end)
{
    uint n = min(end - base, (uint)SURFACE_CHUNK);
    if (flat < n)
    {
        float4 p = _Particles[_TileEntries[base + flat]];
        gs_Spheres[flat] = float4(ToView(p.xyz), saturate((p.w - ColdAttribute) * InverseAttributeSpan));
    }
    GroupMemoryBarrierWithGroupSync();
    return n;
}

// First and one-past-last entry of a tile, clamped to the entries that fit.
uint2 TileRange(uint2 tile)
{
    uint t = tile.y * TilesX + tile.x;
    return uint2(min(_TileStart[t], TileCapacity), min(_TileStart[t + 1], TileCapacity));
}

[numthreads(SURFACE_TILE_GROUP, SURFACE_TILE_GROUP, 1)]
void SplatDepth(uint3 group : SV_GroupID, uint3 thread : SV_GroupThreadID)
{
    uint flat = thread.y * SURFACE_TILE_GROUP + thread.x;
    uint2 range = TileRange(group.xy);
    int2 origin = (int2)group.xy * SURFACE_TILE + (int2)thread.xy * 2;
    float near[4] = { 3.0e38, 3.0e38, 3.0e38, 3.0e38 };
    float3 rays[4];
    for (int k = 0; k < 4; k++)
        rays[k] = PixelRay(float2(origin + int2(k & 1, k >> 1)) + 0.5, DepthFocal, DepthCentre);
    for (uint base = range.x; base < range.y; base += SURFACE_CHUNK)
    {
        uint n = LoadChunk(flat, base, range.y);
        for (uint i = 0; i < n; i++)
        {
            float3 c = gs_Spheres[i].xyz;
            for (int k = 0; k < 4; k++)
            {
                float2 hit = RaySphere(rays[k], c, ParticleRadiusSquared);
                if (hit.y > 0.0)
                    near[k] = min(near[k], hit.x);
            }
        }
        GroupMemoryBarrierWithGroupSync();
    }
    for (int k = 0; k < 4; k++)
    {
        int2 p = origin + int2(k & 1, k >> 1);
        if (InDepth(p))
            _Depth[DepthIndex(p)] = near[k] < 3.0e38 ? near[k] : 0.0;
    }
}

[numthreads(SURFACE_TILE_GROUP, SURFACE_TILE_GROUP, 1)]
void SplatThickness(uint3 group : SV_GroupID, uint3 thread : SV_GroupThreadID)
{
    uint flat = thread.y * SURFACE_TILE_GROUP + thread.x;
    uint2 range = TileRange(group.xy);
    int side = (int)ThicknessPixelsPerThread;
    int2 origin = (int2)group.xy * (SURFACE_TILE_GROUP * side) + (int2)thread.xy * side;
    uint sums[4] = { 0u, 0u, 0u, 0u };
    uint attributes[4] = { 0u, 0u, 0u, 0u };
    float3 rays[4];
    for (int k = 0; k < 4; k++)
        rays[k] = PixelRay(float2(origin + int2(k & 1, k >> 1)) + 0.5, ThicknessFocal, ThicknessCentre);
    float inverseQuantum = 1.0 / ThicknessQuantum;
    for (uint base = range.x; base < range.y; base += SURFACE_CHUNK)
    {
        uint n = LoadChunk(flat, base, range.y);
        for (uint i = 0; i < n; i++)
        {
            float4 s = gs_Spheres[i];
            for (int k = 0; k < side * side; k++)
            {
                float2 hit = RaySphere(rays[k], s.xyz, ParticleRadiusSquared);
                sums[k] += (uint)round(hit.y * inverseQuantum);
                attributes[k] += (uint)round(hit.y * s.w * inverseQuantum);
            }
        }
        GroupMemoryBarrierWithGroupSync();
    }
    for (int k = 0; k < side * side; k++)
    {
        int2 p = origin + int2(k & 1, k >> 1);
        if (p.x < (int)ThicknessWidth && p.y < (int)ThicknessHeight)
            _Thickness[(uint)p.y * ThicknessWidth + (uint)p.x] =
                float2(sums[k] * ThicknessQuantum, sums[k] > 0u ? (float)attributes[k] / (float)sums[k] : 0.0);
    }
}

#endif
