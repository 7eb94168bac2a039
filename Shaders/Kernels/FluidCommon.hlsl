// The buffers, constants and small functions every fluid kernel shares: a port of the data layout of
// Runtime/Solvers/Fluids (FluidParticles, FluidScratch, FluidConstants). Vectors are float4 (no float3 in structured
// buffers): a particle's age rides in the position's w and its lifetime in the velocity's w.
#ifndef SBD_FLUID_COMMON_INCLUDED
#define SBD_FLUID_COMMON_INCLUDED

// Threads per group of every particle kernel; FluidComputeLayout.ThreadGroupSize on the C# side (checked at load).
#define FLUID_GROUP 256
// Neighbour list capacity per particle (FluidScratch.MaxNeighbours).
#define MAX_NEIGHBOURS 64
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

// Constants, computed on the CPU (FluidComputeConstants.Set).
float4 _GridOrigin;      // xyz grid origin (m), w 1 / cell size (1/m)
uint4 _GridDims;         // xyz cells along each axis, w cell count (= the dead key)
float4 _DomainMin;       // xyz (m), w wall distance (m)
float4 _DomainMax;       // xyz (m), w wall scale κ
float4 _Gravity;         // xyz (m/s²), w position-based artificial pressure scale k·λ₁ (m²)
float4 _Kernel;          // h (m), h² (m²), poly6 coefficient, spiky gradient coefficient
float4 _Kernel2;         // cohesion coefficient, cohesion offset, viscosity Laplacian coefficient, gradient correction κ∇
float4 _Material;        // particle mass (kg), ρ₀ (kg/m³), Tait stiffness B (Pa), max density ratio
float4 _Motion;          // substep h (s), max speed (m/s), 2·α·c₀·h (artificial viscosity), position-based relaxation ε
float4 _Cohesion;        // cohesion weight (1/s²), separation weight (1/s²), spacing (m), surface tension γ
float4 _Smoothing;       // viscosity h·ν·2m·(Laplacian coefficient), alignment blend 1 − e^(−rate·h), step dt (s), bulk-viscous scale (FluidConstants.BulkPressureScale)
uint4 _Flags;            // x weakly compressible, y flocking, z Akinci, w unused
uint4 _Counts;           // x capacity, y spawn count, z scan element count, w scan data offset
uint4 _Scan;             // x index of the level's block totals in _ScanSums, yzw unused
uint4 _ShapeCounts;      // x colliders, y drains (in _Shapes), zw unused
float4 _Colliding;       // x collider friction μ, yzw the domain faces' μ per axis
float4 _Period;          // xyz the domain's extent on its periodic axes (m), 0 on the others; w 1 when any axis is periodic
float4 _InversePeriod;   // xyz 1 / the period on the periodic axes (1/m), 0 on the others; w unused
float4 _NoSlip;          // xyz no-slip share of the domain faces per axis (0 on periodic axes); w the colliders' share
float4 _Renormalization; // x gradient trace scale −κ∇·m·C_spiky, y the walls' trace scale κ_T, z largest renormalization, w unused

bool IsFinite3(float3 v) { return all(abs(v) <= FLOAT_MAX); }

uint LiveCount() { return _Stats[STAT_LIVE]; }

// FluidConstants.Offset: xᵢ − xⱼ, between the nearest images on the periodic axes (NearestImageOffset.Apply).
float3 PairOffset(float3 xi, float3 xj)
{
    float3 d = xi - xj;
    if (_Period.w != 0.0) d -= _Period.xyz * round(d * _InversePeriod.xyz);
    return d;
}

// FluidGrid.Cell: the cell of x, clamped into the grid (clamped in float first).
int3 CellOf(float3 x)
{
    float3 c = (x - _GridOrigin.xyz) * _GridOrigin.w;
    return int3(clamp(floor(c), 0.0, float3(_GridDims.xyz) - 1.0));
}

uint KeyOf(int3 cell) { return (uint)(cell.x + (int)_GridDims.x * (cell.y + (int)_GridDims.y * cell.z)); }

// SphKernels.SpikyGradientScale: ∇W = scale·r (1/m⁵); zero at r = 0 and r ≥ h.
float SpikyGradientScale(float r)
{
    if (!(r < _Kernel.x) || !(r > 0.0)) return 0.0;
    float d = _Kernel.x - r;
    return _Kernel.w * d * d / r;
}

// SphKernels.Poly6 from r².
float Poly6(float r2)
{
    if (!(r2 < _Kernel.y)) return 0.0;
    float d = _Kernel.y - r2;
    return _Kernel.z * d * d * d;
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
