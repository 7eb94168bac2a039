using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Geometry of the lattice tetrahedralisation: orientation, conformity, volume, embedding, determinism.</summary>
    public class LatticeTetrahedralizerTests
    {
        static TetrahedralizationResult Build(float3[] vertices, int[] triangles, int resolution)
        {
            TetrahedralizationSettings settings = TetrahedralizationSettings.Default;
            settings.Resolution = resolution;
            TetrahedralizationResult result = LatticeTetrahedralizer.Build(vertices, triangles, settings);
            Assert.That(result.Succeeded, Is.True, string.Join("; ", result.Issues));
            return result;
        }

        /// <summary>
        /// Σ wₖ xₖ reproduces the vertex: rounding each weight to float (≤ ε/2 relative), four float products and three
        /// sums (≤ 3ε on the running sum) give |Σ wₖ xₖ − p| ≤ 4ε·Σ|wₖ||xₖ| per coordinate (ε = 2⁻²³); 6ε leaves room.
        /// </summary>
        static void AssertReproduces(TetrahedralMesh mesh, EmbeddedVertex[] embedding, float3[] vertices, out float worstRatio)
        {
            Assert.That(embedding.Length, Is.EqualTo(vertices.Length));
            var rebuilt = new float3[vertices.Length];
            EmbeddedMeshDeformation.Deform(embedding, mesh.Positions, rebuilt);
            worstRatio = 0f;
            for (int v = 0; v < vertices.Length; v++)
            {
                EmbeddedVertex e = embedding[v];
                float3 scale = math.abs(e.Weights.x * mesh.Positions[e.Nodes.x]) + math.abs(e.Weights.y * mesh.Positions[e.Nodes.y])
                               + math.abs(e.Weights.z * mesh.Positions[e.Nodes.z]) + math.abs(e.Weights.w * mesh.Positions[e.Nodes.w]);
                float3 error = math.abs(rebuilt[v] - vertices[v]);
                float3 bound = 6f * TetMeshAssert.Epsilon * scale;
                Assert.That(error.x <= bound.x && error.y <= bound.y && error.z <= bound.z, Is.True,
                    $"vertex {v}: error {error}, bound {bound}");
                worstRatio = math.max(worstRatio, math.cmax(error / math.max(scale, new float3(1e-30f))) / TetMeshAssert.Epsilon);
            }
        }

        [TestCase(1)]
        [TestCase(3)]
        [TestCase(5)]
        public void Cube_ResolutionN_GivesNCubedCellsOfTotalVolume(int n)
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            TetrahedralizationResult result = Build(vertices, triangles, n);
            Assert.That(result.CellCount, Is.EqualTo(n * n * n));
            Assert.That(result.Mesh.TetrahedronCount, Is.EqualTo(6 * n * n * n));
            Assert.That(result.Mesh.NodeCount, Is.EqualTo((n + 1) * (n + 1) * (n + 1)));
            // The boundary nodes are exactly ±0.5 and the volume is a sum of 6n³ doubles: round-off ~1e-15.
            Assert.That(result.TetrahedralVolume, Is.EqualTo(1.0).Within(1e-9));
            Assert.That(result.SurfaceVolume, Is.EqualTo(1.0).Within(1e-9));
            TetMeshAssert.AllPositive(result.Mesh);
            int boundary = TetMeshAssert.Conforms(result.Mesh);
            Assert.That(boundary, Is.EqualTo(6 * 2 * n * n), "two boundary triangles per cell face on the cube's surface");
        }

        [Test]
        public void Box2x1x1_Resolution4_HasSquareCells()
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            for (int v = 0; v < vertices.Length; v++)
                vertices[v] *= new float3(2f, 1f, 1f);
            TetrahedralizationResult result = Build(vertices, triangles, 4);
            Assert.That(result.CellSize, Is.EqualTo(0.5f));
            Assert.That(result.CellCount, Is.EqualTo(4 * 2 * 2));
            Assert.That(result.TetrahedralVolume, Is.EqualTo(2.0).Within(1e-9));
        }

        [Test]
        public void Torus_TetsPositive_MeshConforms_EmbeddingReproducesVertices()
        {
            TestMeshes.Torus(24, 12, new float3(0.3f, -0.2f, 0.1f), out float3[] vertices, out int[] triangles);
            TetrahedralizationResult result = Build(vertices, triangles, 10);
            TetMeshAssert.AllPositive(result.Mesh);
            TetMeshAssert.Conforms(result.Mesh);
            AssertReproduces(result.Mesh, result.Embedding, vertices, out float worst);
            TestContext.WriteLine($"torus R=10: {result.CellCount} cells, {result.Mesh.NodeCount} nodes, {result.Mesh.TetrahedronCount} tets, worst reproduction error {worst:0.00} ε·Σ|w||x|");
            // Every render vertex lies in a kept cell, so its weights are in [0, 1] up to the inside tolerance.
            foreach (EmbeddedVertex e in result.Embedding)
                Assert.That(math.min(math.min(e.Weights.x, e.Weights.y), math.min(e.Weights.z, e.Weights.w)), Is.GreaterThanOrEqualTo(-1e-6f));
            // The hole is not filled: the torus axis (centre + t·y) is outside the surface and no cell holds a vertex there.
            var centre = new float3(0.3f, -0.2f, 0.1f);
            foreach (int4 q in result.Mesh.Tetrahedra)
            {
                TetrahedralEmbedding.Barycentric(centre, result.Mesh.Positions[q.x], result.Mesh.Positions[q.y], result.Mesh.Positions[q.z], result.Mesh.Positions[q.w],
                    out double l0, out double l1, out double l2, out double l3);
                Assert.That(Math.Min(Math.Min(l0, l1), Math.Min(l2, l3)), Is.LessThan(0.0), "the torus hole holds tetrahedra");
            }
        }

        /// <summary>
        /// The volume of the tetrahedra covers the surface (surface cells are kept) and exceeds it by about
        /// area × h / 2, which halves with each doubling of the resolution (O(h)); the UV sphere's own volume is
        /// within 1 % of 4/3 π at 24 × 48.
        /// </summary>
        [Test]
        public void Sphere_VolumeErrorFallsWithResolution()
        {
            TestMeshes.UvSphere(24, 48, out float3[] vertices, out int[] triangles);
            double exact = 4.0 / 3.0 * Math.PI;
            double previous = double.PositiveInfinity;
            foreach (int resolution in new[] { 4, 8, 16, 32 })
            {
                TetrahedralizationResult result = Build(vertices, triangles, resolution);
                double error = Math.Abs(result.TetrahedralVolume - exact) / exact;
                TestContext.WriteLine($"R={resolution}: {result.CellCount} cells, {result.Mesh.TetrahedronCount} tets, tet volume {result.TetrahedralVolume:0.0000}, surface {result.SurfaceVolume:0.0000}, exact {exact:0.0000}, relative error {error:0.0000}");
                Assert.That(result.TetrahedralVolume, Is.GreaterThan(result.SurfaceVolume));
                Assert.That(error, Is.LessThan(previous));
                previous = error;
            }
            // At R = 32 (h = 1/16) the excess area·h/2 ≈ 4π/32 ≈ 0.39, 9 % of 4.19; allow 15 %.
            Assert.That(previous, Is.LessThan(0.15));
        }

        [Test]
        public void Sphere_EmbeddingReproducesEveryVertex()
        {
            TestMeshes.UvSphere(16, 32, out float3[] vertices, out int[] triangles);
            TetrahedralizationResult result = Build(vertices, triangles, 5);
            TetMeshAssert.AllPositive(result.Mesh);
            TetMeshAssert.Conforms(result.Mesh);
            AssertReproduces(result.Mesh, result.Embedding, vertices, out _);
        }

        [Test]
        public void Build_TwiceSameInput_SameBits()
        {
            TestMeshes.Torus(20, 10, new float3(0.1f, 0.2f, 0.3f), out float3[] vertices, out int[] triangles);
            TetrahedralizationResult a = Build(vertices, triangles, 9), b = Build(vertices, triangles, 9);
            Assert.That(b.Mesh.Tetrahedra, Is.EqualTo(a.Mesh.Tetrahedra));
            Assert.That(b.Mesh.NodeCount, Is.EqualTo(a.Mesh.NodeCount));
            for (int n = 0; n < a.Mesh.NodeCount; n++)
                for (int axis = 0; axis < 3; axis++)
                    Assert.That(BitConverter.SingleToInt32Bits(b.Mesh.Positions[n][axis]), Is.EqualTo(BitConverter.SingleToInt32Bits(a.Mesh.Positions[n][axis])));
            for (int v = 0; v < vertices.Length; v++)
            {
                Assert.That(b.Embedding[v].Nodes, Is.EqualTo(a.Embedding[v].Nodes));
                float4 wa = a.Embedding[v].Weights, wb = b.Embedding[v].Weights;
                Assert.That(new[] { Bits(wb.x), Bits(wb.y), Bits(wb.z), Bits(wb.w) }, Is.EqualTo(new[] { Bits(wa.x), Bits(wa.y), Bits(wa.z), Bits(wa.w) }));
            }
        }

        static int Bits(float x) => BitConverter.SingleToInt32Bits(x);

        [Test]
        public void Build_NoSliverOrUnusedNodeWarnings()
        {
            TestMeshes.UvSphere(12, 24, out float3[] vertices, out int[] triangles);
            TetrahedralizationResult result = Build(vertices, triangles, 8);
            foreach (ValidationIssue issue in result.Issues)
                Assert.That(issue.Code, Is.Not.EqualTo((IssueCode)TetrahedralMeshIssueCode.TetrahedronSliver).And.Not.EqualTo((IssueCode)TetrahedralMeshIssueCode.UnusedNodes));
        }
    }
}
