// The constants of the fluid surface kernels, one constant buffer uploaded whole per fluid and camera frame: the HLSL
// side of Runtime/Solvers/Rendering/FluidSurfaceConstants.cs (same fields, same order, same byte offsets; a test checks
// it). Laid out under HLSL constant-buffer packing: every row is 16 bytes, of four scalars, two float2s, a float4, or a
// float3 that starts the row and a scalar that closes it. Pixel rows count from the bottom of the screen.
#ifndef SBD_FLUID_SURFACE_CONSTANTS_INCLUDED
#define SBD_FLUID_SURFACE_CONSTANTS_INCLUDED

cbuffer FluidSurfaceConstants
{
    float4 ViewRow0;                    // world → view, rows 0..2: xyz rotation, w translation (m)
    float4 ViewRow1;
    float4 ViewRow2;
    float2 DepthFocal;                  // focal length x, y of the depth target (pixels)
    float2 DepthCentre;                 // principal point x, y of the depth target (pixels)
    float2 ThicknessFocal;              // the same of the thickness target
    float2 ThicknessCentre;
    float2 ScreenFocal;                 // the same of the full-resolution screen
    float2 ScreenCentre;
    uint DepthWidth;                    // depth target (pixels)
    uint DepthHeight;
    uint TilesX;                        // tiles of the depth target along x, y
    uint TilesY;
    uint ThicknessWidth;                // thickness target (pixels)
    uint ThicknessHeight;
    uint ScreenWidth;                   // screen (pixels)
    uint ScreenHeight;
    uint ParticleCount;                 // particles drawn this frame
    uint TileCapacity;                  // tile entries that fit; more are dropped and counted
    uint ThicknessPixelsPerThread;      // thickness pixels per thread side in a tile (1 or 2)
    uint PassFlags;                     // the targets the composite reads besides depth (SURFACE_FLAG_*)
    uint DepthDivisor;                  // depth target resolution: 1 full, 2 half
    uint LookModel;                     // FluidLookModel: 0 lit, 1 flat, 2 thickness-tinted, 3 toon
    uint FlipY;                         // 1 when texture row 0 is the top of the screen
    uint CompositeDivisor;              // composite resolution: 1 full, 2 half
    float ParticleRadius;               // r (m)
    float ParticleRadiusSquared;        // r² (m²)
    float NearPlane;                    // (m)
    float ThicknessQuantum;             // m per unit of summed chord: r / FluidSurfaceConstants.QuantaPerRadius
    float FilterRadius;                 // world radius of the smoothing (m)
    float MaxFilterPixels;              // largest smoothing radius (pixels)
    float DepthRange;                   // μ: neighbours farther in depth belong to another surface (m)
    float CurvatureStep;                // λ of the curvature flow
    float3 BodyColour;                  // the look's colour (linear rgb)
    float Scattering;                   // share of the absorbed light replaced by the lit body colour
    float3 Absorption;                  // Beer–Lambert absorption per channel (1/m)
    float FresnelF0;                    // Schlick's F0
    float3 Emission;                    // emission at full heat (linear rgb)
    float Refraction;                   // background shift per metre of thickness
    float SpecularPower;                // Blinn–Phong exponent
    float Specular;                     // highlight strength
    float Opacity;                      // unlit looks' opacity
    float ToonBands;                    // toon look's bands of n·l
    float3 OutlineColour;               // toon look's outline (linear rgb)
    float OutlineThreshold;             // outline where n·v is below this
    float3 LightDirection;              // unit vector toward the light (view space)
    float MaxRefractionPixels;          // largest background shift (pixels)
    float3 LightColour;                 // linear rgb
    float ColdAttribute;                // the attribute (temperature, K) that maps to heat 0
    float3 SkyZenith;                   // sky straight up (linear rgb)
    float InverseAttributeSpan;         // 1 / (hot − cold attribute): heat = (attribute − cold) · this
    float3 SkyHorizon;                  // sky at the horizon (linear rgb)
    float SceneDepthScale;              // eye depth = 1 / (SceneDepthScale · device depth + SceneDepthOffset):
    float3 ViewUp;                      // world up in view space
    float SceneDepthOffset;             // Unity's _ZBufferParams.z and .w of the camera depth texture
};

#endif
