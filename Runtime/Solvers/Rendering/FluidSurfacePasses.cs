using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The surface passes in C# (float32), the reference each kernel of Shaders/FluidSurface.compute ports: the same
    /// expressions in the same order. Screen targets are row-major spans, row 0 at the bottom. Tile lists are not built
    /// here: each pixel tests every particle whose tile rectangle covers its tile, which gives the same pixels.
    /// </summary>
    public static class FluidSurfacePasses
    {
        const float Huge = 3.0e38f;

        public static float3 ToView(in FluidSurfaceConstants c, float3 w)
        {
            var p = new float4(w, 1f);
            return new float3(math.dot(c.ViewRow0, p), math.dot(c.ViewRow1, p), math.dot(c.ViewRow2, p));
        }

        /// <summary>Direction (z = −1) of the ray through the pixel position (x, y) of a target with this focal length and principal point.</summary>
        public static float3 PixelRay(float x, float y, float2 focal, float2 centre) =>
            new float3((x - centre.x) / focal.x, (y - centre.y) / focal.y, -1f);

        /// <summary>
        /// Eye depth of the first hit and chord length of the ray along d with the sphere (view centre c, radius² r2);
        /// zeros on a miss. The perpendicular offset is a vector difference, not |c|² − (d·c)², so a far camera loses no digits.
        /// </summary>
        public static float2 RaySphere(float3 d, float3 c, float r2)
        {
            float len = math.length(d);
            float3 u = d / len;
            float b = math.dot(u, c);
            float3 off = c - b * u;
            float h2 = r2 - math.dot(off, off);
            if (h2 <= 0f || b <= 0f)
                return float2.zero;
            float h = math.sqrt(h2);
            return new float2((b - h) / len, 2f * h);
        }

        /// <summary>Pixel range covered along one axis by a sphere at view (a, −z), radius r: the tangents from the eye, (a z ± r √(a² + z² − r²)) / (z² − r²).</summary>
        public static float2 SphereExtent(float a, float z, float r, float f, float c)
        {
            float s = r * math.sqrt(math.max(a * a + z * z - r * r, 0f));
            float inv = 1f / (z * z - r * r);
            return new float2(c + f * (a * z - s) * inv, c + f * (a * z + s) * inv);
        }

        /// <summary>First (xy) and last (zw) tile the particle covers; x &gt; z when culled (behind the near plane, off screen, not finite).</summary>
        public static int4 TileRect(in FluidSurfaceConstants k, float3 world)
        {
            float3 c = ToView(k, world);
            float z = -c.z;
            float r = k.ParticleRadius;
            if (!(z - r > k.NearPlane) || math.any(math.abs(c) > 3.0e38f))
                return new int4(1, 0, 0, 0);
            float2 ex = SphereExtent(c.x, z, r, k.DepthFocal.x, k.DepthCentre.x);
            float2 ey = SphereExtent(c.y, z, r, k.DepthFocal.y, k.DepthCentre.y);
            if (ex.y < 0f || ey.y < 0f || ex.x > k.DepthWidth || ey.x > k.DepthHeight)
                return new int4(1, 0, 0, 0);
            const int tile = FluidSurfaceLayout.TileSize;
            return new int4((int)math.floor(math.max(ex.x, 0f)) / tile, (int)math.floor(math.max(ey.x, 0f)) / tile,
                (int)math.floor(math.min(ex.y, k.DepthWidth - 1f)) / tile, (int)math.floor(math.min(ey.y, k.DepthHeight - 1f)) / tile);
        }

        /// <summary>Tile entries the particles need (the scan's total).</summary>
        public static int TileEntries(in FluidSurfaceConstants k, ReadOnlySpan<float4> particles)
        {
            int total = 0;
            for (int i = 0; i < (int)k.ParticleCount; i++)
            {
                int4 t = TileRect(k, particles[i].xyz);
                if (t.x <= t.z)
                    total += (t.z - t.x + 1) * (t.w - t.y + 1);
            }
            return total;
        }

        static bool Covers(int4 rect, int tx, int ty) => rect.x <= rect.z && tx >= rect.x && tx <= rect.z && ty >= rect.y && ty <= rect.w;

        /// <summary>SplatDepth: eye depth of the nearest sphere per depth pixel, 0 where none.</summary>
        public static void SplatDepth(in FluidSurfaceConstants k, ReadOnlySpan<float4> particles, Span<float> depth) =>
            SplatDepth(k, particles, depth, new int4[k.ParticleCount], new float4[k.ParticleCount], new int[k.ParticleCount]);

        /// <summary>
        /// SplatDepth with the caller's scratch (<see cref="FluidSurfaceConstants.ParticleCount"/> entries each): allocates
        /// nothing. Each tile first gathers the particles whose rectangle covers it, in index order, so every pixel tests
        /// the same particles in the same order as a test of every particle would.
        /// </summary>
        public static void SplatDepth(in FluidSurfaceConstants k, ReadOnlySpan<float4> particles, Span<float> depth, Span<int4> rects, Span<float4> centres,
            Span<int> covering)
        {
            int n = (int)k.ParticleCount, w = (int)k.DepthWidth, h = (int)k.DepthHeight;
            const int tile = FluidSurfaceLayout.TileSize;
            for (int i = 0; i < n; i++)
            {
                rects[i] = TileRect(k, particles[i].xyz);
                centres[i] = new float4(ToView(k, particles[i].xyz), 0f);
            }
            for (int ty = 0; ty * tile < h; ty++)
                for (int tx = 0; tx * tile < w; tx++)
                {
                    int count = Gather(rects, n, tx, ty, covering);
                    for (int y = ty * tile; y < math.min(h, (ty + 1) * tile); y++)
                        for (int x = tx * tile; x < math.min(w, (tx + 1) * tile); x++)
                        {
                            float3 ray = PixelRay(x + 0.5f, y + 0.5f, k.DepthFocal, k.DepthCentre);
                            float near = Huge;
                            for (int c = 0; c < count; c++)
                            {
                                float2 hit = RaySphere(ray, centres[covering[c]].xyz, k.ParticleRadiusSquared);
                                if (hit.y > 0f)
                                    near = math.min(near, hit.x);
                            }
                            depth[y * w + x] = near < Huge ? near : 0f;
                        }
                }
        }

        /// <summary>The particles whose rectangle covers tile (tx, ty), in index order; returns their count.</summary>
        static int Gather(ReadOnlySpan<int4> rects, int n, int tx, int ty, Span<int> covering)
        {
            int count = 0;
            for (int i = 0; i < n; i++)
                if (Covers(rects[i], tx, ty))
                    covering[count++] = i;
            return count;
        }

        /// <summary>SplatThickness: summed chords (m, in integer quanta of ThicknessQuantum) and their mean attribute (0–1) per thickness pixel.</summary>
        public static void SplatThickness(in FluidSurfaceConstants k, ReadOnlySpan<float4> particles, Span<float2> thickness) =>
            SplatThickness(k, particles, thickness, new int4[k.ParticleCount], new float4[k.ParticleCount], new int[k.ParticleCount]);

        /// <summary>SplatThickness with the caller's scratch (<see cref="FluidSurfaceConstants.ParticleCount"/> entries each): allocates nothing; tiles gather their particles as in SplatDepth.</summary>
        public static void SplatThickness(in FluidSurfaceConstants k, ReadOnlySpan<float4> particles, Span<float2> thickness, Span<int4> rects, Span<float4> spheres,
            Span<int> covering)
        {
            int n = (int)k.ParticleCount, w = (int)k.ThicknessWidth, h = (int)k.ThicknessHeight;
            int perTile = FluidSurfaceLayout.TileGroup * (int)k.ThicknessPixelsPerThread;
            for (int i = 0; i < n; i++)
            {
                rects[i] = TileRect(k, particles[i].xyz);
                spheres[i] = new float4(ToView(k, particles[i].xyz), math.saturate((particles[i].w - k.ColdAttribute) * k.InverseAttributeSpan));
            }
            float inverseQuantum = 1f / k.ThicknessQuantum;
            for (int ty = 0; ty * perTile < h; ty++)
                for (int tx = 0; tx * perTile < w; tx++)
                {
                    int count = Gather(rects, n, tx, ty, covering);
                    for (int y = ty * perTile; y < math.min(h, (ty + 1) * perTile); y++)
                        for (int x = tx * perTile; x < math.min(w, (tx + 1) * perTile); x++)
                        {
                            float3 ray = PixelRay(x + 0.5f, y + 0.5f, k.ThicknessFocal, k.ThicknessCentre);
                            uint sum = 0, attributes = 0;
                            for (int c = 0; c < count; c++)
                            {
                                float4 sphere = spheres[covering[c]];
                                float2 hit = RaySphere(ray, sphere.xyz, k.ParticleRadiusSquared);
                                sum += (uint)math.round(hit.y * inverseQuantum);
                                attributes += (uint)math.round(hit.y * sphere.w * inverseQuantum);
                            }
                            thickness[y * w + x] = new float2(sum * k.ThicknessQuantum, sum > 0 ? attributes / (float)sum : 0f);
                        }
                }
        }

        static bool InDepth(in FluidSurfaceConstants k, int x, int y) => x >= 0 && y >= 0 && x < k.DepthWidth && y < k.DepthHeight;

        static float At(in FluidSurfaceConstants k, ReadOnlySpan<float> depth, int x, int y) =>
            InDepth(k, x, y) ? depth[y * (int)k.DepthWidth + x] : 0f;

        /// <summary>
        /// One separable pass along (ax, ay): narrow-range (Truong &amp; Yuksel 2018, §4: samples more than μ behind are
        /// skipped, more than μ in front clamped to z₀ − μ, Gaussian in screen distance) or bilateral (Gaussian in screen
        /// distance times Gaussian in depth difference, σ = μ). Empty pixels stay empty and are never sampled.
        /// </summary>
        public static void Separable(in FluidSurfaceConstants k, ReadOnlySpan<float> input, Span<float> output, int ax, int ay, bool narrow)
        {
            int w = (int)k.DepthWidth;
            for (int y = 0; y < (int)k.DepthHeight; y++)
                for (int x = 0; x < w; x++)
                {
                    float z0 = input[y * w + x];
                    if (z0 <= 0f)
                    {
                        output[y * w + x] = 0f;
                        continue;
                    }
                    float radius = math.min(k.FilterRadius * k.DepthFocal.x / z0, k.MaxFilterPixels);
                    int n = (int)math.ceil(radius);
                    float inverseSigma2 = 4f / math.max(radius * radius, 1e-6f);
                    float mu = k.DepthRange;
                    float sum = 0f, weights = 0f;
                    for (int i = -n; i <= n; i++)
                    {
                        int qx = x + ax * i, qy = y + ay * i;
                        if (!InDepth(k, qx, qy))
                            continue;
                        float z = input[qy * w + qx];
                        if (z <= 0f)
                            continue;
                        float wt = math.exp(-0.5f * (i * i) * inverseSigma2);
                        if (narrow)
                        {
                            if (z > z0 + mu)
                                continue;
                            z = math.max(z, z0 - mu);
                        }
                        else
                        {
                            float dz = (z - z0) / mu;
                            wt *= math.exp(-0.5f * dz * dz);
                        }
                        sum += wt * z;
                        weights += wt;
                    }
                    output[y * w + x] = sum / weights;
                }
        }

        /// <summary>
        /// One explicit step of screen-space curvature flow (van der Laan, Green &amp; Sainz 2009, eqs. 3–9) with C = 1/f:
        /// D = C²(z_x² + z_y²) + C⁴z², E_x = ½ z_x ∂D/∂x − z_xx D, H = C (E_x + E_y) / (2 D^{3/2}), z ← z − ε H with
        /// ε = 2 λ C z, which for a nearly flat surface is z + λ (z_xx + z_yy): stable for λ ≤ ¼. Silhouette pixels (a
        /// neighbour empty or more than μ away in depth) keep their depth.
        /// </summary>
        public static void CurvatureFlow(in FluidSurfaceConstants k, ReadOnlySpan<float> input, Span<float> output)
        {
            int w = (int)k.DepthWidth;
            float mu = k.DepthRange;
            for (int y = 0; y < (int)k.DepthHeight; y++)
                for (int x = 0; x < w; x++)
                {
                    float z = input[y * w + x];
                    float zl = At(k, input, x - 1, y), zr = At(k, input, x + 1, y), zd = At(k, input, x, y - 1), zu = At(k, input, x, y + 1);
                    bool edge = z <= 0f || zl <= 0f || zr <= 0f || zd <= 0f || zu <= 0f
                        || math.abs(zl - z) > mu || math.abs(zr - z) > mu || math.abs(zd - z) > mu || math.abs(zu - z) > mu;
                    if (edge)
                    {
                        output[y * w + x] = z;
                        continue;
                    }
                    float zul = At(k, input, x - 1, y + 1), zur = At(k, input, x + 1, y + 1);
                    float zdl = At(k, input, x - 1, y - 1), zdr = At(k, input, x + 1, y - 1);
                    bool corners = zul > 0f && zur > 0f && zdl > 0f && zdr > 0f;
                    float c = 1f / k.DepthFocal.x;
                    float c2 = c * c;
                    float zx = 0.5f * (zr - zl), zy = 0.5f * (zu - zd);
                    float zxx = zr - 2f * z + zl, zyy = zu - 2f * z + zd;
                    float zxy = corners ? 0.25f * (zur - zul - zdr + zdl) : 0f;
                    float d = c2 * (zx * zx + zy * zy) + c2 * c2 * z * z;
                    float dDx = 2f * c2 * (zx * zxx + zy * zxy) + 2f * c2 * c2 * z * zx;
                    float dDy = 2f * c2 * (zx * zxy + zy * zyy) + 2f * c2 * c2 * z * zy;
                    float ex = 0.5f * zx * dDx - zxx * d;
                    float ey = 0.5f * zy * dDy - zyy * d;
                    float h = c * (ex + ey) / (2f * d * math.sqrt(d));
                    output[y * w + x] = z - 2f * k.CurvatureStep * c * z * h;
                }
        }

        /// <summary>The frame's smoothing on the CPU (the passes FluidSurfaceFrame.RecordSmoothing records for these settings); the result ends where FluidSurfaceFrame.SmoothedDepth says.</summary>
        public static void Smooth(in FluidSurfaceConstants k, in FluidSurfaceSettings s, Span<float> a, Span<float> b)
        {
            for (int i = 0; i < s.Iterations && s.Filter != FluidSurfaceFilter.None; i++)
            {
                if (s.Filter == FluidSurfaceFilter.CurvatureFlow)
                {
                    if (i % 2 == 0) CurvatureFlow(k, a, b); else CurvatureFlow(k, b, a);
                    continue;
                }
                bool narrow = s.Filter == FluidSurfaceFilter.NarrowRange;
                Separable(k, a, b, 1, 0, narrow);
                Separable(k, b, a, 0, 1, narrow);
            }
        }

        /// <summary>Octahedral packing of a unit vector into 16 + 16 bits.</summary>
        public static uint PackNormal(float3 n)
        {
            n /= math.abs(n.x) + math.abs(n.y) + math.abs(n.z);
            float ox = n.x, oy = n.y;
            if (n.z < 0f)
            {
                ox = (1f - math.abs(n.y)) * (n.x >= 0f ? 1f : -1f);
                oy = (1f - math.abs(n.x)) * (n.y >= 0f ? 1f : -1f);
            }
            uint qx = (uint)math.round(math.saturate(ox * 0.5f + 0.5f) * 65535f);
            uint qy = (uint)math.round(math.saturate(oy * 0.5f + 0.5f) * 65535f);
            return qx | (qy << 16);
        }

        public static float3 UnpackNormal(uint packed)
        {
            float ox = (packed & 0xFFFFu) / 65535f * 2f - 1f, oy = (packed >> 16) / 65535f * 2f - 1f;
            var n = new float3(ox, oy, 1f - math.abs(ox) - math.abs(oy));
            float t = math.saturate(-n.z);
            n.x += n.x >= 0f ? -t : t;
            n.y += n.y >= 0f ? -t : t;
            return math.normalize(n);
        }

        static float3 ViewPositionAt(in FluidSurfaceConstants k, int x, int y, float z) => PixelRay(x + 0.5f, y + 0.5f, k.DepthFocal, k.DepthCentre) * z;

        static float3 Tangent(in FluidSurfaceConstants k, ReadOnlySpan<float> depth, int x, int y, int ax, int ay, float z, float3 v)
        {
            float zf = At(k, depth, x + ax, y + ay), zb = At(k, depth, x - ax, y - ay);
            float mu = k.DepthRange;
            bool useF = zf > 0f && math.abs(zf - z) <= mu;
            bool useB = zb > 0f && math.abs(zb - z) <= mu;
            if (useF && (!useB || math.abs(zf - z) <= math.abs(zb - z)))
                return ViewPositionAt(k, x + ax, y + ay, zf) - v;
            if (useB)
                return v - ViewPositionAt(k, x - ax, y - ay, zb);
            return new float3(ax, ay, 0f) * (z / k.DepthFocal.x);
        }

        /// <summary>
        /// Normals: packed view-space normal per depth pixel from the smoothed depth; along each axis the one-sided
        /// difference with the smaller depth step, so a silhouette does not tilt the normal towards the background.
        /// </summary>
        public static void Normals(in FluidSurfaceConstants k, ReadOnlySpan<float> depth, Span<uint> normals)
        {
            int w = (int)k.DepthWidth;
            for (int y = 0; y < (int)k.DepthHeight; y++)
                for (int x = 0; x < w; x++)
                {
                    float z = depth[y * w + x];
                    if (z <= 0f)
                    {
                        normals[y * w + x] = PackNormal(new float3(0f, 0f, 1f));
                        continue;
                    }
                    float3 v = ViewPositionAt(k, x, y, z);
                    float3 n = math.cross(Tangent(k, depth, x, y, 1, 0, z, v), Tangent(k, depth, x, y, 0, 1, z, v));
                    float len = math.length(n);
                    normals[y * w + x] = PackNormal(len > 0f ? n / len : new float3(0f, 0f, 1f));
                }
        }
    }
}
