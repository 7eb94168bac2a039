using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks
{
    /// <summary>
    /// The body of the mesh write-back benchmarks, shared by the Unity performance test
    /// (<c>MeshWriteBackPerformanceTests</c>) and the headless timing tool
    /// (<c>Tools~/DotNet/SoftBodyDynamics.MeshWriteBackTiming</c>), which compiles this file: a UV sphere of 1 m
    /// diameter with <see cref="Segments"/> × <see cref="Rings"/> segments, its seam column and pole rows split into
    /// separate render vertices as in Unity's built-in sphere (425 vertices, 720 triangles, 362 welded surface
    /// particles), filled with interior particles every 0.2 m and cut into 0.5 m clusters like the sample's bodies.
    /// Pure C# (Unity.Mathematics and the solvers only).
    /// </summary>
    public static class MeshWriteBackBody
    {
        /// <summary>Body counts every write-back benchmark measures.</summary>
        public static readonly int[] BodyCounts = { 1, 100, 1000 };

        /// <summary>Segments around the vertical axis.</summary>
        public const int Segments = 24;
        /// <summary>Rings from pole to pole.</summary>
        public const int Rings = 16;
        /// <summary>Sphere radius (m).</summary>
        public const float Radius = 0.5f;

        /// <summary>Render vertices: (Segments + 1) × (Rings + 1), the seam column and the pole rows repeated.</summary>
        public const int VertexCount = (Segments + 1) * (Rings + 1);

        /// <summary>
        /// The sphere's render vertices, normals and triangles. Vertex (r, j) sits at polar angle π·r/Rings and
        /// azimuth 2π·j/Segments; each pole cap is one fan of triangles, every other band two triangles per
        /// quad, wound as Unity expects (clockwise seen from outside: (b − a) × (c − a) points out).
        /// </summary>
        public static void Sphere(out float3[] vertices, out float3[] normals, out int[] triangles)
        {
            vertices = new float3[VertexCount];
            normals = new float3[VertexCount];
            for (int r = 0; r <= Rings; r++)
            for (int j = 0; j <= Segments; j++)
            {
                // Exact poles, so the pole rows weld into one particle each.
                float polar = math.PI * r / Rings;
                float azimuth = 2f * math.PI * (j % Segments) / Segments;
                math.sincos(polar, out float sinPolar, out float cosPolar);
                math.sincos(azimuth, out float sinAzimuth, out float cosAzimuth);
                if (r == 0 || r == Rings)
                {
                    sinPolar = 0f;
                    cosPolar = r == 0 ? 1f : -1f;
                }
                var n = new float3(sinPolar * cosAzimuth, cosPolar, sinPolar * sinAzimuth);
                vertices[Index(r, j)] = Radius * n;
                normals[Index(r, j)] = n;
            }

            var list = new List<int>(6 * Segments * Rings);
            for (int r = 0; r < Rings; r++)
            for (int j = 0; j < Segments; j++)
            {
                int a = Index(r, j), b = Index(r, j + 1), c = Index(r + 1, j), d = Index(r + 1, j + 1);
                if (r > 0)
                    AddOutward(list, vertices, a, b, d);
                if (r < Rings - 1)
                    AddOutward(list, vertices, a, d, c);
            }
            triangles = list.ToArray();
        }

        /// <summary>Interior particles every 0.2 m, 0.5 m clusters, 1 kg: the settings of the sample's bodies.</summary>
        public static SoftBodyBuildSettings BuildSettings
        {
            get
            {
                SoftBodyBuildSettings settings = SoftBodyBuildSettings.Default;
                settings.AddInteriorParticles = true;
                settings.InteriorSpacing = 0.2f;
                settings.ClusterSize = 0.5f;
                settings.TotalMass = 1f;
                return settings;
            }
        }

        /// <summary>Builds the body from <see cref="Sphere"/>; throws if the builder reports an error.</summary>
        public static SoftBodyBuildResult Build(out float3[] vertices, out float3[] normals, out int[] triangles)
        {
            Sphere(out vertices, out normals, out triangles);
            SoftBodyBuildResult result = SoftBodyBuilder.Build(vertices, triangles, BuildSettings);
            if (!result.Succeeded)
                throw new InvalidOperationException("The write-back benchmark sphere did not build: " +
                    string.Join("; ", result.Issues.ConvertAll(i => i.Message)));
            return result;
        }

        /// <summary>
        /// Where body <paramref name="index"/> of a benchmark stands (m): a 10 × 10 × 10 grid with 2 m spacing above the
        /// ground, within 20 m of the world origin, so bodies do not touch and their particle positions stay world
        /// positions (the solver moves a body's origin only beyond 64 m).
        /// </summary>
        public static float3 Position(int index) => new float3(2f * (index % 10), 1f + 2f * (index / 100 % 10), 2f * (index / 10 % 10));

        static int Index(int ring, int segment) => ring * (Segments + 1) + segment;

        /// <summary>Adds (a, b, c), or (a, c, b) when that is the order whose normal points away from the centre.</summary>
        static void AddOutward(List<int> list, float3[] vertices, int a, int b, int c)
        {
            float3 n = math.cross(vertices[b] - vertices[a], vertices[c] - vertices[a]);
            bool outward = math.dot(n, vertices[a] + vertices[b] + vertices[c]) > 0f;
            list.Add(a);
            list.Add(outward ? b : c);
            list.Add(outward ? c : b);
        }
    }
}
