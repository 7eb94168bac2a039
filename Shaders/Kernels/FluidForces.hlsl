// Accelerations and the velocity update (FluidPasses.SurfaceNormals, Forces), into _VectorsA.
#ifndef SBD_FLUID_FORCES_INCLUDED
#define SBD_FLUID_FORCES_INCLUDED
#include "FluidWalls.hlsl"

// Akinci et al. 2013 surface normals nᵢ = h·Σⱼ (m/ρⱼ)·∇W(xᵢ − xⱼ) (eq. 4) into _VectorsB.
[numthreads(FLUID_GROUP, 1, 1)]
void SurfaceNormals(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    float3 xi = _Positions[i].xyz;
    float m = ParticleMass;
    float3 n = float3(0.0, 0.0, 0.0);
    uint count = _NeighbourCounts[i], list = i * MAX_NEIGHBOURS;
    for (uint a = 0; a < count; a++)
    {
        uint j = _Neighbours[list + a];
        float3 rij = PairOffset(xi, _Positions[j].xyz);
        n += (m / _Densities[j]) * SpikyGradientScale(length(rij)) * rij;
    }
    _VectorsB[i] = float4(SmoothingLength * n, 0.0);
}

// FluidPasses.MirroredPressure, one wall: the tangential part of the pressure term from i's neighbours mirrored through a
// plane at distance d (unit normal n into the fluid), the ghost of j carrying pⱼ; before the factor −m·C_spiky·κ∇.
float3 MirroredPressure(uint i, float3 xi, float pi, float3 n, float d)
{
    float H = SmoothingLength;
    d = max(d, 0.0);
    float3 sum = float3(0.0, 0.0, 0.0);
    uint count = _NeighbourCounts[i], list = i * MAX_NEIGHBOURS;
    for (uint m = 0; m < count; m++)
    {
        uint j = _Neighbours[list + m];
        float3 rij = PairOffset(xi, _Positions[j].xyz);
        float along = -dot(rij, n);
        float t = d + along;
        if (!(t > 0.0)) continue;
        float3 tangential = rij + along * n;
        float normal = d + t;
        float r2 = dot(tangential, tangential) + normal * normal;
        if (!(r2 < H * H)) continue;
        float r = sqrt(r2);
        float hr = H - r;
        sum += ((pi + _Pressures[j]) * hr * hr / r) * tangential;
    }
    return sum;
}

// FluidPasses.MirroredPressure: the domain's faces (none on a periodic axis) and the colliders' tangent planes within h.
float3 MirroredPressures(uint i, float3 xi, float pi)
{
    float H = SmoothingLength;
    float3 sum = float3(0.0, 0.0, 0.0);
    [unroll] for (int a = 0; a < 3; a++)
    {
        if (Period[a] > 0.0) continue;
        float below = xi[a] - DomainMin[a], above = DomainMax[a] - xi[a];
        float3 axis = float3(0.0, 0.0, 0.0);
        axis[a] = 1.0;
        if (below < H) sum += MirroredPressure(i, xi, pi, axis, below);
        if (above < H) sum += MirroredPressure(i, xi, pi, -axis, above);
    }
    for (uint c = 0; c < ColliderCount; c++)
    {
        // Penetration with radius h reports depth = h − d for every point closer than h to the surface.
        float3 normal; float depth; bool deep;
        if (Penetration(LoadShape(c), xi, H, normal, depth, deep))
            sum += MirroredPressure(i, xi, pi, normal, H - depth);
    }
    return sum;
}

