// Depth smoothing (FluidSurfacePasses.NarrowRange / Bilateral / CurvatureFlow), one pass per dispatch from _DepthIn to
// _DepthOut. Pixels without fluid (depth 0) stay empty and are never sampled, so silhouettes do not bleed.
#ifndef SBD_FLUID_SURFACE_FILTERS_INCLUDED
#define SBD_FLUID_SURFACE_FILTERS_INCLUDED
#include "FluidSurfaceCommon.hlsl"

// Filter radius on screen for a pixel at eye depth z: the world radius times f / z, clamped to the largest radius;
// the Gaussian's σ is half of it.
float FilterPixels(float z) { return min(FilterRadius * DepthFocal.x / z, MaxFilterPixels); }

// One separable pass along axis a. Narrow-range (Truong & Yuksel 2018, §4): samples more than μ behind the centre
// belong to another surface and are skipped, samples more than μ in front are clamped to z₀ − μ, the rest weigh by a
// Gaussian in screen distance. Bilateral: every sample weighs by a Gaussian in screen distance times a Gaussian in
// depth difference (σ = μ).
float SeparablePass(int2 p, int2 a, bool narrow)
{
    float z0 = _DepthIn[DepthIndex(p)];
    if (z0 <= 0.0)
        return 0.0;
    float radius = FilterPixels(z0);
    int n = (int)ceil(radius);
    float inverseSigma2 = 4.0 / max(radius * radius, 1.0e-6);
    float mu = DepthRange;
    float sum = 0.0, weights = 0.0;
    for (int i = -n; i <= n; i++)
    {
        int2 q = p + a * i;
        if (!InDepth(q))
            continue;
        float z = _DepthIn[DepthIndex(q)];
        if (z <= 0.0)
            continue;
        float w = exp(-0.5 * (float)(i * i) * inverseSigma2);
        if (narrow)
        {
            if (z > z0 + mu)
                continue;
            z = max(z, z0 - mu);
        }
        else
        {
            float dz = (z - z0) / mu;
            w *= exp(-0.5 * dz * dz);
        }
        sum += w * z;
        weights += w;
    }
    return sum / weights;
}

[numthreads(SURFACE_TILE_GROUP, SURFACE_TILE_GROUP, 1)]
void NarrowRangeX(uint3 id : SV_DispatchThreadID)
{
    if (InDepth((int2)id.xy))
        _DepthOut[DepthIndex((int2)id.xy)] = SeparablePass((int2)id.xy, int2(1, 0), true);
}

[numthreads(SURFACE_TILE_GROUP, SURFACE_TILE_GROUP, 1)]
void NarrowRangeY(uint3 id : SV_DispatchThreadID)
{
    if (InDepth((int2)id.xy))
        _DepthOut[DepthIndex((int2)id.xy)] = SeparablePass((int2)id.xy, int2(0, 1), true);
}

[numthreads(SURFACE_TILE_GROUP, SURFACE_TILE_GROUP, 1)]
void BilateralX(uint3 id : SV_DispatchThreadID)
{
    if (InDepth((int2)id.xy))
        _DepthOut[DepthIndex((int2)id.xy)] = SeparablePass((int2)id.xy, int2(1, 0), false);
}

[numthreads(SURFACE_TILE_GROUP, SURFACE_TILE_GROUP, 1)]
void BilateralY(uint3 id : SV_DispatchThreadID)
{
    if (InDepth((int2)id.xy))
        _DepthOut[DepthIndex((int2)id.xy)] = SeparablePass((int2)id.xy, int2(0, 1), false);
}

// A neighbour's depth, or 0 outside the target.
float DepthAt(int2 q) { return InDepth(q) ? _DepthIn[DepthIndex(InDepth(q) ? q : int2(0, 0))] : 0.0; }

// One explicit step of screen-space curvature flow (van der Laan, Green & Sainz 2009, eqs. 3–9) with C = 1/f:
// D = C²z_x² + C²z_y² + C⁴z², E_x = ½ z_x ∂D/∂x − z_xx D, H = C (E_x + E_y) / (2 D^{3/2}), z ← z − ε H. For a nearly flat
// surface H ≈ −(z_xx + z_yy) / (2 C z), so ε = 2 λ C z makes the step z + λ (z_xx + z_yy): stable for λ ≤ ¼. A pixel
// at a silhouette (a neighbour empty or more than μ away in depth) keeps its depth.
[numthreads(SURFACE_TILE_GROUP, SURFACE_TILE_GROUP, 1)]
void CurvatureFlow(uint3 id : SV_DispatchThreadID)
{
    int2 p = (int2)id.xy;
    if (!InDepth(p))
        return;
    float z = _DepthIn[DepthIndex(p)];
    float zl = DepthAt(p + int2(-1, 0)), zr = DepthAt(p + int2(1, 0));
    float zd = DepthAt(p + int2(0, -1)), zu = DepthAt(p + int2(0, 1));
    float mu = DepthRange;
    bool edge = z <= 0.0 || zl <= 0.0 || zr <= 0.0 || zd <= 0.0 || zu <= 0.0
        || abs(zl - z) > mu || abs(zr - z) > mu || abs(zd - z) > mu || abs(zu - z) > mu;
    if (edge)
    {
        _DepthOut[DepthIndex(p)] = z;
        return;
    }
    float zul = DepthAt(p + int2(-1, 1)), zur = DepthAt(p + int2(1, 1));
    float zdl = DepthAt(p + int2(-1, -1)), zdr = DepthAt(p + int2(1, -1));
    bool corners = zul > 0.0 && zur > 0.0 && zdl > 0.0 && zdr > 0.0;
    float c = 1.0 / DepthFocal.x;
    float c2 = c * c;
    float zx = 0.5 * (zr - zl), zy = 0.5 * (zu - zd);
    float zxx = zr - 2.0 * z + zl, zyy = zu - 2.0 * z + zd;
    float zxy = corners ? 0.25 * (zur - zul - zdr + zdl) : 0.0;
    float d = c2 * (zx * zx + zy * zy) + c2 * c2 * z * z;
    float dDx = 2.0 * c2 * (zx * zxx + zy * zxy) + 2.0 * c2 * c2 * z * zx;
    float dDy = 2.0 * c2 * (zx * zxy + zy * zyy) + 2.0 * c2 * c2 * z * zy;
    float ex = 0.5 * zx * dDx - zxx * d;
    float ey = 0.5 * zy * dDy - zyy * d;
    float h = c * (ex + ey) / (2.0 * d * sqrt(d));
    _DepthOut[DepthIndex(p)] = z - 2.0 * CurvatureStep * c * z * h;
}

#endif
