using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Welding render vertices into particles. A particle sits exactly at its first vertex, so exact
    /// copies compare bitwise; copies that differ by float32 round-off (sphere seam and poles, ≤ 2e-7 m)
    /// are checked against the weld distance itself.
    /// </summary>
    public class MeshWeldingTests
    {
        [Test]
        public void Weld_MergesCubeCornersToEightParticles()
        {
            TestMeshes.UnityCube(out float3[] vertices, out _);
            WeldedVertices welded = MeshWelding.Weld(vertices, 1e-5f);

            Assert.That(vertices.Length, Is.EqualTo(24));
            Assert.That(welded.ParticleCount, Is.EqualTo(8));
            var uses = new int[welded.ParticleCount];
            for (int v = 0; v < vertices.Length; v++)
            {
                int p = welded.VertexToParticle[v];
                Assert.That(welded.Positions[p].Equals(vertices[v]), Is.True, $"vertex {v} maps to particle {p} at another position");
                uses[p]++;
            }
            Assert.That(uses, Is.All.EqualTo(3), "each corner of a cube is shared by three faces");
            for (int a = 0; a < 8; a++)
            for (int b = a + 1; b < 8; b++)
                Assert.That(welded.Positions[a].Equals(welded.Positions[b]), Is.False, $"particles {a} and {b} coincide");
        }

        [Test]
        public void Weld_NumbersParticlesInOrderOfFirstVertex()
        {
            TestMeshes.UnityCube(out float3[] vertices, out _);
            WeldedVertices welded = MeshWelding.Weld(vertices, 1e-5f);
            int next = 0;
            foreach (int p in welded.VertexToParticle)
            {
                Assert.That(p, Is.LessThanOrEqualTo(next));
                if (p == next)
                    next++;
            }
        }

        [Test]
        public void Weld_MergesUvSphereSeamAndPoles()
        {
            const int rings = 16, segments = 24;
            TestMeshes.UvSphere(rings, segments, out float3[] vertices, out _);
            float tolerance = MeshWelding.ResolveTolerance(AxisAlignedBox.Of(vertices), MeshWelding.DefaultRelativeTolerance, 0f);
            WeldedVertices welded = MeshWelding.Weld(vertices, tolerance);

            Assert.That(welded.ParticleCount, Is.EqualTo((rings - 1) * segments + 2), "one particle per ring vertex plus the two poles");
            for (int v = 0; v < vertices.Length; v++)
                Assert.That(math.distance(vertices[v], welded.Positions[welded.VertexToParticle[v]]), Is.LessThanOrEqualTo(tolerance), $"vertex {v}");
            for (int a = 0; a < welded.ParticleCount; a++)
            for (int b = a + 1; b < welded.ParticleCount; b++)
                Assert.That(math.distance(welded.Positions[a], welded.Positions[b]), Is.GreaterThan(tolerance), $"particles {a} and {b}");
        }

        [Test]
        public void Weld_MergesWithinToleranceAndKeepsVerticesBeyondIt()
        {
            // Distances 0.5 mm and 2 mm against a 1 mm tolerance: far from the boundary at float32 precision.
            float3[] vertices = { new float3(0f), new float3(5e-4f, 0f, 0f), new float3(2e-3f, 0f, 0f) };
            WeldedVertices welded = MeshWelding.Weld(vertices, 1e-3f);
            Assert.That(welded.VertexToParticle, Is.EqualTo(new[] { 0, 0, 1 }));
            Assert.That(welded.Positions[0].Equals(vertices[0]), Is.True, "a particle stays at its first vertex");
        }

        [Test]
        public void Weld_ZeroToleranceMergesOnlyIdenticalPositions()
        {
            float3[] vertices = { new float3(1f, 2f, 3f), new float3(1f, 2f, math.asfloat(math.asuint(3f) + 1u)), new float3(1f, 2f, 3f) };
            WeldedVertices welded = MeshWelding.Weld(vertices, 0f);
            Assert.That(welded.VertexToParticle, Is.EqualTo(new[] { 0, 1, 0 }));
        }

        [Test]
        public void ResolveTolerance_ScalesWithDiagonalUnlessAbsoluteIsSet()
        {
            TestMeshes.UnityCube(out float3[] vertices, out _, 2f);
            AxisAlignedBox bounds = AxisAlignedBox.Of(vertices);
            // 1e-5f, the diagonal 2√3 m and their product are each rounded once to float (≤ 1.5ε relative), and
            // the expected value is rounded once more (≤ ε/2): they differ by at most 2ε relative.
            float expected = (float)(1e-5 * 2.0 * System.Math.Sqrt(3.0));
            Assert.That(MeshWelding.ResolveTolerance(bounds, 1e-5f, 0f), Is.EqualTo(expected).Within(2f * math.EPSILON * expected));
            Assert.That(MeshWelding.ResolveTolerance(bounds, 1e-5f, 0.01f), Is.EqualTo(0.01f));
        }
    }
}
