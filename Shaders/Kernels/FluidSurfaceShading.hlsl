// The looks (FluidSurfacePasses.Shade, FluidLook): lit (refraction, Beer–Lambert absorption, Schlick Fresnel, sky
// reflection, Blinn–Phong highlight, emission by temperature) and unlit (flat, thickness-tinted, toon). Needs
// SceneColorBilinear, LoadSceneColor and LoadSceneEyeDepth (FluidSurfaceComposite.hlsl).
#ifndef SBD_FLUID_SURFACE_SHADING_INCLUDED
#define SBD_FLUID_SURFACE_SHADING_INCLUDED

struct SurfacePixel
{
    float2 pixel;     // screen position (pixel centre)
    float eyeDepth;   // m
    float3 normal;    // view space, towards the viewer
    float3 view;      // unit vector from the surface to the eye (view space)
    float thickness;  // m
    float heat;       // mean attribute, 0 cold – 1 hot
};

// Sky seen along the view-space direction r: horizon to zenith by elevation, half the horizon below it.
float3 Sky(float3 r)
{
    float e = dot(r, ViewUp);
    return e >= 0.0 ? lerp(SkyHorizon, SkyZenith, e) : SkyHorizon * (1.0 + 0.5 * e);
}

float3 ShadeLit(SurfacePixel px)
{
    float3 n = px.normal;
    float3 l = LightDirection;
    // Refraction: the background seen through the fluid shifts along the normal by the thickness (Snell's law's
    // screen-space stand-in), clamped; where the shifted point is nearer than the fluid, the unshifted one is used.
    float2 offset = n.xy * (Refraction * px.thickness * ScreenFocal.x / px.eyeDepth);
    float len = length(offset);
    offset *= len > MaxRefractionPixels ? MaxRefractionPixels / len : 1.0;
    float2 q = px.pixel + offset;
    int2 qi = ClampToScreen((int2)floor(q));
    if (LoadSceneEyeDepth(qi) < px.eyeDepth)
        q = px.pixel;
    float3 background = SceneColorBilinear(q);
    // Beer–Lambert: T = e^(−a t); the absorbed share is replaced by the body colour times the scattering, lit by the
    // sky and the light.
    float3 transmittance = exp(-Absorption * px.thickness);
    float3 lighting = lerp(SkyHorizon, LightColour, saturate(dot(n, l)));
    float3 body = BodyColour * Scattering * lighting;
    float3 transmitted = background * transmittance + body * (1.0 - transmittance);
    // Schlick: F = F0 + (1 − F0)(1 − n·v)⁵, mixing in the sky along the reflected ray.
    float cosine = saturate(dot(n, px.view));
    float fresnel = FresnelF0 + (1.0 - FresnelF0) * pow(1.0 - cosine, 5.0);
    float3 reflected = Sky(reflect(-px.view, n));
    float3 h = normalize(l + px.view);
    float3 highlight = Specular * pow(saturate(dot(n, h)), SpecularPower) * LightColour;
    float3 emission = Emission * (px.heat * px.heat);
    return lerp(transmitted, reflected, fresnel) + highlight + emission;
}

float3 ShadeUnlit(SurfacePixel px, uint model)
{
    float3 background = LoadSceneColor(ClampToScreen((int2)floor(px.pixel))).rgb;
    float3 colour = BodyColour;
    float opacity = Opacity;
    if (model == 2u)
        opacity *= 1.0 - exp(-Absorption.x * px.thickness);
    else if (model == 3u)
    {
        float bands = max(ToonBands, 1.0);
        float lit = floor(saturate(dot(px.normal, LightDirection)) * bands) / bands;
        colour = dot(px.normal, px.view) < OutlineThreshold ? OutlineColour : colour * (0.4 + 0.6 * lit);
        opacity = 1.0;
    }
    return lerp(background, colour, opacity);
}

float3 Shade(SurfacePixel px)
{
    uint model = LookModel;
    return model == 0u ? ShadeLit(px) : ShadeUnlit(px, model);
}

#endif
