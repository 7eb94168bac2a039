// The composite (FluidSurfacePasses.Composite): per screen pixel, the fluid's smoothed depth against the opaque scene,
// its normal and its thickness shaded by the look, written with coverage for the overlay onto the camera colour.
#ifndef SBD_FLUID_SURFACE_COMPOSITE_INCLUDED
#define SBD_FLUID_SURFACE_COMPOSITE_INCLUDED
#include "FluidSurfaceCommon.hlsl"
#include "FluidSurfaceScreenIO.hlsl"

int2 ClampToScreen(int2 p) { return clamp(p, int2(0, 0), int2(ScreenWidth, ScreenHeight) - 1); }

// Bilinear scene colour at a continuous pixel position (centres at i + 0.5).
float3 SceneColorBilinear(float2 x)
{
    float2 t = x - 0.5;
    int2 i = (int2)floor(t);
    float2 f = t - floor(t);
    float3 a = LoadSceneColor(ClampToScreen(i)).rgb, b = LoadSceneColor(ClampToScreen(i + int2(1, 0))).rgb;
    float3 c = LoadSceneColor(ClampToScreen(i + int2(0, 1))).rgb, d = LoadSceneColor(ClampToScreen(i + int2(1, 1))).rgb;
    return lerp(lerp(a, b, f.x), lerp(c, d, f.x), f.y);
}

#include "FluidSurfaceShading.hlsl"

// Thickness (m) and mean attribute at a screen position (pixel centres at i + 0.5): bilinear over the half-resolution
// texels that hold fluid, the weights renormalised so the empty background does not thin the edge; the particle radius
// where none does.
float2 ThicknessAt(float2 pixel)
{
    float2 t = pixel / 2.0 - 0.5;
    int2 i = (int2)floor(t);
    float2 f = t - floor(t);
    float2 sum = 0.0;
    float weights = 0.0;
    for (int k = 0; k < 4; k++)
    {
        int2 o = int2(k & 1, k >> 1);
        int2 q = clamp(i + o, int2(0, 0), int2(ThicknessWidth, ThicknessHeight) - 1);
        float2 v = _Thickness[(uint)q.y * ThicknessWidth + (uint)q.x];
        float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
        if (v.x > 0.0)
        {
            sum += w * v;
            weights += w;
        }
    }
    return weights > 0.0 ? sum / weights : float2(ParticleRadius, 0.0);
}

// One thread per composite pixel c: every screen pixel, or every other one each way at half resolution (its centre at
// (c + ½)·divisor on the screen; the overlay upsamples).
[numthreads(SURFACE_TILE_GROUP, SURFACE_TILE_GROUP, 1)]
void Composite(uint3 id : SV_DispatchThreadID)
{
    int2 c = (int2)id.xy;
    if (any(id.xy >= CompositeSize()))
        return;
    float2 pixel = (float2(c) + 0.5) * (float)CompositeDivisor;
    int2 s = min((int2)floor(pixel), int2(ScreenWidth, ScreenHeight) - 1);
    int2 d = min((int2)floor(pixel / (float)DepthDivisor), int2(DepthWidth, DepthHeight) - 1);
    float z = _Depth[DepthIndex(d)];
    float sceneDepth = LoadSceneEyeDepth(s);
    if (z <= 0.0 || z >= sceneDepth)
    {
        StoreFluidColor(c, float4(0.0, 0.0, 0.0, 0.0));
        return;
    }
    SurfacePixel px;
    px.pixel = pixel;
    px.eyeDepth = z;
    // A target whose pass is off is not read: the look does not use it (FluidSurfacePassList).
    px.normal = (PassFlags & SURFACE_FLAG_NORMALS) != 0u ? UnpackNormal(_Normals[DepthIndex(d)]) : float3(0.0, 0.0, 1.0);
    px.view = -normalize(PixelRay(px.pixel, ScreenFocal, ScreenCentre));
    float2 thickness = (PassFlags & SURFACE_FLAG_THICKNESS) != 0u ? ThicknessAt(pixel) : float2(ParticleRadius, 0.0);
    px.thickness = thickness.x;
    px.heat = thickness.y;
    StoreFluidColor(c, float4(Shade(px), 1.0));
}

#endif
