// Density and neighbour lists (FluidPasses.Density, DensityFromNeighbours, GhostDensity, StoreDensity) over the 25 rows of the
// 5×5×5 cells around a particle (NeighbourRows), in the same order as the CPU so the sums round alike.
#ifndef SBD_FLUID_DENSITY_INCLUDED
#define SBD_FLUID_DENSITY_INCLUDED
#include "FluidWalls.hlsl"

// NeighbourRows.AxisRanges: the cells within 2 of cell coordinate u along an axis of n cells as two inclusive ranges
// (x..y, z..w; an empty one ends below its start): on a periodic axis of `period` cells the part beyond an end wraps.
int4 AxisRanges(float u, int n, bool periodic, float period)
{
    if (!periodic)
    {
        int c = min((int)u, n - 1);
        return int4(max(c - 2, 0), min(c + 2, n - 1), 0, -1);
    }
    float lo = u - 2.0, hi = u + 2.0;
    int4 r = int4(max((int)floor(lo), 0), min((int)floor(hi), n - 1), 0, -1);
    if (lo < 0.0)
    {
        r.z = clamp((int)floor(lo + period), r.y + 1, n);
        r.w = n - 1;
    }
    else if (hi >= period)
    {
        r.z = 0;
        r.w = min((int)floor(hi - period), r.x - 1);
    }
    return r;
}

// FluidPasses.GhostDensity (weakly compressible): the images of the particle and of its listed neighbours through every
// set of walls add (h² − r²)³ and (h − r)²·r, and with bulk (vᵢ − v_g)·xᵢ_g·(h² − r²)² with the image's mirrored velocity.
void GhostDensity(GhostWalls walls, float3 xi, float3 vi, uint listStart, uint found, bool bulk,
    inout float sum, inout float spiky, inout float divergence)
{
    float h = SmoothingLength, h2 = SmoothingLengthSquared;
    uint subsets = (1u << walls.count) - 1u;
    for (uint subset = 1; subset <= subsets; subset++)
    for (int m = -1; m < (int)found; m++)
    {
        uint j = m < 0 ? 0 : _Neighbours[listStart + (uint)m];
        float3 y = m < 0 ? float3(0.0, 0.0, 0.0) : -PairOffset(xi, _Positions[j].xyz);
        float3 v = m < 0 ? vi : (bulk ? _Velocities[j].xyz : float3(0.0, 0.0, 0.0));
        if (!MirrorGhost(walls, subset, xi, y, v)) continue;
        float q = h2 - (y.x * y.x + y.y * y.y + y.z * y.z);
        if (!(q > 0.0)) continue;
        sum += q * q * q;
        float distance = sqrt(h2 - q);
        float hr = h - distance;
        spiky += hr * hr * distance;
        if (bulk) divergence -= dot(vi - v, y) * (q * q);
    }
}

// ρ = m·(poly6 coefficient)·Σ(h² − r²)³ (weakly compressible: the ghosts included), plus for position-based fluids
// ρ₀·(the walls' share), stored and counted against the bound.
float StoreDensity(uint i, float3 xi, float kernelSum)
{
    float wall = 0.0; float3 push;
    if (WeaklyCompressible == 0) SampleWalls(xi, wall, push);
    float rho = ParticleMass * Poly6Coefficient * kernelSum + RestDensity * wall;
    _Densities[i] = rho;
    float ratio = rho / RestDensity;
    InterlockedMax(_Stats[STAT_MAX_DENSITY_RATIO], asuint(max(ratio, 0.0)));
    if (ratio > MaxDensityRatio) InterlockedAdd(_Stats[STAT_OVER_COMPRESSED], 1);
    return rho;
}

// FluidConstants.GradientRenormalization: 3 / the corrected gradient trace (the ghosts included), clamped to 1/limit … limit.
float GradientRenormalization(float spikySum, float rho)
{
    float trace = GradientTraceScale * spikySum / rho;
    return clamp(3.0 / trace, 1.0 / MaxGradientRenormalization, MaxGradientRenormalization);
}

