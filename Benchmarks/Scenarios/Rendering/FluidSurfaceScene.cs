using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// A known set of fluid particles in front of a known opaque scene: a checkerboard floor (y = 0) under a sky, and
    /// optionally an opaque box. The scene's linear colour and eye depth per screen pixel (row 0 at the bottom) are what
    /// Unity's opaque colour and depth textures would hold.
    /// </summary>
    public sealed class FluidSurfaceScene
    {
        public string Name;
        /// <summary>xyz world position (m), w attribute (temperature, K).</summary>
        public float4[] Particles;
        /// <summary>Sphere radius drawn per particle (m).</summary>
        public float Radius;
        public FluidSurfaceCamera Camera;
        public FluidSurfaceLighting Lighting = FluidSurfaceLighting.Default;
        /// <summary>Side of a floor square (m).</summary>
        public float CheckerSize;
        /// <summary>An opaque box in front of part of the fluid (none when Min = Max).</summary>
        public float3 OccluderMin, OccluderMax;
        public float4[] SceneColour;
        public float[] SceneEyeDepth;

        /// <summary>Eye depth of the sky (m).</summary>
        public const float SkyDepth = 1e6f;

        /// <summary>Renders the opaque scene (floor, sky, occluder) into <see cref="SceneColour"/> and <see cref="SceneEyeDepth"/>.</summary>
        public void RenderBackground()
        {
            int w = Camera.Width, h = Camera.Height;
            SceneColour = new float4[w * h];
            SceneEyeDepth = new float[w * h];
            float4 pin = Camera.Pinhole(1);
            float3x3 toWorld = math.transpose(Camera.Rotation);
            float3 eye = -math.mul(toWorld, Camera.Translation);
            for (int y = 0; y < h; y++)
                for (int x = 0; x < w; x++)
                {
                    float3 rayView = new float3((x + 0.5f - pin.z) / pin.x, (y + 0.5f - pin.w) / pin.y, -1f);
                    float3 d = math.mul(toWorld, rayView);   // world direction, eye depth 1 per unit of t
                    float t = SkyDepth;
                    float3 colour = Sky(math.normalize(d));
                    if (d.y < 0f)
                    {
                        float tf = -eye.y / d.y;
                        float3 p = eye + tf * d;
                        int cx = (int)math.floor(p.x / CheckerSize), cz = (int)math.floor(p.z / CheckerSize);
                        bool light = ((cx + cz) & 1) == 0;
                        t = tf;
                        colour = light ? new float3(0.78f, 0.76f, 0.72f) : new float3(0.16f, 0.17f, 0.2f);
                    }
                    if (math.any(OccluderMax > OccluderMin) && HitBox(eye, d, OccluderMin, OccluderMax, out float tb) && tb < t)
                    {
                        t = tb;
                        colour = new float3(0.45f, 0.08f, 0.06f);
                    }
                    SceneColour[y * w + x] = new float4(colour, 1f);
                    SceneEyeDepth[y * w + x] = t;
                }
        }

        float3 Sky(float3 d)
        {
            float e = math.dot(d, Lighting.Up);
            return e >= 0f ? math.lerp(Lighting.SkyHorizon, Lighting.SkyZenith, e) : Lighting.SkyHorizon * 0.5f;
        }

        static bool HitBox(float3 o, float3 d, float3 lo, float3 hi, out float t)
        {
            float t0 = 0f, t1 = float.MaxValue;
            for (int a = 0; a < 3; a++)
            {
                float inv = 1f / d[a];
                float ta = (lo[a] - o[a]) * inv, tb = (hi[a] - o[a]) * inv;
                t0 = math.max(t0, math.min(ta, tb));
                t1 = math.min(t1, math.max(ta, tb));
            }
            t = t0;
            return t0 <= t1 && t0 > 0f;
        }

        /// <summary>
        /// A ball of particles: lattice points within <paramref name="ballRadius"/> of <paramref name="centre"/>, jittered by
        /// up to a tenth of the spacing; the attribute is <paramref name="attribute"/> at the centre, 3000 K/m cooler upwards.
        /// </summary>
        public static float4[] Ball(float3 centre, float ballRadius, float spacing, float attribute, uint seed)
        {
            var rng = new Unity.Mathematics.Random(seed);
            int n = (int)math.ceil(ballRadius / spacing);
            var list = new System.Collections.Generic.List<float4>();
            for (int z = -n; z <= n; z++)
                for (int y = -n; y <= n; y++)
                    for (int x = -n; x <= n; x++)
                    {
                        var q = new float3(x, y, z) * spacing;
                        if (math.length(q) > ballRadius)
                            continue;
                        float3 jitter = (rng.NextFloat3() - 0.5f) * (0.2f * spacing);
                        list.Add(new float4(centre + q + jitter, attribute - 3000f * q.y));
                    }
            return list.ToArray();
        }

        /// <summary>One ball of about 500 particles (radius 0.1 m, spacing 2 cm, drawn at 1.4 cm) over the floor.</summary>
        public static FluidSurfaceScene Sphere(int width, int height)
        {
            var s = new FluidSurfaceScene
            {
                Name = "sphere",
                Particles = Ball(new float3(0f, 0.13f, 0f), 0.1f, 0.02f, 1400f, 1u),
                Radius = 0.014f,
                Camera = FluidSurfaceCamera.LookAt(new float3(0.05f, 0.3f, 0.55f), new float3(0f, 0.11f, 0f), width, height, 40f),
                CheckerSize = 0.05f,
            };
            s.RenderBackground();
            return s;
        }

        /// <summary>Two balls just touching, with an opaque post in front of the right one.</summary>
        public static FluidSurfaceScene TwoBlobs(int width, int height)
        {
            float4[] a = Ball(new float3(-0.085f, 0.1f, 0f), 0.075f, 0.02f, 1000f, 2u);
            float4[] b = Ball(new float3(0.075f, 0.09f, 0.01f), 0.065f, 0.02f, 1300f, 3u);
            var all = new float4[a.Length + b.Length];
            a.CopyTo(all, 0);
            b.CopyTo(all, a.Length);
            var s = new FluidSurfaceScene
            {
                Name = "two-blobs",
                Particles = all,
                Radius = 0.014f,
                Camera = FluidSurfaceCamera.LookAt(new float3(0f, 0.25f, 0.55f), new float3(0f, 0.09f, 0f), width, height, 40f),
                CheckerSize = 0.05f,
                OccluderMin = new float3(0.09f, 0f, 0.16f),
                OccluderMax = new float3(0.115f, 0.3f, 0.185f),
            };
            s.RenderBackground();
            return s;
        }

        /// <summary>
        /// A frame of the CPU solver's dam break (WCSPH, Martin &amp; Moyce's column a = 5.7 cm at a/10, 8 layers deep)
        /// after <paramref name="seconds"/>; particles drawn at 0.75 of the spacing, the attribute cooling from 1400 K
        /// with height so lava shows a gradient.
        /// </summary>
        public static FluidSurfaceScene DamBreak(int width, int height, float seconds = 0.08f)
        {
            float a = (float)MartinMoyce1952.ColumnWidth;
            float dx = a / 10f;
            FluidParameters p = FluidParameters.Default;
            p.Solver = FluidSolverKind.WeaklyCompressible;
            p.SpeedOfSound = 10f * DamBreakScenario.ReferenceSpeed;
            p.ViscosityIterations = 1;
            p.MaxSubsteps = FluidParameters.SubstepLimit;
            FluidBuffers buffers = FluidScene.BlockInBox(p, dx, new float3(4f * a, 3f * a, 8f * dx), new float3(a, 2f * a, 8f * dx), out FluidConstants constants);
            for (float t = 0f; t < seconds - 1e-6f; t += 1f / 120f)
                FluidSolver.Step(constants, ReadOnlySpan<ColliderShape>.Empty, 1f / 120f, buffers.Particles, buffers.Scratch, ref buffers.Status);
            var particles = new float4[buffers.Status.Count];
            for (int i = 0; i < particles.Length; i++)
                particles[i] = new float4(buffers.Positions[i], 1400f - 4000f * buffers.Positions[i].y);
            var s = new FluidSurfaceScene
            {
                Name = "dam-break",
                Particles = particles,
                Radius = 0.75f * dx,
                Camera = FluidSurfaceCamera.LookAt(new float3(0.13f, 0.13f, 0.24f), new float3(0.08f, 0.025f, 0.02f), width, height, 40f),
                CheckerSize = 0.02f,
            };
            s.RenderBackground();
            return s;
        }

        /// <summary>The three scenes at one size.</summary>
        public static FluidSurfaceScene[] All(int width, int height) => new[] { Sphere(width, height), TwoBlobs(width, height), DamBreak(width, height) };
    }
}
