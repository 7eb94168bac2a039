using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>How the fluid's depth is smoothed before normals are taken from it.</summary>
    public enum FluidSurfaceFilter
    {
        /// <summary>The spheres as splatted: a bumpy surface, the cheapest.</summary>
        None = 0,
        /// <summary>Narrow-range filter (Truong &amp; Yuksel 2018): Gaussian over a depth range, in front clamped, behind ignored. The default.</summary>
        NarrowRange = 1,
        /// <summary>Bilateral filter: Gaussian in space times Gaussian in depth.</summary>
        Bilateral = 2,
        /// <summary>Screen-space curvature flow (van der Laan et al. 2009): explicit steps of mean-curvature flow.</summary>
        CurvatureFlow = 3,
    }

    /// <summary>
    /// The per-camera knobs of the screen-space fluid renderer (units in each field's comment). <see cref="Sanitized"/>
    /// replaces what cannot be used and says why; the authoring side shows the same messages.
    /// </summary>
    [Serializable]
    public struct FluidSurfaceSettings
    {
        /// <summary>Radius of the sphere drawn for each particle (m); about half the particle spacing.</summary>
        public float ParticleRadius;
        /// <summary>1 = depth and smoothing at full resolution; 2 = half resolution (the mobile tier). Thickness is always at half resolution.</summary>
        public int DepthDivisor;
        /// <summary>1 = the composite shades every screen pixel; 2 = every other pixel each way (the mobile tier), upsampled by the overlay.</summary>
        public int CompositeDivisor;
        public FluidSurfaceFilter Filter;
        /// <summary>Filter iterations: pairs of separable passes (narrow-range, bilateral) or curvature-flow steps.</summary>
        public int Iterations;
        /// <summary>Filter radius in the world (m); on screen it shrinks with distance, clamped to <see cref="MaxFilterPixels"/>.</summary>
        public float FilterRadius;
        /// <summary>Largest filter radius on screen (pixels of the depth target).</summary>
        public int MaxFilterPixels;
        /// <summary>Depth range of the narrow-range and bilateral filters (m): neighbours farther behind belong to another surface.</summary>
        public float DepthRange;
        /// <summary>Curvature-flow step as a fraction of the explicit stability limit (0–0.25).</summary>
        public float CurvatureStep;
        /// <summary>Largest refraction offset (pixels of the screen).</summary>
        public float MaxRefractionPixels;

        public const int MaxIterations = 64;
        public const int MaxFilterPixelsLimit = 32;

        /// <summary>
        /// Desktop defaults for particles of <paramref name="radius"/> metres: full-resolution depth, one narrow-range pass
        /// pair (more pairs over-smooth: the main job's accuracy table shows the normal error rising after the first).
        /// </summary>
        public static FluidSurfaceSettings Desktop(float radius) => new FluidSurfaceSettings
        {
            ParticleRadius = radius,
            DepthDivisor = 1,
            CompositeDivisor = 1,
            Filter = FluidSurfaceFilter.NarrowRange,
            Iterations = 1,
            FilterRadius = 2.5f * radius,
            MaxFilterPixels = 16,
            DepthRange = 2f * radius,
            CurvatureStep = 0.2f,
            MaxRefractionPixels = 48f,
        };

        /// <summary>The mobile tier: depth, thickness, smoothing and the composite at half resolution, a smaller largest filter radius and refraction offset.</summary>
        public static FluidSurfaceSettings Mobile(float radius)
        {
            FluidSurfaceSettings s = Desktop(radius);
            s.DepthDivisor = 2;
            s.CompositeDivisor = 2;
            s.MaxFilterPixels = 8;
            s.MaxRefractionPixels = 32f;
            return s;
        }

        /// <summary>Thickness target divisor (always half resolution).</summary>
        public const int ThicknessDivisor = 2;

        /// <summary>
        /// These settings with every unusable value replaced by the desktop default (non-finite, zero or negative sizes,
        /// out-of-range counts); <paramref name="problems"/> names each replacement, empty when there was none.
        /// </summary>
        public FluidSurfaceSettings Sanitized(out string problems)
        {
            System.Text.StringBuilder sb = null; // allocated only when something is replaced
            FluidSurfaceSettings s = this;
            if (!(s.ParticleRadius > 0f) || !math.isfinite(s.ParticleRadius))
            {
                Note(ref sb).Append($"particle radius {s.ParticleRadius} m must be positive and finite: 0.02 m used. ");
                s.ParticleRadius = 0.02f;
            }
            FluidSurfaceSettings d = Desktop(s.ParticleRadius);
            if (s.DepthDivisor != 1 && s.DepthDivisor != 2)
            {
                Note(ref sb).Append($"depth divisor {s.DepthDivisor} must be 1 (full) or 2 (half): 1 used. ");
                s.DepthDivisor = 1;
            }
            if (s.CompositeDivisor != 1 && s.CompositeDivisor != 2)
            {
                Note(ref sb).Append($"composite divisor {s.CompositeDivisor} must be 1 (full) or 2 (half): 1 used. ");
                s.CompositeDivisor = 1;
            }
            if (!Enum.IsDefined(typeof(FluidSurfaceFilter), s.Filter))
            {
                Note(ref sb).Append($"unknown filter {(int)s.Filter}: narrow-range used. ");
                s.Filter = FluidSurfaceFilter.NarrowRange;
            }
            s.Iterations = IntIn(s.Iterations, 0, MaxIterations, "filter iterations", ref sb);
            s.FilterRadius = Positive(s.FilterRadius, d.FilterRadius, "filter radius (m)", ref sb);
            s.MaxFilterPixels = IntIn(s.MaxFilterPixels, 1, MaxFilterPixelsLimit, "largest filter radius (px)", ref sb);
            s.DepthRange = Positive(s.DepthRange, d.DepthRange, "depth range (m)", ref sb);
            if (!(s.CurvatureStep > 0f) || s.CurvatureStep > 0.25f)
            {
                Note(ref sb).Append($"curvature step {s.CurvatureStep} must be in (0, 0.25] (stability): {d.CurvatureStep} used. ");
                s.CurvatureStep = d.CurvatureStep;
            }
            if (!(s.MaxRefractionPixels >= 0f) || !math.isfinite(s.MaxRefractionPixels))
            {
                Note(ref sb).Append($"largest refraction offset {s.MaxRefractionPixels} px must be zero or positive: {d.MaxRefractionPixels} px used. ");
                s.MaxRefractionPixels = d.MaxRefractionPixels;
            }
            problems = sb == null ? string.Empty : sb.ToString().TrimEnd();
            return s;
        }

        static int IntIn(int v, int lo, int hi, string name, ref System.Text.StringBuilder sb)
        {
            if (v >= lo && v <= hi)
                return v;
            int clamped = math.clamp(v, lo, hi);
            Note(ref sb).Append($"{name} {v} is outside {lo}–{hi}: {clamped} used. ");
            return clamped;
        }

        static float Positive(float v, float fallback, string name, ref System.Text.StringBuilder sb)
        {
            if (v > 0f && math.isfinite(v))
                return v;
            Note(ref sb).Append($"{name} {v} must be positive and finite: {fallback} used. ");
            return fallback;
        }

        static System.Text.StringBuilder Note(ref System.Text.StringBuilder sb) => sb ??= new System.Text.StringBuilder();
    }
}
