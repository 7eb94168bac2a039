using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// End-to-end building. Mass sums: N equal float32 masses M/N, each within ε/2 relative of exact, summed
    /// with N − 1 roundings: |Σ − M| ≤ N·ε·M.
    /// </summary>
    public class SoftBodyBuilderTests
    {
        static SoftBodyBuildSettings Settings(bool interior = false, float spacing = 0f, float clusterSize = 0f)
        {
            SoftBodyBuildSettings settings = SoftBodyBuildSettings.Default;
            settings.AddInteriorParticles = interior;
            settings.InteriorSpacing = spacing;
            settings.ClusterSize = clusterSize;
            return settings;
        }

        static float MassSum(ShapeMatchingModelData model)
        {
            float sum = 0f;
            foreach (float m in model.Masses)
                sum += m;
            return sum;
        }

        [Test]
        public void Build_UnityCube_GivesEightParticlesInOneClusterWithoutIssues()
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            SoftBodyBuildResult result = SoftBodyBuilder.Build(vertices, triangles, SoftBodyBuildSettings.Default);

            Assert.That(result.Succeeded, Is.True);
            Assert.That(result.Issues, Is.Empty);
            Assert.That(result.SurfaceParticleCount, Is.EqualTo(8));
            Assert.That(result.InteriorParticleCount, Is.EqualTo(0));
            Assert.That(result.IsClosed, Is.True);
            Assert.That(result.ClusterCount, Is.EqualTo(1));
            Assert.That(result.MeanClusterSize, Is.EqualTo(8f));
            Assert.That(result.Model.ParticleCount, Is.EqualTo(8));
            Assert.That(result.Model.ClusterOffsets, Is.EqualTo(new[] { 0, 8 }));
            Assert.That(result.VertexToParticle.Length, Is.EqualTo(24));
            for (int v = 0; v < vertices.Length; v++)
                Assert.That(result.Model.RestPositions[result.VertexToParticle[v]].Equals(vertices[v]), Is.True, $"vertex {v}");
        }

        [Test]
        public void Build_SpreadsTotalMassUniformly()
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            SoftBodyBuildSettings settings = Settings(interior: true, spacing: 0.25f);
            settings.TotalMass = 3.5f;
            SoftBodyBuildResult result = SoftBodyBuilder.Build(vertices, triangles, settings);

            int n = result.ParticleCount;
            Assert.That(n, Is.EqualTo(8 + 27));
            Assert.That(result.Model.Masses, Is.All.EqualTo(3.5f / n));
            Assert.That(MassSum(result.Model), Is.EqualTo(3.5f).Within(n * math.EPSILON * 3.5f));
        }

        [Test]
        public void Build_CubeWithAutoInteriorSpacing_FillsAnEighthLattice()
        {
            // Auto spacing = 1/8 m: n = 9 lattice points per axis, 7³ = 343 strictly inside; the closest to a
            // corner is √3/8 ≈ 0.22 m away, beyond s/2 = 0.0625 m.
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            SoftBodyBuildResult result = SoftBodyBuilder.Build(vertices, triangles, Settings(interior: true));
            Assert.That(result.Succeeded, Is.True);
            Assert.That(result.InteriorParticleCount, Is.EqualTo(343));
            for (int i = result.SurfaceParticleCount; i < result.ParticleCount; i++)
                Assert.That(math.cmax(math.abs(result.Model.RestPositions[i])), Is.LessThan(0.5f));
        }

        [Test]
        public void Build_ClusterSizeBelowBodySize_GivesOverlappingClustersCoveringEveryParticle()
        {
            TestMeshes.UvSphere(12, 20, out float3[] vertices, out int[] triangles);
            SoftBodyBuildResult result = SoftBodyBuilder.Build(vertices, triangles, Settings(interior: true, spacing: 0.25f, clusterSize: 0.8f));

            Assert.That(result.Succeeded, Is.True, string.Join("\n", result.Issues));
            Assert.That(result.ClusterCount, Is.GreaterThan(1));
            var coverage = new int[result.ParticleCount];
            foreach (int p in result.Model.ClusterParticles)
                coverage[p]++;
            Assert.That(coverage, Is.All.GreaterThanOrEqualTo(1));
            Assert.That(coverage, Has.Some.GreaterThan(1));
            Assert.That(result.MeanClusterSize, Is.EqualTo((float)result.Model.ClusterParticles.Length / result.ClusterCount));
        }

        [Test]
        public void Build_WeldedUvSphere_WarnsAboutCollapsedPoleTrianglesAndSucceeds()
        {
            const int rings = 12, segments = 20;
            TestMeshes.UvSphere(rings, segments, out float3[] vertices, out int[] triangles);
            SoftBodyBuildResult result = SoftBodyBuilder.Build(vertices, triangles, SoftBodyBuildSettings.Default);

            Assert.That(result.Succeeded, Is.True);
            Assert.That(result.SurfaceParticleCount, Is.EqualTo((rings - 1) * segments + 2));
            Assert.That(result.IsClosed, Is.True);
            Assert.That(result.Issues.Count, Is.EqualTo(1));
            Assert.That(result.Issues[0].Code, Is.EqualTo((IssueCode)MeshBuildIssueCode.DegenerateTriangles));
            Assert.That(result.Issues[0].Severity, Is.EqualTo(IssueSeverity.Warning));
        }

        [Test]
        public void Build_SameInputGivesBitwiseIdenticalArrays()
        {
            TestMeshes.UvSphere(12, 20, out float3[] vertices, out int[] triangles);
            SoftBodyBuildSettings settings = Settings(interior: true, spacing: 0.2f, clusterSize: 0.7f);
            settings.BuildQuadratic = true;
            SoftBodyBuildResult first = SoftBodyBuilder.Build(vertices, triangles, settings);
            SoftBodyBuildResult second = SoftBodyBuilder.Build(vertices, triangles, settings);

            Assert.That(first.Succeeded, Is.True);
            Assert.That(Bits(second.Model.RestPositions), Is.EqualTo(Bits(first.Model.RestPositions)));
            Assert.That(Bits(second.Model.Masses), Is.EqualTo(Bits(first.Model.Masses)));
            Assert.That(second.VertexToParticle, Is.EqualTo(first.VertexToParticle));
            Assert.That(second.Model.ClusterOffsets, Is.EqualTo(first.Model.ClusterOffsets));
            Assert.That(second.Model.ClusterParticles, Is.EqualTo(first.Model.ClusterParticles));
        }

        static uint[] Bits(float3[] values)
        {
            var bits = new uint[3 * values.Length];
            for (int i = 0; i < values.Length; i++)
            {
                bits[3 * i] = math.asuint(values[i].x);
                bits[3 * i + 1] = math.asuint(values[i].y);
                bits[3 * i + 2] = math.asuint(values[i].z);
            }
            return bits;
        }

        static uint[] Bits(float[] values) => System.Array.ConvertAll(values, v => math.asuint(v));
    }
}
