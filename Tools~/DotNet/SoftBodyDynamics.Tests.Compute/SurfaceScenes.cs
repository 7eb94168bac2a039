using System;
using System.Collections.Generic;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Lavapipe;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Compute
{
    /// <summary>The renderer's test scenes at a small size, built once, and helpers shared by the surface tests.</summary>
    static class SurfaceScenes
    {
        public const int Width = 160, Height = 96;
        static readonly Dictionary<string, FluidSurfaceScene> s_Scenes = new Dictionary<string, FluidSurfaceScene>();

        public static readonly string[] Names = { "sphere", "two-blobs", "dam-break" };

        public static FluidSurfaceScene Get(string name)
        {
            lock (s_Scenes)
            {
                if (!s_Scenes.TryGetValue(name, out FluidSurfaceScene scene))
                {
                    scene = name switch
                    {
                        "sphere" => FluidSurfaceScene.Sphere(Width, Height),
                        "two-blobs" => FluidSurfaceScene.TwoBlobs(Width, Height),
                        "dam-break" => FluidSurfaceScene.DamBreak(Width, Height),
                        _ => throw new ArgumentException(name),
                    };
                    s_Scenes[name] = scene;
                }
                return scene;
            }
        }

        public static LavapipeFluidSurface.Frame Render(FluidSurfaceScene scene, in FluidSurfaceSettings settings, in FluidLook look) =>
            Lavapipe.Surface.Render(scene.Camera, settings, look, scene.Lighting, scene.Particles, scene.SceneColour, scene.SceneEyeDepth);

        /// <summary>float32 unit round-off.</summary>
        public const double Epsilon = 5.96e-8;

        /// <summary>
        /// The largest difference between two float32 evaluations (or one and the exact value) of a ray's first hit on a
        /// sphere, from the error of each step of RaySphere: the normalised ray and b = u·c carry a few ε of the eye depth
        /// z; h² = r² − |c − b u|² carries about 8ε r² from its own sums, and the offset c − b u, whose components are
        /// differences of terms as large as z, about ε z per component, so |c − b u|² ≤ r² carries 2√3·ε z r more; h = √h²
        /// carries half of that over h. With a factor 4 for the division and the rounding of the inputs:
        /// 16ε z + 16ε r²/h + 8ε z r/h (the last term dominates at grazing hits, h ≪ r ≪ z).
        /// </summary>
        public static double HitTolerance(double z, double r, double h) =>
            16 * Epsilon * z + (16 * Epsilon * r * r + 8 * Epsilon * z * r) / Math.Max(h, 1e-9);
    }
}
