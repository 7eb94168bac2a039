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

// FluidPasses.GhostPressure: the images of i and of its neighbours through every set of walls, each carrying its source's
// κⱼpⱼ/ρⱼ² extrapolated hydrostatically where pⱼ > 0, max(0, κⱼpⱼ/ρⱼ² + g·(x_g − xⱼ)/ρⱼ), its density and its mirrored velocity; before
// the factor −m·C_spiky·κ∇.
float3 GhostPressure(GhostWalls walls, uint i, float3 xi, float3 vi, float pi, float rhoi, float alphaCh)
{
    float H = SmoothingLength, H2 = SmoothingLengthSquared;
    float eta2 = 0.01 * H2, minDistance = 1e-6 * H;
    float3 sum = float3(0.0, 0.0, 0.0);
    uint count = _NeighbourCounts[i], list = i * MAX_NEIGHBOURS;
    uint subsets = (1u << walls.count) - 1u;
    for (uint subset = 1; subset <= subsets; subset++)
    for (int m = -1; m < (int)count; m++)
    {
        uint j = m < 0 ? i : _Neighbours[list + (uint)m];
        float3 source = m < 0 ? float3(0.0, 0.0, 0.0) : -PairOffset(xi, _Positions[j].xyz);
        float3 y = source;
        float3 v = m < 0 ? vi : _Velocities[j].xyz;
        if (!MirrorGhost(walls, subset, xi, y, v)) continue;
        float r2 = dot(y, y);
        if (!(r2 < H2)) continue;
        float r = sqrt(r2);
        if (!(r > minDistance)) continue;
        float rhoj = m < 0 ? rhoi : _Densities[j];
        // Extrapolated only from a source under pressure (a lone particle rests on the wall through its contact).
        float pj = m < 0 ? pi : _Pressures[j];
        float ghost = pj > 0.0 ? max(pj + dot(Gravity, y - source) / max(rhoj, RestDensity), 0.0) : 0.0;
        float3 rig = -y;
        float scale = pi + ghost;
        float approach = min(dot(vi - v, rig), 0.0);
        scale -= alphaCh * approach / ((rhoi + rhoj) * (r2 + eta2));
        float hr = H - r;
        sum += (scale * hr * hr / r) * rig;
    }
    return sum;
}

// Weakly compressible: gravity, the symmetric pressure term with Monaghan's artificial viscosity (Müller 2003, eq. 10;
// Becker & Teschner 2007, eq. 11) over the neighbours and the walls' ghosts (GhostPressure); (position-based: CohesionForces). Then flocking or Akinci cohesion. Returns vᵢ + h·aᵢ.
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
        GhostWalls walls = NearWalls(xi);
        if (walls.count > 0) sum += GhostPressure(walls, i, xi, vi, pi, rhoi, alphaCh);
        sum *= -m * SpikyGradientCoefficient * GradientCorrection;
        a += Gravity + sum;
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
