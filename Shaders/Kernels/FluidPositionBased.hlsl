// Position-based fluids (Macklin & Müller 2013): FluidPasses.Predict, Lambda, Correction, ApplyCorrection and
// VelocityFromPositions.
#ifndef SBD_FLUID_POSITION_BASED_INCLUDED
#define SBD_FLUID_POSITION_BASED_INCLUDED
#include "FluidIntegrate.hlsl"

// v += h·g, x⁰ = x, x += h·v, kept in the domain box.
[numthreads(FLUID_GROUP, 1, 1)]
void Predict(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    Move(i, _Velocities[i].xyz + SubstepSeconds * Gravity);
}

// λᵢ = −Cᵢ / (Σₖ |∇ₖCᵢ|² + ε), Cᵢ = ρᵢ/ρ₀ − 1 clamped at 0 (eqs. 1–11), the wall term included.
[numthreads(FLUID_GROUP, 1, 1)]
void Lambda(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    float invRho0 = 1.0 / RestDensity;
    float mOverRho0 = ParticleMass * invRho0;
    float constraint = _Densities[i] * invRho0 - 1.0;
    if (!(constraint > 0.0)) { _Pressures[i] = 0.0; return; }
    float3 xi = _Positions[i].xyz;
    float wall; float3 push;
    SampleWalls(xi, wall, push);
    float3 gradI = -push;
    float sumSq = 0.0;
    uint count = _NeighbourCounts[i], list = i * MAX_NEIGHBOURS;
    for (uint n = 0; n < count; n++)
    {
        float3 rij = PairOffset(xi, _Positions[_Neighbours[list + n]].xyz);
        float3 g = mOverRho0 * SpikyGradientScale(length(rij)) * rij;
        gradI += g;
        sumSq += dot(g, g);
    }
    _Pressures[i] = -constraint / (sumSq + dot(gradI, gradI) + Relaxation);
}

// (h² − Δq²)/h² of the artificial pressure's reference distance Δq = 0.2h (FluidPasses.ArtificialPressureQ).
#define ARTIFICIAL_PRESSURE_Q 0.96

// Δxᵢ = (m/ρ₀)·Σⱼ (λᵢ + λⱼ + s_corr)·∇W(xᵢ − xⱼ) − λᵢ·Σ_walls G(d)·n (eqs. 12–14) into _VectorsA, s_corr = −k·λ₁·(W(r)/W(Δq))⁴
// with k·λ₁ = ArtificialPressureScale (FluidConstants.ArtificialPressureScale).
[numthreads(FLUID_GROUP, 1, 1)]
void Correction(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    float mOverRho0 = ParticleMass / RestDensity;
    float artificial = ArtificialPressureScale, h2 = SmoothingLengthSquared, inverseQ = 1.0 / (ARTIFICIAL_PRESSURE_Q * SmoothingLengthSquared);
    float3 xi = _Positions[i].xyz;
    float li = _Pressures[i];
    float3 dx = float3(0.0, 0.0, 0.0);
    int idI = (int)_Extras[i].y;
    uint count = _NeighbourCounts[i], list = i * MAX_NEIGHBOURS;
    for (uint n = 0; n < count; n++)
    {
        uint j = _Neighbours[list + n];
        float3 rij = PairOffset(xi, _Positions[j].xyz);
        float lij = li + _Pressures[j];
        if (artificial > 0.0)
        {
            // (W(r)/W(Δq))⁴ = ((h² − r²)/(h² − Δq²))¹²
            float t = max(h2 - dot(rij, rij), 0.0) * inverseQ;
            float t3 = t * t * t, t6 = t3 * t3;
            lij -= artificial * (t6 * t6);
        }
        if (lij == 0.0) continue;
        float r = length(rij);
        if (r > 1e-6 * SmoothingLength) dx += lij * SpikyGradientScale(r) * rij;
        else dx += lij * SpikyGradientCoefficient * SmoothingLengthSquared * CoincidentDirection(idI, (int)_Extras[j].y);
    }
    dx *= mOverRho0;
    if (li != 0.0)
    {
        float wall; float3 push;
        SampleWalls(xi, wall, push);
        dx -= li * push;
    }
    _VectorsA[i] = float4(dx, 0.0);
}

// xᵢ += Δxᵢ, kept in the domain box.
[numthreads(FLUID_GROUP, 1, 1)]
void ApplyCorrection(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    float4 xa = _Positions[i];
    float3 x = xa.xyz + _VectorsA[i].xyz;
    float3 v = _Velocities[i].xyz;
    ClampToDomain(x, v, _Previous[i].xyz);
    _Positions[i] = float4(x, xa.w);
}

// vᵢ = (xᵢ − x⁰ᵢ)/h (the nearest image's offset across a periodic face).
[numthreads(FLUID_GROUP, 1, 1)]
void VelocityFromPositions(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    float invH = 1.0 / SubstepSeconds;
    _Velocities[i] = float4(PairOffset(_Positions[i].xyz, _Previous[i].xyz) * invH, _Velocities[i].w);
}

#endif
