using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The composite and the looks in C# (float32): the reference of FluidSurfaceComposite.hlsl and
    /// FluidSurfaceShading.hlsl. The scene is given as linear colour and eye depth per screen pixel (row 0 at the bottom).
    /// </summary>
    public static class FluidSurfaceComposite
    {
        /// <summary>The inputs of the composite.</summary>
        public readonly ref struct Inputs
        {
            public readonly ReadOnlySpan<float> Depth;
            public readonly ReadOnlySpan<uint> Normals;
            public readonly ReadOnlySpan<float2> Thickness;
            public readonly ReadOnlySpan<float4> SceneColour;
            public readonly ReadOnlySpan<float> SceneEyeDepth;

            public Inputs(ReadOnlySpan<float> depth, ReadOnlySpan<uint> normals, ReadOnlySpan<float2> thickness,
                ReadOnlySpan<float4> sceneColour, ReadOnlySpan<float> sceneEyeDepth)
            {
                Depth = depth;
                Normals = normals;
                Thickness = thickness;
                SceneColour = sceneColour;
                SceneEyeDepth = sceneEyeDepth;
            }
        }

        static int ClampX(in FluidSurfaceConstants k, int x) => math.clamp(x, 0, (int)k.ScreenWidth - 1);
        static int ClampY(in FluidSurfaceConstants k, int y) => math.clamp(y, 0, (int)k.ScreenHeight - 1);

        static float3 SceneColour(in FluidSurfaceConstants k, in Inputs i, int x, int y) => i.SceneColour[y * (int)k.ScreenWidth + x].xyz;

        static float SceneEyeDepth(in FluidSurfaceConstants k, in Inputs i, int x, int y) => i.SceneEyeDepth[y * (int)k.ScreenWidth + x];

        /// <summary>Bilinear scene colour at a continuous pixel position (centres at i + 0.5), clamped to the screen.</summary>
        static float3 SceneColourBilinear(in FluidSurfaceConstants k, in Inputs i, float px, float py)
        {
            float tx = px - 0.5f, ty = py - 0.5f;
            int bx = (int)math.floor(tx), by = (int)math.floor(ty);
            float fx = tx - math.floor(tx), fy = ty - math.floor(ty);
            float3 a = SceneColour(k, i, ClampX(k, bx), ClampY(k, by)), b = SceneColour(k, i, ClampX(k, bx + 1), ClampY(k, by));
            float3 c = SceneColour(k, i, ClampX(k, bx), ClampY(k, by + 1)), d = SceneColour(k, i, ClampX(k, bx + 1), ClampY(k, by + 1));
            return math.lerp(math.lerp(a, b, fx), math.lerp(c, d, fx), fy);
        }

        /// <summary>
        /// Thickness (m) and mean attribute at a screen position (pixel centres at i + 0.5): bilinear over the half-resolution texels that hold fluid,
        /// the weights renormalised so the empty background does not thin the edge; the particle radius where none does.
        /// </summary>
        static float2 ThicknessAt(in FluidSurfaceConstants k, in Inputs i, float px, float py)
        {
            float tx = px / 2f - 0.5f, ty = py / 2f - 0.5f;
            int bx = (int)math.floor(tx), by = (int)math.floor(ty);
            float fx = tx - math.floor(tx), fy = ty - math.floor(ty);
            float sumT = 0f, sumA = 0f, weights = 0f;
            for (int n = 0; n < 4; n++)
            {
                int ox = n & 1, oy = n >> 1;
                int qx = math.clamp(bx + ox, 0, (int)k.ThicknessWidth - 1), qy = math.clamp(by + oy, 0, (int)k.ThicknessHeight - 1);
                float2 v = i.Thickness[qy * (int)k.ThicknessWidth + qx];
                float w = (ox == 1 ? fx : 1f - fx) * (oy == 1 ? fy : 1f - fy);
                if (v.x > 0f)
                {
                    sumT += w * v.x;
                    sumA += w * v.y;
                    weights += w;
                }
            }
            return weights > 0f ? new float2(sumT / weights, sumA / weights) : new float2(k.ParticleRadius, 0f);
        }

        /// <summary>Sky along the view-space direction r: horizon to zenith by elevation, half the horizon below it.</summary>
        static float3 Sky(in FluidSurfaceConstants k, float3 r)
        {
            float e = math.dot(r, k.ViewUp);
            return e >= 0f ? math.lerp(k.SkyHorizon, k.SkyZenith, e) : k.SkyHorizon * (1f + 0.5f * e);
        }

        static float3 Exp(float3 v) => new float3(math.exp(v.x), math.exp(v.y), math.exp(v.z));

        /// <summary>
        /// Lit: the background shifted along the normal by the thickness (clamped; unshifted where the shifted point is
        /// nearer than the fluid), Beer–Lambert T = e^(−a t) with the absorbed share replaced by the lit body colour
        /// times the scattering, Schlick's F = F0 + (1 − F0)(1 − n·v)⁵ mixing in the sky along the reflected ray, a
        /// Blinn–Phong highlight and emission by the squared heat.
        /// </summary>
        static float3 ShadeLit(in FluidSurfaceConstants k, in Inputs i, float px, float py, float eyeDepth, float3 n, float3 view, float thickness, float heat)
        {
            float3 l = k.LightDirection;
            float scale = k.Refraction * thickness * k.ScreenFocal.x / eyeDepth;
            float ox = n.x * scale, oy = n.y * scale;
            float len = math.sqrt(ox * ox + oy * oy);
            float clampScale = len > k.MaxRefractionPixels ? k.MaxRefractionPixels / len : 1f;
            ox *= clampScale;
            oy *= clampScale;
            float qx = px + ox, qy = py + oy;
            if (SceneEyeDepth(k, i, ClampX(k, (int)math.floor(qx)), ClampY(k, (int)math.floor(qy))) < eyeDepth)
            {
                qx = px;
                qy = py;
            }
            float3 background = SceneColourBilinear(k, i, qx, qy);
            float3 transmittance = Exp(-k.Absorption * thickness);
            float3 lighting = math.lerp(k.SkyHorizon, k.LightColour, math.saturate(math.dot(n, l)));
            float3 body = k.BodyColour * k.Scattering * lighting;
            float3 transmitted = background * transmittance + body * (1f - transmittance);
            float cosine = math.saturate(math.dot(n, view));
            float fresnel = k.FresnelF0 + (1f - k.FresnelF0) * math.pow(1f - cosine, 5f);
            float3 incident = -view;
            float3 reflected = Sky(k, incident - 2f * math.dot(n, incident) * n);
            float3 h = math.normalize(l + view);
            float3 highlight = k.Specular * math.pow(math.saturate(math.dot(n, h)), k.SpecularPower) * k.LightColour;
            float3 emission = k.Emission * (heat * heat);
            return math.lerp(transmitted, reflected, fresnel) + highlight + emission;
        }

        /// <summary>Unlit: flat (colour at the opacity), thickness-tinted (opacity × (1 − e^(−k t))), toon (bands of n·l, outline where n·v is small).</summary>
        static float3 ShadeUnlit(in FluidSurfaceConstants k, in Inputs i, float px, float py, float3 n, float3 view, float thickness, int model)
        {
            float3 background = SceneColour(k, i, ClampX(k, (int)math.floor(px)), ClampY(k, (int)math.floor(py)));
            float3 colour = k.BodyColour;
            float opacity = k.Opacity;
            if (model == 2)
                opacity *= 1f - math.exp(-k.Absorption.x * thickness);
            else if (model == 3)
            {
                float bands = math.max(k.ToonBands, 1f);
                float lit = math.floor(math.saturate(math.dot(n, k.LightDirection)) * bands) / bands;
                colour = math.dot(n, view) < k.OutlineThreshold ? k.OutlineColour : colour * (0.4f + 0.6f * lit);
                opacity = 1f;
            }
            return math.lerp(background, colour, opacity);
        }

        /// <summary>Composite pixels of the target (the screen divided by CompositeDivisor, rounded up).</summary>
        public static int2 Size(in FluidSurfaceConstants k) =>
            new int2((int)((k.ScreenWidth + k.CompositeDivisor - 1) / k.CompositeDivisor), (int)((k.ScreenHeight + k.CompositeDivisor - 1) / k.CompositeDivisor));

        /// <summary>
        /// The composite: rgb fluid colour and coverage (0 or 1) per composite pixel (every screen pixel, or every other one
        /// each way at half resolution, its centre at (c + ½)·divisor on the screen); 0 where there is no fluid or the
        /// scene is nearer.
        /// </summary>
        public static void Composite(in FluidSurfaceConstants k, in Inputs i, Span<float4> output)
        {
            int2 size = Size(k);
            float divisor = k.CompositeDivisor;
            for (int y = 0; y < size.y; y++)
                for (int x = 0; x < size.x; x++)
                {
                    float px = (x + 0.5f) * divisor, py = (y + 0.5f) * divisor;
                    int sx = math.min((int)math.floor(px), (int)k.ScreenWidth - 1), sy = math.min((int)math.floor(py), (int)k.ScreenHeight - 1);
                    int dx = math.min((int)math.floor(px / k.DepthDivisor), (int)k.DepthWidth - 1), dy = math.min((int)math.floor(py / k.DepthDivisor), (int)k.DepthHeight - 1);
                    float z = i.Depth[dy * (int)k.DepthWidth + dx];
                    float sceneDepth = SceneEyeDepth(k, i, sx, sy);
                    if (z <= 0f || z >= sceneDepth)
                    {
                        output[y * size.x + x] = float4.zero;
                        continue;
                    }
                    // A target whose pass is off is not read: the look does not use it (FluidSurfacePassList).
                    float3 n = (k.PassFlags & FluidSurfacePassList.NormalsFlag) != 0
                        ? FluidSurfacePasses.UnpackNormal(i.Normals[dy * (int)k.DepthWidth + dx]) : new float3(0f, 0f, 1f);
                    float3 view = -math.normalize(FluidSurfacePasses.PixelRay(px, py, k.ScreenFocal, k.ScreenCentre));
                    float2 t = (k.PassFlags & FluidSurfacePassList.ThicknessFlag) != 0 ? ThicknessAt(k, i, px, py) : new float2(k.ParticleRadius, 0f);
                    float3 c = k.LookModel == 0
                        ? ShadeLit(k, i, px, py, z, n, view, t.x, t.y)
                        : ShadeUnlit(k, i, px, py, n, view, t.x, (int)k.LookModel);
                    output[y * size.x + x] = new float4(c, 1f);
                }
        }
    }
}
