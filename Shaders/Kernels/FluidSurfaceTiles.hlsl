// Tile binning of the particles (FluidSurfacePasses.CountTiles / ScanTiles / BinParticles): each particle is listed in
// every 16 × 16-pixel tile of the depth target its sphere may cover, so the splats gather per pixel without atomics.
#ifndef SBD_FLUID_SURFACE_TILES_INCLUDED
#define SBD_FLUID_SURFACE_TILES_INCLUDED
#include "FluidSurfaceCommon.hlsl"

// Tiles a particle covers: xy first tile, zw last tile; x > z when it is culled (behind the near plane or off screen).
int4 TileRect(uint particle)
{
    float3 c = ToView(_Particles[particle].xyz);
    float z = -c.z;
    float r = ParticleRadius;
    if (!(z - r > NearPlane) || any(abs(c) > 3.0e38))
        return int4(1, 0, 0, 0);
    float2 ex = SphereExtent(c.x, z, r, DepthFocal.x, DepthCentre.x);
    float2 ey = SphereExtent(c.y, z, r, DepthFocal.y, DepthCentre.y);
    if (ex.y < 0.0 || ey.y < 0.0 || ex.x > (float)DepthWidth || ey.x > (float)DepthHeight)
        return int4(1, 0, 0, 0);
    int2 lo = (int2)floor(max(float2(ex.x, ey.x), 0.0)) / SURFACE_TILE;
    int2 hi = (int2)floor(min(float2(ex.y, ey.y), float2(DepthWidth, DepthHeight) - 1.0)) / SURFACE_TILE;
    return int4(lo, hi);
}

[numthreads(SURFACE_SCAN_GROUP, 1, 1)]
void ClearTiles(uint3 id : SV_DispatchThreadID)
{
    uint tiles = TilesX * TilesY;
    if (id.x < SURFACE_STAT_COUNT)
        _SurfaceStats[id.x] = 0;
    if (id.x < tiles)
        _TileCounts[id.x] = 0;
}

[numthreads(SURFACE_PARTICLE_GROUP, 1, 1)]
void CountTiles(uint3 id : SV_DispatchThreadID)
{
    if (id.x >= ParticleCount)
        return;
    int4 rect = TileRect(id.x);
    if (rect.x > rect.z)
        return;
    InterlockedAdd(_SurfaceStats[SURFACE_STAT_DRAWN], 1u);
    for (int ty = rect.y; ty <= rect.w; ty++)
        for (int tx = rect.x; tx <= rect.z; tx++)
            InterlockedAdd(_TileCounts[(uint)ty * TilesX + (uint)tx], 1u);
}

// Exclusive scan of the tile counts in one group: each thread sums a run of consecutive tiles, the group scans the
// run totals, each thread writes its run. The counts become the write cursors of BinParticles.
groupshared uint gs_RunTotals[SURFACE_SCAN_GROUP];

[numthreads(SURFACE_SCAN_GROUP, 1, 1)]
void ScanTiles(uint3 id : SV_GroupThreadID)
{
    uint tiles = TilesX * TilesY;
    uint run = (tiles + SURFACE_SCAN_GROUP - 1) / SURFACE_SCAN_GROUP;
    uint first = id.x * run;
    uint last = min(first + run, tiles);
    uint sum = 0;
    for (uint t = first; t < last; t++)
        sum += _TileCounts[t];
    gs_RunTotals[id.x] = sum;
    GroupMemoryBarrierWithGroupSync();
    // Hillis–Steele inclusive scan of the run totals.
    for (uint offset = 1; offset < SURFACE_SCAN_GROUP; offset <<= 1)
    {
        uint add = id.x >= offset ? gs_RunTotals[id.x - min(offset, id.x)] : 0u;
        GroupMemoryBarrierWithGroupSync();
        gs_RunTotals[id.x] += add;
        GroupMemoryBarrierWithGroupSync();
    }
    uint start = gs_RunTotals[id.x] - sum;
    for (uint s = first; s < last; s++)
    {
        uint count = _TileCounts[s];
        _TileStart[s] = start;
        _TileCounts[s] = start;
        start += count;
    }
    if (id.x == SURFACE_SCAN_GROUP - 1)
    {
        _TileStart[tiles] = gs_RunTotals[id.x];
        _SurfaceStats[SURFACE_STAT_ENTRIES] = gs_RunTotals[id.x];
    }
}

[numthreads(SURFACE_PARTICLE_GROUP, 1, 1)]
void BinParticles(uint3 id : SV_DispatchThreadID)
{
    if (id.x >= ParticleCount)
        return;
    int4 rect = TileRect(id.x);
    if (rect.x > rect.z)
        return;
    for (int ty = rect.y; ty <= rect.w; ty++)
        for (int tx = rect.x; tx <= rect.z; tx++)
        {
            uint slot;
            InterlockedAdd(_TileCounts[(uint)ty * TilesX + (uint)tx], 1u, slot);
            if (slot < TileCapacity)
                _TileEntries[slot] = id.x;
            else
                InterlockedAdd(_SurfaceStats[SURFACE_STAT_DROPPED], 1u);
        }
}

#endif
