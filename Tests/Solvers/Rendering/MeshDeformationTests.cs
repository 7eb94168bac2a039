using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Render-vertex write-back: placement undone, welded normals, bounds.</summary>
    public class MeshDeformationTests
    {
        /// <summary>
        /// Unit cube as a render mesh usually is: 8 particles (the corners) and 24 render vertices, 4
        /// per face, so every corner is split into 3 render vertices. Faces are wound so that
        /// (b − a) × (c − a) points outwards, Unity's front-face convention.
        /// </summary>
        sealed class Cube
        {
            public readonly float3[] RestParticles = new float3[8];
            public readonly float3[] RestVertices = new float3[24];
            public readonly int[] VertexToParticle = new int[24];
            public readonly int[] Triangles = new int[36];
            public readonly float3 RestCenter;

            public Cube(float3 offset)
            {
                RestCenter = offset;
                for (int i = 0; i < 8; i++)
                    RestParticles[i] = offset + new float3((i & 1) - 0.5f, ((i >> 1) & 1) - 0.5f, ((i >> 2) & 1) - 0.5f);
                // (normal, a, b) with a × b = normal.
                var faces = new[]
                {
                    (new float3(1, 0, 0), new float3(0, 1, 0), new float3(0, 0, 1)),
                    (new float3(-1, 0, 0), new float3(0, 0, 1), new float3(0, 1, 0)),
                    (new float3(0, 1, 0), new float3(0, 0, 1), new float3(1, 0, 0)),
                    (new float3(0, -1, 0), new float3(1, 0, 0), new float3(0, 0, 1)),
                    (new float3(0, 0, 1), new float3(1, 0, 0), new float3(0, 1, 0)),
                    (new float3(0, 0, -1), new float3(0, 1, 0), new float3(1, 0, 0)),
                };
                for (int f = 0; f < 6; f++)
                {
                    var (n, a, b) = faces[f];
                    float3[] corners = { n - a - b, n + a - b, n + a + b, n - a + b };
                    for (int k = 0; k < 4; k++)
                    {
                        float3 p = 0.5f * corners[k];
                        RestVertices[4 * f + k] = offset + p;
                        VertexToParticle[4 * f + k] = (p.x > 0f ? 1 : 0) | (p.y > 0f ? 2 : 0) | (p.z > 0f ? 4 : 0);
                    }
                    int[] quad = { 0, 1, 2, 0, 2, 3 };
                    for (int k = 0; k < 6; k++)
                        Triangles[6 * f + k] = 4 * f + quad[k];
                }
            }

            /// <summary>Rest particles placed with their centre of mass at <paramref name="center"/>, rotated by <paramref name="rotation"/>.</summary>
            public float3[] Placed(float3 center, quaternion rotation)
            {
                var x = new float3[RestParticles.Length];
                for (int i = 0; i < x.Length; i++)
                    x[i] = center + math.rotate(rotation, RestParticles[i] - RestCenter);
                return x;
            }
        }

        static DeformedVertex[] Deform(float3[] particles, int[] vertexToParticle, int[] triangles, float3 center,
            quaternion rotation, float3 restCenter, out AxisAlignedBox bounds)
        {
            var vertices = new DeformedVertex[vertexToParticle.Length];
            bounds = MeshDeformation.Deform(particles, vertexToParticle, triangles, center, rotation, restCenter,
                new float3[particles.Length], new float3[particles.Length], vertices);
            return vertices;
        }

        static void AssertClose(float3 actual, float3 expected, float tolerance, string what)
        {
            Assert.That(math.distance(actual, expected), Is.LessThanOrEqualTo(tolerance), $"{what}: {actual} vs {expected}");
        }

        [Test]
        public void UndeformedCube_GivesItsRestVertices_AndUnitOutwardNormals()
        {
            var cube = new Cube(new float3(0.25f, -1f, 2f));
            var vertices = Deform(cube.Placed(cube.RestCenter, quaternion.identity), cube.VertexToParticle, cube.Triangles,
                cube.RestCenter, quaternion.identity, cube.RestCenter, out _);

            for (int v = 0; v < vertices.Length; v++)
            {
                AssertClose(vertices[v].Position, cube.RestVertices[v], 1e-6f, $"vertex {v}");
                Assert.That(math.length(vertices[v].Normal), Is.EqualTo(1f).Within(1e-5f), $"normal {v} is unit");
                float3 outward = cube.RestVertices[v] - cube.RestCenter;
                // A corner normal averages its three faces: it points into the corner's octant.
                Assert.That(math.all(math.sign(vertices[v].Normal) == math.sign(outward)), Is.True,
                    $"normal {v} {vertices[v].Normal} points out of the corner {outward}");
            }
        }

        [Test]
        public void RotationAndTranslation_OfTheBody_AreUndone([Values(0f, 0.7f, 2.5f, -3f)] float angle)
        {
            var cube = new Cube(new float3(0.1f, 0.2f, -0.3f));
            var reference = Deform(cube.RestParticles, cube.VertexToParticle, cube.Triangles, cube.RestCenter,
                quaternion.identity, cube.RestCenter, out _);

            float3 center = new float3(4f, -2f, 7.5f);
            quaternion rotation = quaternion.AxisAngle(math.normalize(new float3(1f, 2f, 3f)), angle);
            var vertices = Deform(cube.Placed(center, rotation), cube.VertexToParticle, cube.Triangles, center, rotation,
                cube.RestCenter, out _);

            for (int v = 0; v < vertices.Length; v++)
            {
                AssertClose(vertices[v].Position, cube.RestVertices[v], 1e-5f, $"vertex {v}");
                AssertClose(vertices[v].Normal, reference[v].Normal, 1e-5f, $"normal {v}");
            }
        }

        [Test]
        public void RenderVertices_OfOneParticle_ShareOneNormal()
        {
            var cube = new Cube(float3.zero);
            var particles = cube.Placed(float3.zero, quaternion.identity);
            particles[7] += new float3(0.2f, 0.1f, -0.05f); // a dent, so the corner normals differ from the undeformed ones
            var vertices = Deform(particles, cube.VertexToParticle, cube.Triangles, float3.zero, quaternion.identity,
                float3.zero, out _);

            for (int p = 0; p < 8; p++)
            {
                int first = Array.IndexOf(cube.VertexToParticle, p);
                int copies = 0;
                for (int v = 0; v < vertices.Length; v++)
                {
                    if (cube.VertexToParticle[v] != p)
                        continue;
                    copies++;
                    Assert.That(vertices[v].Normal.Equals(vertices[first].Normal), Is.True,
                        $"render vertices {first} and {v} of particle {p} are welded: same normal");
                    Assert.That(vertices[v].Position.Equals(vertices[first].Position), Is.True);
                }
                Assert.That(copies, Is.EqualTo(3), "each cube corner is split into three render vertices");
            }
        }

        [Test]
        public void Bounds_ContainEveryVertex_AndTouchTheExtremes()
        {
            var cube = new Cube(new float3(1f, 0f, 0f));
            float3 center = new float3(0f, 3f, 0f);
            quaternion rotation = quaternion.AxisAngle(new float3(0f, 1f, 0f), 0.4f);
            var particles = cube.Placed(center, rotation);
            for (int i = 0; i < particles.Length; i++)
                particles[i] += 0.2f * new float3(math.sin(1.7f * i), math.cos(2.3f * i), math.sin(0.9f * i + 1f));

            var vertices = Deform(particles, cube.VertexToParticle, cube.Triangles, center, rotation, cube.RestCenter,
                out AxisAlignedBox bounds);

            float3 min = new float3(float.MaxValue), max = new float3(float.MinValue);
            foreach (var vertex in vertices)
            {
                Assert.That(math.all(vertex.Position >= bounds.Min) && math.all(vertex.Position <= bounds.Max), Is.True,
                    $"{vertex.Position} inside [{bounds.Min}, {bounds.Max}]");
                min = math.min(min, vertex.Position);
                max = math.max(max, vertex.Position);
            }
            Assert.That(bounds.Min.Equals(min) && bounds.Max.Equals(max), Is.True, "the bounds are tight");
        }

        [Test]
        public void Normal_FollowsUnityWinding()
        {
            // The quad of Unity's procedural-mesh example faces −z (towards the default camera).
            var particles = new[] { new float3(0f, 0f, 0f), new float3(1f, 0f, 0f), new float3(0f, 1f, 0f), new float3(1f, 1f, 0f) };
            var vertices = Deform(particles, new[] { 0, 1, 2, 3 }, new[] { 0, 2, 1, 2, 3, 1 }, float3.zero,
                quaternion.identity, float3.zero, out _);
            foreach (var vertex in vertices)
                AssertClose(vertex.Normal, new float3(0f, 0f, -1f), 1e-6f, "quad normal");
        }

        [Test]
        public void Normal_IsAreaWeighted()
        {
            // Particle 0 is shared by a 2 m² triangle facing +y and a 0.5 m² triangle facing +x.
            var particles = new[]
            {
                float3.zero, new float3(0f, 0f, 2f), new float3(2f, 0f, 0f), new float3(0f, 1f, 0f), new float3(0f, 0f, 1f),
            };
            var vertices = Deform(particles, new[] { 0, 1, 2, 3, 4 }, new[] { 0, 1, 2, 0, 3, 4 }, float3.zero,
                quaternion.identity, float3.zero, out _);
            AssertClose(vertices[0].Normal, math.normalize(new float3(1f, 4f, 0f)), 1e-6f, "area-weighted normal");
        }

        [Test]
        public void VertexInNoTriangle_GetsTheFallbackNormal()
        {
            var particles = new[] { float3.zero, new float3(1f, 0f, 0f), new float3(0f, 1f, 0f), new float3(5f, 5f, 5f) };
            var vertices = Deform(particles, new[] { 0, 1, 2, 3 }, new[] { 0, 2, 1 }, float3.zero, quaternion.identity,
                float3.zero, out _);
            AssertClose(vertices[3].Normal, MeshDeformation.FallbackNormal, 0f, "isolated vertex");
        }

        [Test]
        public void EmptyMesh_GivesAZeroBox()
        {
            var bounds = MeshDeformation.Deform(new[] { new float3(1f, 2f, 3f) }, ReadOnlySpan<int>.Empty,
                ReadOnlySpan<int>.Empty, float3.zero, quaternion.identity, float3.zero, new float3[1], new float3[1],
                Span<DeformedVertex>.Empty);
            Assert.That(bounds.Min.Equals(float3.zero) && bounds.Max.Equals(float3.zero), Is.True);
        }
    }
}
