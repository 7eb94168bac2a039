using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Rendering
{
    /// <summary>
    /// The knobs of the screen-space fluid renderer, shared by every fluid a <see cref="FluidRendererFeature"/> draws.
    /// Lengths that scale with the fluid (filter radius, depth range) are in particle radii, so one asset suits fluids of
    /// any resolution; <see cref="ToSettings"/> turns them into metres for one fluid. Changing <see cref="tier"/> in the
    /// inspector resets the quality fields to that tier's defaults.
    /// </summary>
    [CreateAssetMenu(fileName = "FluidRendererSettings", menuName = "Soft Body Dynamics/Fluid Renderer Settings")]
    public sealed class FluidRendererSettings : ScriptableObject
    {
        /// <summary>Smallest filter radius and depth range accepted (particle radii).</summary>
        public const float MinRadii = 0.1f;
        /// <summary>Bounds of the initial tile-entry capacity (entries of 4 bytes).</summary>
        public const int MinTileCapacity = 1024, MaxTileCapacity = 1 << 26;
        /// <summary>Default initial tile-entry capacity: 256 KiB, about 20 000 particles each touching three tiles.</summary>
        public const int DefaultTileCapacity = 1 << 16;

        // The tier defaults for a particle radius of 1, so every length in them reads in particle radii.
        static readonly FluidSurfaceSettings k_Desktop = FluidSurfaceSettings.Desktop(1f);

        [Header("Shaders")]
        [Tooltip("The fluid surface kernels: Packages/com.softbodydynamics.dots/Shaders/FluidSurface.compute. Nothing is drawn without it.")]
        public ComputeShader computeShader;

        [Tooltip("Draws the fluid over the camera colour: Hidden/SoftBodyDynamics/FluidOverlay (Shaders/FluidOverlay.shader). Nothing is drawn without it.")]
        public Shader overlayShader;

        [Header("Quality")]
        [Tooltip("Desktop: full-resolution depth and composite, filter up to 16 px, refraction up to 48 px. Mobile: half-resolution depth and composite (a quarter of the pixels), filter up to 8 px, refraction up to 32 px. Both: one narrow-range pass pair. Changing it resets the fields below to the tier's defaults.")]
        public FluidRendererTier tier = FluidRendererTier.Desktop;

        [Tooltip("Resolution of the fluid depth, its smoothing and its normals. Half costs a quarter of the pixels and softens the silhouette. Thickness is always at half resolution. Desktop: Full.")]
        public FluidDepthResolution depthResolution = (FluidDepthResolution)k_Desktop.DepthDivisor;

        [Tooltip("Resolution of the composite (refraction, absorption, reflection, the look). Half shades a quarter of the pixels and the overlay upsamples them bilinearly: softer edges, about half the memory traffic of the mobile tier. Desktop: Full.")]
        public FluidDepthResolution compositeResolution = (FluidDepthResolution)k_Desktop.CompositeDivisor;

        [Tooltip("How the depth of the particle spheres is smoothed into a surface. Narrow-range (default): keeps separate sheets apart. Bilateral: classic, softer. Curvature flow: iterative mean-curvature smoothing. None: raw spheres.")]
        public FluidSurfaceFilter filter = k_Desktop.Filter;

        [Tooltip("Filter iterations: pairs of separable passes (narrow-range, bilateral) or curvature-flow steps (0–64). Default 1: more narrow-range or bilateral pairs over-smooth; curvature flow wants about 10–20 steps.")]
        [Range(0, FluidSurfaceSettings.MaxIterations)]
        public int iterations = k_Desktop.Iterations;

        [Tooltip("Filter radius in the world, in particle radii (default 2.5). On screen it shrinks with distance, up to the largest filter radius below.")]
        [Min(MinRadii)]
        public float filterRadius = k_Desktop.FilterRadius;

        [Tooltip("Largest filter radius on screen, in pixels of the depth target (1–32). Bounds the cost of close-ups. Desktop 16, mobile 8.")]
        [Range(1, FluidSurfaceSettings.MaxFilterPixelsLimit)]
        public int maxFilterPixels = k_Desktop.MaxFilterPixels;

        [Tooltip("Depth range of the narrow-range and bilateral filters, in particle radii (default 2): neighbours farther behind belong to another surface and are not blended in.")]
        [Min(MinRadii)]
        public float depthRange = k_Desktop.DepthRange;

        [Tooltip("Curvature-flow step as a fraction of the explicit stability limit (0.01–0.25, default 0.2). Used by the curvature-flow filter only.")]
        [Range(0.01f, 0.25f)]
        public float curvatureStep = k_Desktop.CurvatureStep;

        [Tooltip("Largest offset of the refracted background, in screen pixels (default 48 desktop, 32 mobile). 0 turns refraction off.")]
        [Min(0f)]
        public float maxRefractionPixels = k_Desktop.MaxRefractionPixels;

        [Header("Sky")]
        [Tooltip("Sky colour straight up, as picked (sRGB): what the Fresnel reflection of the lit looks shows on surfaces facing up.")]
        public Color skyZenith = new Color(0.5371f, 0.7014f, 0.9309f);

        [Tooltip("Sky colour at the horizon, as picked (sRGB): what the Fresnel reflection shows on surfaces facing sideways.")]
        public Color skyHorizon = new Color(0.8808f, 0.9163f, 0.9547f);

        [Header("Memory")]
        [Tooltip("Tile entries (one per particle per 16 × 16-pixel tile it covers; 4 bytes each) allocated at first. The list grows to the next power of two, a frame later, when a frame needs more; until then the extra entries are not drawn. Default 65536.")]
        [Min(MinTileCapacity)]
        public int initialTileCapacity = DefaultTileCapacity;

        // The tier whose defaults the quality fields hold, so a change of tier in the inspector can be noticed.
        [SerializeField, HideInInspector]
        FluidRendererTier m_AppliedTier = FluidRendererTier.Desktop;

        /// <summary>
        /// The settings for a fluid whose particles have radius <paramref name="particleRadius"/> (m), with every unusable
        /// value replaced (<see cref="FluidSurfaceSettings.Sanitized"/>); <paramref name="problems"/> names each
        /// replacement and is empty when there was none.
        /// </summary>
        public FluidSurfaceSettings ToSettings(float particleRadius, out string problems)
        {
            var s = new FluidSurfaceSettings
            {
                ParticleRadius = particleRadius,
                DepthDivisor = (int)depthResolution,
                CompositeDivisor = (int)compositeResolution,
                Filter = filter,
                Iterations = iterations,
                FilterRadius = filterRadius * particleRadius,
                MaxFilterPixels = maxFilterPixels,
                DepthRange = depthRange * particleRadius,
                CurvatureStep = curvatureStep,
                MaxRefractionPixels = maxRefractionPixels,
            };
            return s.Sanitized(out problems);
        }

        /// <summary>Sets the quality fields to <see cref="tier"/>'s defaults.</summary>
        public void ApplyTierDefaults()
        {
            FluidSurfaceSettings d = tier == FluidRendererTier.Mobile ? FluidSurfaceSettings.Mobile(1f) : FluidSurfaceSettings.Desktop(1f);
            depthResolution = (FluidDepthResolution)d.DepthDivisor;
            compositeResolution = (FluidDepthResolution)d.CompositeDivisor;
            filter = d.Filter;
            iterations = d.Iterations;
            filterRadius = d.FilterRadius;
            maxFilterPixels = d.MaxFilterPixels;
            depthRange = d.DepthRange;
            curvatureStep = d.CurvatureStep;
            maxRefractionPixels = d.MaxRefractionPixels;
            m_AppliedTier = tier;
        }

        /// <summary>
        /// Applies a changed tier's defaults, then clamps every field into its usable range (non-finite values take the
        /// desktop default). The inspector calls it on every edit.
        /// </summary>
        public void Validate()
        {
            if (tier != m_AppliedTier)
                ApplyTierDefaults();
            if (!Enum.IsDefined(typeof(FluidDepthResolution), depthResolution))
                depthResolution = (FluidDepthResolution)k_Desktop.DepthDivisor;
            if (!Enum.IsDefined(typeof(FluidDepthResolution), compositeResolution))
                compositeResolution = (FluidDepthResolution)k_Desktop.CompositeDivisor;
            if (!Enum.IsDefined(typeof(FluidSurfaceFilter), filter))
                filter = k_Desktop.Filter;
            iterations = math.clamp(iterations, 0, FluidSurfaceSettings.MaxIterations);
            filterRadius = math.isfinite(filterRadius) ? math.max(filterRadius, MinRadii) : k_Desktop.FilterRadius;
            maxFilterPixels = math.clamp(maxFilterPixels, 1, FluidSurfaceSettings.MaxFilterPixelsLimit);
            depthRange = math.isfinite(depthRange) ? math.max(depthRange, MinRadii) : k_Desktop.DepthRange;
            curvatureStep = curvatureStep > 0f ? math.min(curvatureStep, 0.25f) : k_Desktop.CurvatureStep;
            maxRefractionPixels = math.isfinite(maxRefractionPixels) ? math.max(maxRefractionPixels, 0f) : k_Desktop.MaxRefractionPixels;
            initialTileCapacity = math.clamp(initialTileCapacity, MinTileCapacity, MaxTileCapacity);
        }

        void OnValidate() => Validate();
    }
}
