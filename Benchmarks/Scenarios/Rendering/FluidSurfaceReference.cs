using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Ray-cast surfaces of a scene's particles in float64, per pixel of a target: the union of the spheres (exact: the
    /// nearest analytic hit) and the metaball iso-surface φ(x) = Σ (1 − |x − p|²/R²)³ = c with R = 2r and c chosen so a
    /// lone particle's surface is its sphere (c = (1 − r²/R²)³), ray-marched in steps of r/8 and refined by 60 bisections.
    /// The renderer's smoothed depth is measured against the metaball surface; its raw splat against the union.
    /// </summary>
    public static class FluidSurfaceReference
    {
        /// <summary>Eye depth (m, 0 where the ray misses) and the view-space unit normal of each pixel.</summary>
        public sealed class Surface
        {
            public int Width, Height;
            public double[] Depth;
            public Vec64[] Normal;
        }

        public struct Vec64
        {
            public double x, y, z;
            public Vec64(double x, double y, double z) { this.x = x; this.y = y; this.z = z; }
            public static Vec64 operator +(Vec64 a, Vec64 b) => new Vec64(a.x + b.x, a.y + b.y, a.z + b.z);
            public static Vec64 operator -(Vec64 a, Vec64 b) => new Vec64(a.x - b.x, a.y - b.y, a.z - b.z);
            public static Vec64 operator *(double s, Vec64 a) => new Vec64(s * a.x, s * a.y, s * a.z);
            public static double Dot(Vec64 a, Vec64 b) => a.x * b.x + a.y * b.y + a.z * b.z;
            public double Length => Math.Sqrt(Dot(this, this));
            public Vec64 Normalized => (1.0 / Length) * this;
        }

        static readonly System.Runtime.CompilerServices.ConditionalWeakTable<FluidSurfaceScene, Vec64[]> s_Centres =
            new System.Runtime.CompilerServices.ConditionalWeakTable<FluidSurfaceScene, Vec64[]>();

        /// <summary>Particle centres in view space (float64, from the float32 world positions through the float64 view transform), computed once per scene (a scene is not changed after it is built).</summary>
        static Vec64[] ViewCentres(FluidSurfaceScene scene) => s_Centres.GetValue(scene, ComputeViewCentres);

        static Vec64[] ComputeViewCentres(FluidSurfaceScene scene)
        {
            float3x3 r = scene.Camera.Rotation;
            float3 t = scene.Camera.Translation;
            var c = new Vec64[scene.Particles.Length];
            for (int i = 0; i < c.Length; i++)
            {
                float3 p = scene.Particles[i].xyz;
                c[i] = new Vec64(
                    (double)r.c0.x * p.x + (double)r.c1.x * p.y + (double)r.c2.x * p.z + t.x,
                    (double)r.c0.y * p.x + (double)r.c1.y * p.y + (double)r.c2.y * p.z + t.y,
                    (double)r.c0.z * p.x + (double)r.c1.z * p.y + (double)r.c2.z * p.z + t.z);
            }
            return c;
        }

        static Vec64 Ray(float4 pinhole, int x, int y) =>
            new Vec64((x + 0.5 - pinhole.z) / pinhole.x, (y + 0.5 - pinhole.w) / pinhole.y, -1.0).Normalized;

        /// <summary>The unit ray u meets the sphere (centre c, radius² r2) in front of the eye: b the distance to the closest approach, h the half chord.</summary>
        static bool Meets(Vec64 u, Vec64 c, double r2, out double b, out double h)
        {
            b = Vec64.Dot(u, c);
            Vec64 off = c - b * u;
            double h2 = r2 - Vec64.Dot(off, off);
            h = h2 > 0 ? Math.Sqrt(h2) : 0;
            return h2 > 0 && b > 0;
        }

        /// <summary>
        /// The spheres on the ray of pixel (x, y) of a target with this pinhole: the half chord of the nearest one (0 on a
        /// miss), how many the ray meets and their summed chords (m).
        /// </summary>
        public static (double NearestHalfChord, int Hits, double Chords) PixelHits(FluidSurfaceScene scene, float4 pinhole, int x, int y)
        {
            Vec64[] c = ViewCentres(scene);
            Vec64 u = Ray(pinhole, x, y);
            double r2 = (double)scene.Radius * scene.Radius, best = double.MaxValue, half = 0, chords = 0;
            int hits = 0;
            foreach (Vec64 ci in c)
            {
                if (!Meets(u, ci, r2, out double b, out double h))
                    continue;
                hits++;
                chords += 2 * h;
                if (b - h < best)
                {
                    best = b - h;
                    half = h;
                }
            }
            return (half, hits, chords);
        }

        /// <summary>The union of the spheres seen through each pixel of the target <paramref name="divisor"/> times coarser than the screen.</summary>
        public static Surface UnionOfSpheres(FluidSurfaceScene scene, int divisor)
        {
            int2 size = scene.Camera.Size(divisor);
            float4 pin = scene.Camera.Pinhole(divisor);
            Vec64[] c = ViewCentres(scene);
            double r = scene.Radius, r2 = r * r;
            var s = new Surface { Width = size.x, Height = size.y, Depth = new double[size.x * size.y], Normal = new Vec64[size.x * size.y] };
            System.Threading.Tasks.Parallel.For(0, size.y, y =>
            {
                for (int x = 0; x < size.x; x++)
                {
                    Vec64 u = Ray(pin, x, y);
                    double best = double.MaxValue;
                    int hit = -1;
                    for (int i = 0; i < c.Length; i++)
                    {
                        if (!Meets(u, c[i], r2, out double b, out double h))
                            continue;
                        double t = b - h;
                        if (t < best)
                        {
                            best = t;
                            hit = i;
                        }
                    }
                    if (hit < 0)
                        continue;
                    Vec64 p = best * u;
                    s.Depth[y * size.x + x] = -p.z;
                    s.Normal[y * size.x + x] = (1.0 / r) * (p - c[hit]);
                }
            });
            return s;
        }

        /// <summary>Summed chord lengths (m) of the spheres along each pixel's ray (the thickness splat's exact value).</summary>
        public static double[] Thickness(FluidSurfaceScene scene, int divisor)
        {
            int2 size = scene.Camera.Size(divisor);
            float4 pin = scene.Camera.Pinhole(divisor);
            var t = new double[size.x * size.y];
            for (int y = 0; y < size.y; y++)
                for (int x = 0; x < size.x; x++)
                    t[y * size.x + x] = PixelHits(scene, pin, x, y).Chords;
            return t;
        }

        /// <summary>The metaball iso-surface through each pixel of the target <paramref name="divisor"/> times coarser than the screen.</summary>
        public static Surface Metaball(FluidSurfaceScene scene, int divisor)
        {
            int2 size = scene.Camera.Size(divisor);
            float4 pin = scene.Camera.Pinhole(divisor);
            Vec64[] c = ViewCentres(scene);
            double r = scene.Radius, support = 2 * r, support2 = support * support;
            double iso = Math.Pow(1 - r * r / support2, 3);
            var s = new Surface { Width = size.x, Height = size.y, Depth = new double[size.x * size.y], Normal = new Vec64[size.x * size.y] };
            System.Threading.Tasks.Parallel.For(0, size.y, () => new List<int>(), (y, _, candidates) =>
            {
                for (int x = 0; x < size.x; x++)
                {
                    Vec64 u = Ray(pin, x, y);
                    // Particles whose support the ray passes through, and the first entry into any of them.
                    candidates.Clear();
                    double enter = double.MaxValue, exit = 0;
                    for (int i = 0; i < c.Length; i++)
                    {
                        if (!Meets(u, c[i], support2, out double b, out double h))
                            continue;
                        candidates.Add(i);
                        enter = Math.Min(enter, b - h);
                        exit = Math.Max(exit, b + h);
                    }
                    if (candidates.Count == 0)
                        continue;
                    double step = r / 8, prev = Math.Max(enter, 0), t = prev;
                    bool found = false;
                    while (t <= exit)
                    {
                        if (Field(c, candidates, t * u, support2) >= iso)
                        {
                            found = true;
                            break;
                        }
                        prev = t;
                        t += step;
                    }
                    if (!found)
                        continue;
                    double lo = prev, hi = t;
                    for (int k = 0; k < 60; k++)
                    {
                        double mid = 0.5 * (lo + hi);
                        if (Field(c, candidates, mid * u, support2) >= iso) hi = mid; else lo = mid;
                    }
                    Vec64 p = hi * u;
                    s.Depth[y * size.x + x] = -p.z;
                    s.Normal[y * size.x + x] = Gradient(c, candidates, p, support2).Normalized;
                }
                return candidates;
            }, _ => { });
            return s;
        }

        static double Field(Vec64[] c, List<int> candidates, Vec64 x, double support2)
        {
            double sum = 0;
            foreach (int i in candidates)
            {
                Vec64 d = x - c[i];
                double q = Vec64.Dot(d, d) / support2;
                if (q < 1)
                    sum += (1 - q) * (1 - q) * (1 - q);
            }
            return sum;
        }

        /// <summary>−∇φ: the outward normal direction, Σ 6 (1 − q)² (x − p) / R².</summary>
        static Vec64 Gradient(Vec64[] c, List<int> candidates, Vec64 x, double support2)
        {
            var g = new Vec64(0, 0, 0);
            foreach (int i in candidates)
            {
                Vec64 d = x - c[i];
                double q = Vec64.Dot(d, d) / support2;
                if (q < 1)
                    g = g + (6 * (1 - q) * (1 - q) / support2) * d;
            }
            return g;
        }

        /// <summary>How a rendered depth and normal target compares with a reference surface of the same size.</summary>
        public struct Error
        {
            /// <summary>Pixels where both have a surface.</summary>
            public int Both;
            /// <summary>Pixels where exactly one has a surface, over those where either has one.</summary>
            public double CoverageMismatch;
            /// <summary>Mean and 95th percentile of |Δ depth| over pixels where both have a surface, in particle radii.</summary>
            public double MeanDepth, P95Depth;
            /// <summary>Mean and 95th percentile of the angle between the normals (degrees).</summary>
            public double MeanAngle, P95Angle;
        }

        /// <summary>Compares <paramref name="depth"/> and packed <paramref name="normals"/> (the renderer's targets) with <paramref name="reference"/>.</summary>
        public static Error Compare(Surface reference, ReadOnlySpan<float> depth, ReadOnlySpan<uint> normals, double radius)
        {
            var dz = new List<double>();
            var angles = new List<double>();
            int either = 0, one = 0;
            for (int i = 0; i < reference.Depth.Length; i++)
            {
                bool a = reference.Depth[i] > 0, b = depth[i] > 0f;
                if (a || b) either++;
                if (a != b) one++;
                if (!(a && b))
                    continue;
                dz.Add(Math.Abs(depth[i] - reference.Depth[i]) / radius);
                float3 n = FluidSurfacePasses.UnpackNormal(normals[i]);
                Vec64 m = reference.Normal[i];
                Vec64 u = new Vec64(n.x, n.y, n.z).Normalized;
                double cx = u.y * m.z - u.z * m.y, cy = u.z * m.x - u.x * m.z, cz = u.x * m.y - u.y * m.x;
                angles.Add(Math.Atan2(Math.Sqrt(cx * cx + cy * cy + cz * cz), Vec64.Dot(u, m)) * 180.0 / Math.PI);
            }
            var e = new Error { Both = dz.Count, CoverageMismatch = either == 0 ? 0 : one / (double)either };
            if (dz.Count > 0)
            {
                e.MeanDepth = Mean(dz);
                e.P95Depth = Percentile(dz, 0.95);
                e.MeanAngle = Mean(angles);
                e.P95Angle = Percentile(angles, 0.95);
            }
            return e;
        }

        static double Mean(List<double> v)
        {
            double s = 0;
            foreach (double x in v) s += x;
            return s / v.Count;
        }

        static double Percentile(List<double> v, double q)
        {
            v.Sort();
            return v[Math.Min(v.Count - 1, (int)Math.Floor(q * v.Count))];
        }
    }
}
