// Where the composite reads the scene and writes its result. In Unity: the camera's opaque colour and depth textures
// and a random-write colour texture (row 0 at the top where the platform says so). With SBD_SCREEN_BUFFERS (the
// lavapipe harness): structured buffers of the same pixels, row 0 at the bottom, scene depth already as eye depth.
// Everything else in the composite is the same code in both.
#ifndef SBD_FLUID_SURFACE_SCREEN_IO_INCLUDED
#define SBD_FLUID_SURFACE_SCREEN_IO_INCLUDED
#include "FluidSurfaceCommon.hlsl"

#if defined(SBD_SCREEN_BUFFERS)
StructuredBuffer<float4> _SceneColor;      // linear RGB
StructuredBuffer<float> _SceneEyeDepth;    // eye depth (m) of the opaque scene
RWStructuredBuffer<float4> _FluidColor;    // rgb fluid colour, a coverage (0 or 1)

float4 LoadSceneColor(int2 p) { return _SceneColor[(uint)p.y * _OtherSizes.z + (uint)p.x]; }
float LoadSceneEyeDepth(int2 p) { return _SceneEyeDepth[(uint)p.y * _OtherSizes.z + (uint)p.x]; }
void StoreFluidColor(int2 p, float4 c) { _FluidColor[(uint)p.y * _OtherSizes.z + (uint)p.x] = c; }
#else
Texture2D<float4> _SceneColor;             // _CameraOpaqueTexture
Texture2D<float> _SceneDepth;              // _CameraDepthTexture (device depth)
RWTexture2D<float4> _FluidColor;

int2 TexelOf(int2 p) { return _Composite.z != 0u ? int2(p.x, (int)_OtherSizes.w - 1 - p.y) : p; }
float4 LoadSceneColor(int2 p) { return _SceneColor.Load(int3(TexelOf(p), 0)); }
float LoadSceneEyeDepth(int2 p) { return 1.0 / (_SceneDepthParams.z * _SceneDepth.Load(int3(TexelOf(p), 0)) + _SceneDepthParams.w); }
void StoreFluidColor(int2 p, float4 c) { _FluidColor[TexelOf(p)] = c; }
#endif

#endif