// Müller 2003 eq. 3 with the neighbour list; weakly compressible adds the Tait pressure (Becker & Teschner 2007,
// eq. 6) of the density clamped to at least ρ₀ and the bulk-viscous pressure, stored as κᵢ·p/ρ² with κᵢ the
// gradient renormalization.
[numthreads(FLUID_GROUP, 1, 1)]
void Density(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    float3 xi = _Positions[i].xyz;
    float h2 = SmoothingLengthSquared;
    int3 c = CellOf(xi);
    int3 d = GridDimensions;
    int x0 = max(c.x - 2, 0), x1 = min(c.x + 2, d.x - 1);
    int y0 = max(c.y - 2, 0), y1 = min(c.y + 2, d.y - 1);
    int z0 = max(c.z - 2, 0), z1 = min(c.z + 2, d.z - 1);
    uint listStart = i * MAX_NEIGHBOURS, found = 0, overflow = 0;
    float sum = 0.0, divergence = 0.0, spiky = 0.0;
    bool tait = WeaklyCompressible != 0;
    bool bulk = WeaklyCompressible != 0 && BulkPressureScale > 0.0;
    float3 vi = bulk ? _Velocities[i].xyz : float3(0.0, 0.0, 0.0);
    // The cells within h along each axis as two ranges each (the second empty unless a periodic axis wraps).
    int4 xs = int4(x0, x1, 0, -1), ys = int4(y0, y1, 0, -1), zs = int4(z0, z1, 0, -1);
    if (IsPeriodic != 0.0)
    {
        float3 extent = max(DomainMax - DomainMin, 1.0 / InverseCellSize) * InverseCellSize;
        float3 u = clamp((xi - GridOrigin) * InverseCellSize, 0.0, extent);
        xs = AxisRanges(u.x, d.x, Period.x > 0.0, extent.x);
        ys = AxisRanges(u.y, d.y, Period.y > 0.0, extent.y);
        zs = AxisRanges(u.z, d.z, Period.z > 0.0, extent.z);
    }
    for (int zp = 0; zp < 2; zp++)
    for (int z = zp == 0 ? zs.x : zs.z; z <= (zp == 0 ? zs.y : zs.w); z++)
    for (int yp = 0; yp < 2; yp++)
    for (int y = yp == 0 ? ys.x : ys.z; y <= (yp == 0 ? ys.y : ys.w); y++)
    for (int xp = 0; xp < 2; xp++)
    {
        int xa = xp == 0 ? xs.x : xs.z, xb = xp == 0 ? xs.y : xs.w;
        if (xb < xa) continue;
        int row = d.x * (y + d.y * z);
        uint begin = _CellStart[row + xa], end = _CellStart[row + xb + 1];
        for (uint j = begin; j < end; j++)
        {
            float3 r = PairOffset(xi, _Positions[j].xyz);
            float q = h2 - (r.x * r.x + r.y * r.y + r.z * r.z);
            if (!(q > 0.0)) continue;
            sum += q * q * q;
            if (j == i) continue;
            if (tait)
            {
                float distance = sqrt(h2 - q);
                float hr = SmoothingLength - distance;
                spiky += hr * hr * distance;
            }
            if (bulk) divergence += dot(vi - _Velocities[j].xyz, r) * (q * q);
            if (found < MAX_NEIGHBOURS) _Neighbours[listStart + found++] = j;
            else overflow++;
        }
    }
    _NeighbourCounts[i] = found;
    if (overflow > 0) InterlockedAdd(_Stats[STAT_NEIGHBOUR_OVERFLOW], overflow);
    if (tait)
    {
        GhostWalls walls = NearWalls(xi);
        if (walls.count > 0) GhostDensity(walls, xi, vi, listStart, found, bulk, sum, spiky, divergence);
    }
    float rho = StoreDensity(i, xi, sum);
    if (tait)
    {
        float rho0 = RestDensity;
        float rc = max(rho, rho0);
        float qr = rc / rho0;
        float q2 = qr * qr;
        float pressure = TaitStiffness * (q2 * q2 * q2 * qr - 1.0);
        // Bulk-viscous p_b = −ρ₀ζ·∇·vᵢ (FluidConstants.BulkPressureScale); the total stays ≥ 0.
        if (bulk) pressure = max(pressure - BulkPressureScale * divergence / rho, 0.0);
        _Pressures[i] = GradientRenormalization(spiky, rho) * pressure / (rc * rc);
    }
}

// The density again from the lists of the last Density pass (position-based iterations).
[numthreads(FLUID_GROUP, 1, 1)]
void DensityFromNeighbours(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    float3 xi = _Positions[i].xyz;
    float h2 = SmoothingLengthSquared;
    float sum = h2 * h2 * h2;
    uint count = _NeighbourCounts[i], list = i * MAX_NEIGHBOURS;
    for (uint n = 0; n < count; n++)
    {
        float3 r = PairOffset(xi, _Positions[_Neighbours[list + n]].xyz);
        float q = h2 - (r.x * r.x + r.y * r.y + r.z * r.z);
        if (q > 0.0) sum += q * q * q;
    }
    StoreDensity(i, xi, sum);
}

#endif