// Weakly compressible: gravity, the symmetric pressure term with Monaghan's artificial viscosity (Müller 2003, eq. 10;
// Becker & Teschner 2007, eq. 11), the walls' push (Akinci 2012, eq. 9) and their ghosts' tangential share (MirroredPressures); (position-based: CohesionForces). Then flocking or Akinci cohesion. Returns vᵢ + h·aᵢ.
float4 Acceleration(uint i, bool pressureAndGravity)
{
    float h = SubstepSeconds, H = SmoothingLength, H2 = SmoothingLengthSquared;
    float m = ParticleMass, rho0 = RestDensity;
    float3 xi = _Positions[i].xyz;
    float3 vi = _Velocities[i].xyz;
    float3 a = float3(0.0, 0.0, 0.0);
    uint count = _NeighbourCounts[i], list = i * MAX_NEIGHBOURS;
    int idI = (int)_Extras[i].y;
    if (pressureAndGravity)
    {
        float alphaCh = ArtificialViscosity, eta2 = 0.01 * H2, minDistance = 1e-6 * H;
        float pi = _Pressures[i], rhoi = _Densities[i];
        float3 sum = float3(0.0, 0.0, 0.0);
        for (uint n = 0; n < count; n++)
        {
            uint j = _Neighbours[list + n];
            float3 rij = PairOffset(xi, _Positions[j].xyz);
            float r2 = dot(rij, rij);
            float r = sqrt(r2);
            float scale = pi + _Pressures[j];
            // Πᵢⱼ for approaching pairs only.
            float approach = min(dot(vi - _Velocities[j].xyz, rij), 0.0);
            scale -= alphaCh * approach / ((rhoi + _Densities[j]) * (r2 + eta2));
            if (r > minDistance)
            {
                float hr = max(H - r, 0.0);
                sum += (scale * hr * hr / r) * rij;
            }
            else
                sum += scale * H2 * CoincidentDirection(idI, (int)_Extras[j].y);
        }
        sum += MirroredPressures(i, xi, pi);
        sum *= -m * SpikyGradientCoefficient * GradientCorrection;
        float wall, trace; float3 push;
        SampleWalls(xi, wall, push, trace);
        a += Gravity + sum + rho0 * pi * push;
    }
    if (Flocking != 0)
    {
        // Flocking: toward the kernel-weighted neighbour centre, away from neighbours closer than the spacing.
        float3 centre = float3(0.0, 0.0, 0.0), separation = float3(0.0, 0.0, 0.0);
        float weight = 0.0, spacing = ParticleSpacing;
        for (uint n = 0; n < count; n++)
        {
            float3 rij = PairOffset(xi, _Positions[_Neighbours[list + n]].xyz);
            float3 xj = xi - rij;
            float r2 = dot(rij, rij);
            float w = Poly6(r2);
            centre += w * xj;
            weight += w;
            float r = sqrt(r2);
            if (r < spacing && r > 0.0) separation += (spacing - r) / r * rij;
        }
        if (weight > 0.0) a += CohesionWeight * (centre / weight - xi);
        a += SeparationWeight * separation;
    }
    if (Akinci != 0)
    {
        // Akinci et al. 2013, eqs. 1–5: aᵢ = −γ·Σⱼ Kᵢⱼ·(m·C(r)·r̂ + (nᵢ − nⱼ)), Kᵢⱼ = 2ρ₀/(ρᵢ + ρⱼ).
        float3 ni = _VectorsB[i].xyz;
        float rhoi = _Densities[i];
        float3 sum = float3(0.0, 0.0, 0.0);
        for (uint n = 0; n < count; n++)
        {
            uint j = _Neighbours[list + n];
            float3 rij = PairOffset(xi, _Positions[j].xyz);
            float r = length(rij);
            if (!(r < H)) continue;
            float kij = 2.0 * rho0 / (rhoi + _Densities[j]);
            float3 cohesion = float3(0.0, 0.0, 0.0);
            if (r > 0.0)
            {
                float t = (H - r) * r;
                float c3 = t * t * t;
                float spline = CohesionCoefficient * (2.0 * r > H ? c3 : 2.0 * c3 - CohesionOffset);
                cohesion = m * spline / r * rij;
            }
            sum += kij * (cohesion + (ni - _VectorsB[j].xyz));
        }
        a -= SurfaceTension * sum;
    }
    return float4(vi + h * a, 0.0);
}

[numthreads(FLUID_GROUP, 1, 1)]
void Forces(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    _VectorsA[i] = Acceleration(i, true);
}

// Cohesion only (position-based).
[numthreads(FLUID_GROUP, 1, 1)]
void CohesionForces(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    _VectorsA[i] = Acceleration(i, false);
}

#endif
