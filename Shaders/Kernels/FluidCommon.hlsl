// The buffers, constants and small functions every fluid kernel shares: a port of the data layout of
// Runtime/Solvers/Fluids (FluidParticles, FluidScratch, FluidConstants). Vectors are float4 (no float3 in structured
// buffers): a particle's age rides in the position's w and its lifetime in the velocity's w.
#ifndef SBD_FLUID_COMMON_INCLUDED
#define SBD_FLUID_COMMON_INCLUDED

#include "FluidComputeConstants.hlsl"

// Threads per group of every particle kernel; FluidComputeLayout.ThreadGroupSize on the C# side (checked at load).
#define FLUID_GROUP 256
// Neighbour list capacity per particle (FluidScratch.MaxNeighbours).
#define MAX_NEIGHBOURS 64
// Largest viscosity renormalization, and smallest its inverse (FluidConstants.MaxViscosityRenormalization).
#define MAX_VISCOSITY_RENORMALIZATION 1.1
#define FLOAT_MAX 3.402823466e+38

// _Stats slots (FluidComputeLayout.Stat* on the C# side).
#define STAT_LIVE 0
#define STAT_KILLED 1
#define STAT_EXPIRED 2
#define STAT_INVALID 3
#define STAT_SPEED_CLAMPED 4
#define STAT_OVER_COMPRESSED 5
#define STAT_NEIGHBOUR_OVERFLOW 6
#define STAT_MAX_DENSITY_RATIO 7
#define STAT_MAX_SPEED_SQUARED 8
#define STAT_CONTACTS 9
// Totals since the particles were uploaded (ClearStats keeps them): removals the CPU reads back asynchronously.
#define STAT_TOTAL_KILLED 10
#define STAT_TOTAL_EXPIRED 11
#define STAT_TOTAL_INVALID 12
// Position-based: the particles' highest height along −g and the lowest as a maximum of its mirror (BeginStep).
#define STAT_MAX_HEIGHT 13
#define STAT_MIN_HEIGHT_MIRRORED 14
#define STAT_COUNT 15

// Particle state (FluidParticles): ping-ponged by the permutation of the sort.
RWStructuredBuffer<float4> _Positions;   // xyz position (m), w age (s)
RWStructuredBuffer<float4> _Velocities;  // xyz velocity (m/s), w lifetime (s; 0 = forever, < 0 = marked by a drain)
RWStructuredBuffer<uint2> _Extras;       // x attribute (float bits), y id
RWStructuredBuffer<float4> _Previous;    // start-of-substep position (position-based)
RWStructuredBuffer<float4> _PositionsOut;
RWStructuredBuffer<float4> _VelocitiesOut;
RWStructuredBuffer<uint2> _ExtrasOut;
RWStructuredBuffer<float4> _PreviousOut;

// Scratch (FluidScratch).
RWStructuredBuffer<uint> _Keys;
RWStructuredBuffer<uint> _Ranks;
RWStructuredBuffer<uint> _CellStart;     // cells + 2 entries: counts, then (scanned) first sorted slot of each key
RWStructuredBuffer<uint> _ScanSums;      // the block totals of every level of the scan above the cells
RWStructuredBuffer<uint> _Order;
RWStructuredBuffer<float> _Densities;
RWStructuredBuffer<float> _Pressures;    // p/ρ² (weakly compressible) or λ (position-based)
RWStructuredBuffer<uint> _Neighbours;    // MAX_NEIGHBOURS per particle
RWStructuredBuffer<uint> _NeighbourCounts;
RWStructuredBuffer<float4> _VectorsA;
RWStructuredBuffer<float4> _VectorsB;
RWStructuredBuffer<uint> _Stats;         // STAT_* counters; STAT_LIVE is the live particle count
RWStructuredBuffer<uint> _Args;          // indirect dispatch arguments: ceil(live / FLUID_GROUP), 1, 1
RWStructuredBuffer<float4> _Shapes;      // colliders, then drains: 5 float4 each (FluidColliders.hlsl)
RWStructuredBuffer<float4> _RenderParticles; // xyz position, w attribute for the fluid renderer; NaN beyond the live ones

// Per-dispatch arguments (set before each dispatch that reads them, FluidComputeStep).
uint4 _Counts;           // x capacity, y spawn count, z scan element count, w scan data offset
uint4 _Scan;             // x index of the level's block totals in _ScanSums, yzw unused

bool IsFinite3(float3 v) { return all(abs(v) <= FLOAT_MAX); }

uint LiveCount() { return _Stats[STAT_LIVE]; }

// FluidConstants.Offset: xᵢ − xⱼ, between the nearest images on the periodic axes (NearestImageOffset.Apply).
float3 PairOffset(float3 xi, float3 xj)
{
    float3 d = xi - xj;
    if (IsPeriodic != 0.0) d -= Period * round(d * InversePeriod);
    return d;
}

// FluidGrid.Cell: the cell of x, clamped into the grid (clamped in float first).
int3 CellOf(float3 x)
{
    float3 c = (x - GridOrigin) * InverseCellSize;
    return int3(clamp(floor(c), 0.0, float3(GridDimensions) - 1.0));
}

uint KeyOf(int3 cell) { return (uint)(cell.x + GridDimensions.x * (cell.y + GridDimensions.y * cell.z)); }

// SphKernels.SpikyGradientScale: ∇W = scale·r (1/m⁵); zero at r = 0 and r ≥ h.
float SpikyGradientScale(float r)
{
    if (!(r < SmoothingLength) || !(r > 0.0)) return 0.0;
    float d = SmoothingLength - r;
    return SpikyGradientCoefficient * d * d / r;
}

// SphKernels.Poly6 from r².
float Poly6(float r2)
{
    if (!(r2 < SmoothingLengthSquared)) return 0.0;
    float d = SmoothingLengthSquared - r2;
    return Poly6Coefficient * d * d * d;
}

// FluidPasses.CoincidentDirection: a unit vector fixed by an unordered id pair, negated when the ids swap.
float3 CoincidentDirection(int idI, int idJ)
{
    int lo = min(idI, idJ), hi = max(idI, idJ);
    uint hash = (uint)lo * 0x9E3779B1u ^ ((uint)hi + 0x7F4A7C15u) * 0x85EBCA77u;
    hash ^= hash >> 15;
    hash *= 0xC2B2AE3Du;
    hash ^= hash >> 13;
    float z = (hash & 0xFFFF) / 32767.5 - 1.0;
    float phi = (hash >> 16) * (2.0 * 3.14159265358979 / 65536.0);
    float rxy = sqrt(max(0.0, 1.0 - z * z));
    float3 d = float3(rxy * cos(phi), rxy * sin(phi), z);
    return idI <= idJ ? d : -d;
}

#endif
