// Where the composite reads the scene (screen pixels p) and writes its result (composite pixels c). In Unity: the
// camera's opaque colour and depth textures and a random-write colour texture (row 0 at the top where the platform says
// so). With SBD_SCREEN_BUFFERS (the lavapipe harness): structured buffers of the same pixels, row 0 at the bottom, scene
// depth already as eye depth. Everything else in the composite is the same code in both.
#ifndef SBD_FLUID_SURFACE_SCREEN_IO_INCLUDED
#define SBD_FLUID_SURFACE_SCREEN_IO_INCLUDED
#include "FluidSurfaceCommon.hlsl"

#if defined(SBD_SCREEN_BUFFERS)
StructuredBuffer<float4> _SceneColor;      // linear RGB
StructuredBuffer<float> _SceneEyeDepth;    // eye depth (m) of the opaque scene
RWStructuredBuffer<float4> _FluidColor;    // rgb fluid colour, a coverage (0 or 1)

float4 LoadSceneColor(int2 p) { return _SceneColor[(uint)p.y * ScreenWidth + (uint)p.x]; }
float LoadSceneEyeDepth(int2 p) { return _SceneEyeDepth[(uint)p.y * ScreenWidth + (uint)p.x]; }
void StoreFluidColor(int2 c, float4 colour) { _FluidColor[(uint)c.y * CompositeSize().x + (uint)c.x] = colour; }
#else
Texture2D<float4> _SceneColor;             // _CameraOpaqueTexture
Texture2D<float> _SceneDepth;              // _CameraDepthTexture (device depth)
RWTexture2D<float4> _FluidColor;

// Row p.y of a target of this height, counted from the top where the platform's textures start there.
int2 TexelOf(int2 p, uint height) { return FlipY != 0u ? int2(p.x, (int)height - 1 - p.y) : p; }
float4 LoadSceneColor(int2 p) { return _SceneColor.Load(int3(TexelOf(p, ScreenHeight), 0)); }
float LoadSceneEyeDepth(int2 p) { return 1.0 / (SceneDepthScale * _SceneDepth.Load(int3(TexelOf(p, ScreenHeight), 0)) + SceneDepthOffset); }
void StoreFluidColor(int2 c, float4 colour) { _FluidColor[TexelOf(c, CompositeSize().y)] = colour; }
#endif

#endif
