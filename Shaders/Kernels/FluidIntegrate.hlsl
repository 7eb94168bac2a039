// Velocity smoothing, copies and the position update (FluidPasses.ViscosityIteration, Alignment, Advect, Move).
#ifndef SBD_FLUID_INTEGRATE_INCLUDED
#define SBD_FLUID_INTEGRATE_INCLUDED
#include "FluidWalls.hlsl"

// Copies between the velocities and the vector scratch (FluidPass.CopyAToVelocities, CopyBToVelocities,
// CopyVelocitiesToA); a velocity's w (the lifetime) stays.
[numthreads(FLUID_GROUP, 1, 1)]
void CopyAToVelocities(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    _Velocities[i] = float4(_VectorsA[i].xyz, _Velocities[i].w);
}

[numthreads(FLUID_GROUP, 1, 1)]
void CopyBToVelocities(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    _Velocities[i] = float4(_VectorsB[i].xyz, _Velocities[i].w);
}

[numthreads(FLUID_GROUP, 1, 1)]
void CopyVelocitiesToA(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    _VectorsA[i] = float4(_Velocities[i].xyz, 0.0);
}

// One Jacobi iteration of implicit viscosity from _VectorsB (fromB) or _VectorsA:
// v⁽ᵏ⁺¹⁾ᵢ = (v⁰ᵢ + hν'·Σⱼ wᵢⱼ·v⁽ᵏ⁾ⱼ) / (1 + hν'·Σⱼ wᵢⱼ), wᵢⱼ = (h − r)/(ρᵢ + ρⱼ), hν' = h·ν·2m·(Laplacian coefficient)·κ_ν;
// a no-slip face adds (ρ₀/m)·NoSlipWeight/(ρᵢ + ρ₀) to the weight only (FluidBoundary.NoSlipWeight).
float4 ViscosityIteration(uint i, bool fromB)
{
    float3 xi = _Positions[i].xyz;
    float rhoi = _Densities[i], hk = SmoothingLength, hnu = ViscosityScale;
    float3 sum = float3(0.0, 0.0, 0.0);
    bool noSlip = any(FaceNoSlip > 0.0) || (ColliderNoSlip > 0.0 && ColliderCount > 0);
    float weight = noSlip ? RestDensity / ParticleMass * NoSlipWeight(xi) / (rhoi + RestDensity) : 0.0;
    uint count = _NeighbourCounts[i], list = i * MAX_NEIGHBOURS;
    for (uint n = 0; n < count; n++)
    {
        uint j = _Neighbours[list + n];
        float r = length(PairOffset(xi, _Positions[j].xyz));
        float w = max(hk - r, 0.0) / (rhoi + _Densities[j]);
        sum += w * (fromB ? _VectorsB[j].xyz : _VectorsA[j].xyz);
        weight += w;
    }
    return float4((_Velocities[i].xyz + hnu * sum) / (1.0 + hnu * weight), 0.0);
}

[numthreads(FLUID_GROUP, 1, 1)]
void ViscosityAToB(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    _VectorsB[i] = ViscosityIteration(i, false);
}

[numthreads(FLUID_GROUP, 1, 1)]
void ViscosityBToA(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    _VectorsA[i] = ViscosityIteration(i, true);
}

// XSPH smoothing, symmetric (momentum-conserving): vᵢ += b·Σⱼ (2m/(ρᵢ + ρⱼ))·Wᵢⱼ·(vⱼ − vᵢ), into _VectorsA.
[numthreads(FLUID_GROUP, 1, 1)]
void Alignment(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    float3 xi = _Positions[i].xyz, vi = _Velocities[i].xyz;
    float rhoi = _Densities[i];
    float3 sum = float3(0.0, 0.0, 0.0);
    uint count = _NeighbourCounts[i], list = i * MAX_NEIGHBOURS;
    for (uint n = 0; n < count; n++)
    {
        uint j = _Neighbours[list + n];
        float3 r = PairOffset(xi, _Positions[j].xyz);
        float w = Poly6(dot(r, r)) / (rhoi + _Densities[j]);
        sum += w * (_Velocities[j].xyz - vi);
    }
    _VectorsA[i] = float4(vi + AlignmentBlend * 2.0 * ParticleMass * sum, 0.0);
}

// FluidPasses.Move: start position into _Previous, the speed bound (counted), x += h·v, the domain box.
void Move(uint i, float3 v)
{
    float maxSpeed = MaxSpeed, h = SubstepSeconds;
    float4 xa = _Positions[i];
    float3 x = xa.xyz;
    _Previous[i] = float4(x, 0.0);
    float speed2 = dot(v, v);
    if (speed2 > maxSpeed * maxSpeed)
    {
        v *= maxSpeed / sqrt(speed2);
        InterlockedAdd(_Stats[STAT_SPEED_CLAMPED], 1);
    }
    float3 start = x;
    x += h * v;
    ClampToDomain(x, v, start);
    _Positions[i] = float4(x, xa.w);
    _Velocities[i] = float4(v, _Velocities[i].w);
}

// Weakly compressible: the position update; a non-finite velocity marks the particle invalid for the next sort.
[numthreads(FLUID_GROUP, 1, 1)]
void Advect(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    float3 v = _Velocities[i].xyz;
    if (!IsFinite3(v))
    {
        float4 xa = _Positions[i];
        _Previous[i] = float4(xa.xyz, 0.0);
        _Velocities[i] = float4(0.0, 0.0, 0.0, _Velocities[i].w);
        _Positions[i] = float4(asfloat(0x7FC00000u).xxx, xa.w);
        return;
    }
    Move(i, v);
}

#endif
