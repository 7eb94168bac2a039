using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Small meshes and point sets with known welding, topology and interior, for the building tests.</summary>
    static class TestMeshes
    {
        /// <summary>
        /// A cube laid out like Unity's built-in one: 6 faces × 4 vertices (split for hard normals and UVs),
        /// 12 triangles wound counter-clockwise seen from outside. Corners are centre ± 0.5·size, exact in float
        /// for the sizes and centres the tests use.
        /// </summary>
        public static void UnityCube(out float3[] vertices, out int[] triangles, float size = 1f, float3 center = default)
        {
            // (normal, u, v) with u × v = normal.
            float3[] frames =
            {
                new float3(1, 0, 0), new float3(0, 1, 0), new float3(0, 0, 1),
                new float3(-1, 0, 0), new float3(0, 0, 1), new float3(0, 1, 0),
                new float3(0, 1, 0), new float3(0, 0, 1), new float3(1, 0, 0),
                new float3(0, -1, 0), new float3(1, 0, 0), new float3(0, 0, 1),
                new float3(0, 0, 1), new float3(1, 0, 0), new float3(0, 1, 0),
                new float3(0, 0, -1), new float3(0, 1, 0), new float3(1, 0, 0),
            };
            vertices = new float3[24];
            triangles = new int[36];
            for (int f = 0; f < 6; f++)
            {
                float3 n = frames[3 * f], u = frames[3 * f + 1], v = frames[3 * f + 2];
                vertices[4 * f] = center + 0.5f * size * (n - u - v);
                vertices[4 * f + 1] = center + 0.5f * size * (n + u - v);
                vertices[4 * f + 2] = center + 0.5f * size * (n + u + v);
                vertices[4 * f + 3] = center + 0.5f * size * (n - u + v);
                int[] face = { 0, 1, 2, 0, 2, 3 };
                for (int k = 0; k < 6; k++)
                    triangles[6 * f + k] = 4 * f + face[k];
            }
        }

        /// <summary>
        /// A UV sphere of radius 1 as modelling tools export it: (rings + 1) × (segments + 1) vertices, with the
        /// seam column duplicated and each pole repeated segments + 1 times, two triangles per quad (so each
        /// pole row has one triangle per quad that collapses when the pole is welded). Positions come from
        /// float32 sin/cos, so the seam and pole copies differ by round-off (≤ 2e-7), not exactly.
        /// Welds to (rings − 1)·segments + 2 particles with 2·segments degenerate triangles.
        /// </summary>
        public static void UvSphere(int rings, int segments, out float3[] vertices, out int[] triangles)
        {
            vertices = new float3[(rings + 1) * (segments + 1)];
            for (int r = 0; r <= rings; r++)
            {
                float theta = math.PI * r / rings;
                for (int s = 0; s <= segments; s++)
                {
                    float phi = 2f * math.PI * s / segments;
                    vertices[r * (segments + 1) + s] = new float3(math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi));
                }
            }
            var list = new List<int>();
            for (int r = 0; r < rings; r++)
            for (int s = 0; s < segments; s++)
            {
                int a = r * (segments + 1) + s, b = a + segments + 1;
                list.AddRange(new[] { a, b, a + 1, a + 1, b, b + 1 });
            }
            triangles = list.ToArray();
        }

        /// <summary>
        /// A torus around the y axis (major radius 1 m, minor 0.4 m) exported like a UV mesh: the seam rows and
        /// columns are duplicated, so it is closed only after welding. Not convex, genus 1.
        /// </summary>
        public static void Torus(int around, int tube, float3 center, out float3[] vertices, out int[] triangles)
        {
            vertices = new float3[(around + 1) * (tube + 1)];
            for (int a = 0; a <= around; a++)
            {
                float phi = 2f * math.PI * a / around;
                for (int b = 0; b <= tube; b++)
                {
                    float theta = 2f * math.PI * b / tube;
                    float ring = 1f + 0.4f * math.cos(theta);
                    vertices[a * (tube + 1) + b] = center + new float3(ring * math.cos(phi), 0.4f * math.sin(theta), ring * math.sin(phi));
                }
            }
            var list = new List<int>();
            for (int a = 0; a < around; a++)
            for (int b = 0; b < tube; b++)
            {
                int i = a * (tube + 1) + b, j = i + tube + 1;
                list.AddRange(new[] { i, i + 1, j, i + 1, j + 1, j });
            }
            triangles = list.ToArray();
        }

        /// <summary>A unit square in the xy plane as two triangles: open, with 4 boundary edges.</summary>
        public static void OpenQuad(out float3[] vertices, out int[] triangles)
        {
            vertices = new[] { new float3(0, 0, 0), new float3(1, 0, 0), new float3(1, 1, 0), new float3(0, 1, 0) };
            triangles = new[] { 0, 1, 2, 0, 2, 3 };
        }

        /// <summary>
        /// A closed box with a cavity: the cube [−1, 1]³ facing outwards plus the cube [−½, ½]³ facing
        /// inwards (its triangles reversed), both Unity-style (48 vertices, 24 triangles).
        /// </summary>
        public static void HollowBox(out float3[] vertices, out int[] triangles)
        {
            UnityCube(out float3[] outer, out int[] outerTriangles, 2f);
            UnityCube(out float3[] inner, out int[] innerTriangles, 1f);
            vertices = new float3[outer.Length + inner.Length];
            outer.CopyTo(vertices, 0);
            inner.CopyTo(vertices, outer.Length);
            int[] reversedInner = Reversed(innerTriangles);
            triangles = new int[outerTriangles.Length + reversedInner.Length];
            outerTriangles.CopyTo(triangles, 0);
            for (int i = 0; i < reversedInner.Length; i++)
                triangles[outerTriangles.Length + i] = reversedInner[i] + outer.Length;
        }

        /// <summary>n × n × n points at spacing <paramref name="spacing"/> from the origin, x fastest (exact in float for the spacings used).</summary>
        public static float3[] Grid(int n, float spacing)
        {
            var points = new float3[n * n * n];
            for (int k = 0; k < n; k++)
            for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++)
                points[i + n * (j + n * k)] = new float3(i, j, k) * spacing;
            return points;
        }

        /// <summary>A copy of <paramref name="triangles"/> with every triangle wound the other way (second and third corners swapped).</summary>
        public static int[] Reversed(int[] triangles)
        {
            var copy = (int[])triangles.Clone();
            for (int t = 0; t < triangles.Length / 3; t++)
            {
                copy[3 * t + 1] = triangles[3 * t + 2];
                copy[3 * t + 2] = triangles[3 * t + 1];
            }
            return copy;
        }

        /// <summary>
        /// Welds <paramref name="vertices"/> at the default relative tolerance (as <see cref="SoftBodyBuildSettings.Default"/> does)
        /// and gives the triangles as particle indices.
        /// </summary>
        public static WeldedVertices WeldAtDefaultTolerance(float3[] vertices, int[] triangles, out int[] particleTriangles)
        {
            float tolerance = MeshWelding.ResolveTolerance(AxisAlignedBox.Of(vertices), MeshWelding.DefaultRelativeTolerance, 0f);
            WeldedVertices welded = MeshWelding.Weld(vertices, tolerance);
            particleTriangles = MeshWelding.RemapTriangles(triangles, welded.VertexToParticle);
            return welded;
        }

        /// <summary>A copy of <paramref name="triangles"/> with triangle <paramref name="triangle"/> wound the other way.</summary>
        public static int[] FlipTriangle(int[] triangles, int triangle)
        {
            var copy = (int[])triangles.Clone();
            copy[3 * triangle + 1] = triangles[3 * triangle + 2];
            copy[3 * triangle + 2] = triangles[3 * triangle + 1];
            return copy;
        }
    }
}
