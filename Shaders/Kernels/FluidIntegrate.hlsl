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

// One ghost of MirroredGhosts at tangential distance² tangential2 and normal distance normal from i: weight σ·(h − r)/(ρᵢ + ρⱼ)
// times factor (1 + t/d) and the pair scale (FluidPasses.MirroredGhost).
void MirroredGhost(float tangential2, float normal, float factor, float shareOverDensity, float pair, inout float weight, inout float moment)
{
    float h = SmoothingLength;
    float r2 = tangential2 + normal * normal;
    if (!(r2 < h * h)) return;
    float w = shareOverDensity * (h - sqrt(r2));
    moment += w * r2;
    weight += pair * factor * w;
}

// FluidPasses.MirroredGhosts: i and its neighbours mirrored through a no-slip plane at distance d (unit normal n into the
// fluid, share σ; Morris et al. 1997), the ghost of j with velocity −vᵢ·tⱼ/d, tⱼ = d + (xⱼ − xᵢ)·n > 0: adds σwᵢ_g·(1 + tⱼ/d)
// to i's weight and σwᵢ_g·rᵢ_g² to its second moment. si is 0 in a substep's first iteration.
void MirroredGhosts(uint i, float3 xi, float rhoi, float si, float3 n, float d, float share, bool fromB, inout float weight, inout float moment)
{
    d = max(d, 1e-3 * SmoothingLength);
    bool first = !(si > 0.0);
    MirroredGhost(0.0, 2.0 * d, 2.0, share / (2.0 * rhoi), first ? 1.0 : si, weight, moment);
    uint count = _NeighbourCounts[i], list = i * MAX_NEIGHBOURS;
    for (uint m = 0; m < count; m++)
    {
        uint j = _Neighbours[list + m];
        float3 rij = PairOffset(xi, _Positions[j].xyz);
        float along = -dot(rij, n);
        float t = d + along;
        if (!(t > 0.0)) continue;
        float pair = first ? 1.0 : 0.5 * (si + (fromB ? _VectorsB[j].w : _VectorsA[j].w));
        MirroredGhost(dot(rij, rij) - along * along, d + t, 1.0 + t / d, share / (rhoi + _Densities[j]), pair, weight, moment);
    }
}

// One Jacobi iteration of implicit viscosity from _VectorsB (fromB) or _VectorsA (FluidPasses.ViscosityIteration):
// v⁽ᵏ⁺¹⁾ᵢ = (v⁰ᵢ + hν'·Σⱼ sᵢⱼwᵢⱼ·v⁽ᵏ⁾ⱼ) / (1 + hν'·(Σⱼ sᵢⱼwᵢⱼ + gᵢ)), wᵢⱼ = (h − r)/(ρᵢ + ρⱼ), hν' = h·ν·2m·(Laplacian
// coefficient)·κ_ν, sᵢⱼ = (sᵢ + sⱼ)/2 with the renormalizations s in the iterates' w (0 from CopyVelocitiesToA: the first
// iteration computes sᵢ = FluidConstants.ViscosityRenormalization and weighs every pair by it); gᵢ the no-slip walls' ghosts.
float4 ViscosityIteration(uint i, bool fromB)
{
    float3 xi = _Positions[i].xyz;
    float rhoi = _Densities[i], hk = SmoothingLength, hnu = ViscosityScale;
    float si = fromB ? _VectorsB[i].w : _VectorsA[i].w;
    bool first = !(si > 0.0);
    float3 sum = float3(0.0, 0.0, 0.0);
    float weight = 0.0, moment = 0.0;
    uint count = _NeighbourCounts[i], list = i * MAX_NEIGHBOURS;
    for (uint n = 0; n < count; n++)
    {
        uint j = _Neighbours[list + n];
        float3 rij = PairOffset(xi, _Positions[j].xyz);
        float r2 = dot(rij, rij);
        float w = max(hk - sqrt(r2), 0.0) / (rhoi + _Densities[j]);
        moment += w * r2;
        float4 vj = fromB ? _VectorsB[j] : _VectorsA[j];
        w *= first ? 1.0 : 0.5 * (si + vj.w);
        sum += w * vj.xyz;
        weight += w;
    }
    [unroll] for (int a = 0; a < 3; a++)
    {
        float share = FaceNoSlip[a];
        if (!(share > 0.0)) continue;
        float below = xi[a] - DomainMin[a], above = DomainMax[a] - xi[a];
        float3 axis = float3(0.0, 0.0, 0.0);
        axis[a] = 1.0;
        if (below < hk) MirroredGhosts(i, xi, rhoi, first ? 0.0 : si, axis, below, share, fromB, weight, moment);
        if (above < hk) MirroredGhosts(i, xi, rhoi, first ? 0.0 : si, -axis, above, share, fromB, weight, moment);
    }
    if (ColliderNoSlip > 0.0)
        for (uint c = 0; c < ColliderCount; c++)
        {
            // Penetration with radius h reports depth = h − d for every point closer than h to the surface.
            float3 normal; float depth; bool deep;
            if (Penetration(LoadShape(c), xi, hk, normal, depth, deep))
                MirroredGhosts(i, xi, rhoi, first ? 0.0 : si, normal, hk - depth, ColliderNoSlip, fromB, weight, moment);
        }
    if (first)
    {
        // FluidConstants.ViscosityRenormalization.
        si = clamp(ViscosityMomentScale / moment, 1.0 / MAX_VISCOSITY_RENORMALIZATION, MAX_VISCOSITY_RENORMALIZATION);
        sum *= si;
        weight *= si;
    }
    return float4((_Velocities[i].xyz + hnu * sum) / (1.0 + hnu * weight), si);
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
