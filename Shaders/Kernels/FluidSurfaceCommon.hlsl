// The buffers, constants and small functions every fluid surface kernel shares: a port of
// Runtime/Solvers/Rendering (FluidSurfaceCamera, FluidSurfaceConstants, FluidSurfacePasses). Screen targets are
// structured buffers (row-major, row 0 at the bottom), so every pass runs the same on lavapipe and on each target.
#ifndef SBD_FLUID_SURFACE_COMMON_INCLUDED
#define SBD_FLUID_SURFACE_COMMON_INCLUDED
#include "FluidSurfaceConstants.hlsl"

// Threads per group of the particle kernels (FluidSurfaceLayout.ParticleGroup).
#define SURFACE_PARTICLE_GROUP 64
// Pixels per tile side, in the depth target (FluidSurfaceLayout.TileSize); tile kernels run 8 × 8 threads.
#define SURFACE_TILE 16
#define SURFACE_TILE_GROUP 8
// Threads of the one-group tile scan (FluidSurfaceLayout.ScanGroup).
#define SURFACE_SCAN_GROUP 256
// Largest filter radius (pixels); FluidSurfaceSettings.MaxFilterPixelsLimit.
#define SURFACE_MAX_FILTER 32

// _SurfaceStats slots (FluidSurfaceLayout.Stat*).
#define SURFACE_STAT_ENTRIES 0   // tile entries the particles need this frame
#define SURFACE_STAT_DROPPED 1   // entries beyond the capacity (not drawn this frame)
#define SURFACE_STAT_DRAWN 2     // particles in front of the near plane and on screen
#define SURFACE_STAT_COUNT 4

// PassFlags bits: the targets the composite reads besides depth (FluidSurfacePassList.Flags); a pass that is off
// was not dispatched this frame, so its target holds nothing to read.
#define SURFACE_FLAG_THICKNESS 1u
#define SURFACE_FLAG_NORMALS 2u

StructuredBuffer<float4> _Particles;        // xyz world position (m), w attribute (temperature, K)
RWStructuredBuffer<uint> _TileCounts;       // particles per tile, then the write cursor of each tile
RWStructuredBuffer<uint> _TileStart;        // tiles + 1 entries: first entry of each tile; the last is the total
RWStructuredBuffer<uint> _TileEntries;      // particle indices, grouped by tile
RWStructuredBuffer<uint> _SurfaceStats;     // SURFACE_STAT_*
RWStructuredBuffer<float> _Depth;           // eye depth (m) per depth pixel, 0 where there is no fluid
RWStructuredBuffer<float> _DepthIn;         // a filter's input
RWStructuredBuffer<float> _DepthOut;        // a filter's output
RWStructuredBuffer<float2> _Thickness;      // x thickness (m), y mean attribute (0 cold – 1 hot) per thickness pixel
RWStructuredBuffer<uint> _Normals;          // octahedral view-space normal, 16 + 16 bits, per depth pixel

float3 ToView(float3 world)
{
    float4 p = float4(world, 1.0);
    return float3(dot(ViewRow0, p), dot(ViewRow1, p), dot(ViewRow2, p));
}

// The direction (not normalised, z = −1) of the ray through pixel (px, py) of a target with this focal length and
// principal point.
float3 PixelRay(float2 pixel, float2 focal, float2 centre)
{
    return float3((pixel.x - centre.x) / focal.x, (pixel.y - centre.y) / focal.y, -1.0);
}

// The ray from the eye along d (z = −1) meets the sphere (view centre c, radius² r2): eye depth of the first hit and
// chord length (m), both 0 on a miss. The perpendicular offset is formed as a vector difference, not as
// |c|² − (d·c)², so a far camera loses no digits (FluidSurfacePasses.RaySphere).
float2 RaySphere(float3 d, float3 c, float r2)
{
    float len = length(d);
    float3 u = d / len;
    float b = dot(u, c);
    float3 off = c - b * u;
    float h2 = r2 - dot(off, off);
    if (h2 <= 0.0 || b <= 0.0)
        return float2(0.0, 0.0);
    float h = sqrt(h2);
    return float2((b - h) / len, 2.0 * h);
}

// Pixel range [lo, hi] along one axis covered by a sphere at view (a, −z) of radius r: the tangents from the eye,
// (a z ± r √(a² + z² − r²)) / (z² − r²), times the focal length, plus the principal point.
float2 SphereExtent(float a, float z, float r, float f, float c)
{
    float s = r * sqrt(max(a * a + z * z - r * r, 0.0));
    float inv = 1.0 / (z * z - r * r);
    return float2(c + f * (a * z - s) * inv, c + f * (a * z + s) * inv);
}

// Octahedral packing of a unit vector into 16 + 16 bits (FluidSurfacePasses.PackNormal).
uint PackNormal(float3 n)
{
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    float2 o = n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * float2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    uint2 q = (uint2)round(saturate(o * 0.5 + 0.5) * 65535.0);
    return q.x | (q.y << 16);
}

float3 UnpackNormal(uint packed)
{
    float2 o = float2(packed & 0xFFFFu, packed >> 16) / 65535.0 * 2.0 - 1.0;
    float3 n = float3(o, 1.0 - abs(o.x) - abs(o.y));
    float t = saturate(-n.z);
    n.x += n.x >= 0.0 ? -t : t;
    n.y += n.y >= 0.0 ? -t : t;
    return normalize(n);
}

// Composite pixels: the screen divided by the composite divisor, rounded up (FluidSurfaceComposite.Size).
uint2 CompositeSize() { return (uint2(ScreenWidth, ScreenHeight) + CompositeDivisor - 1u) / CompositeDivisor; }

uint DepthIndex(int2 p) { return (uint)p.y * DepthWidth + (uint)p.x; }
bool InDepth(int2 p) { return p.x >= 0 && p.y >= 0 && p.x < (int)DepthWidth && p.y < (int)DepthHeight; }

#endif
