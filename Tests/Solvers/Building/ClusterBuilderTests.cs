using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Overlapping lattice clusters. The point sets are grids with spacings of 0.25 m or 0.5 m and the
    /// cluster sizes are multiples of 0.5 m, so centres and the membership test |x − c|∞ ≤ d/2 are exact;
    /// counts follow from the lattice (n = ⌈E/(d/2)⌉ + 1 centres per axis, centred on the bounds).
    /// </summary>
    public class ClusterBuilderTests
    {
        static int[] Coverage(ClusterSet clusters, int particleCount)
        {
            var coverage = new int[particleCount];
            foreach (int p in clusters.Particles)
                coverage[p]++;
            return coverage;
        }

        static void AssertWellFormed(ClusterSet clusters, int particleCount)
        {
            Assert.That(clusters.Offsets[0], Is.EqualTo(0));
            Assert.That(clusters.Offsets[clusters.Count], Is.EqualTo(clusters.Particles.Length));
            for (int c = 0; c < clusters.Count; c++)
            {
                Assert.That(clusters.Offsets[c + 1], Is.GreaterThan(clusters.Offsets[c]), $"cluster {c} is empty");
                for (int k = clusters.Offsets[c]; k < clusters.Offsets[c + 1]; k++)
                {
                    Assert.That(clusters.Particles[k], Is.InRange(0, particleCount - 1));
                    if (k > clusters.Offsets[c])
                        Assert.That(clusters.Particles[k], Is.GreaterThan(clusters.Particles[k - 1]), $"cluster {c} is not ascending or repeats a particle");
                }
            }
            Assert.That(Coverage(clusters, particleCount), Is.All.GreaterThanOrEqualTo(1), "every particle is in a cluster");
        }

        [Test]
        public void Clusters_OneClusterOfEveryParticle_WhenSizeIsZeroOrAtLeastTheBody([Values(0f, -1f, 1f, 3f)] float clusterSize)
        {
            float3[] points = TestMeshes.Grid(5, 0.25f);
            ClusterSet clusters = ClusterBuilder.Build(points, clusterSize);
            Assert.That(clusters.Count, Is.EqualTo(1));
            Assert.That(clusters.Offsets, Is.EqualTo(new[] { 0, points.Length }));
            for (int i = 0; i < points.Length; i++)
                Assert.That(clusters.Particles[i], Is.EqualTo(i));
        }

        [Test]
        public void Clusters_GridOfPoints_GiveTheLatticeCountAndMeanSize()
        {
            // 5³ points at 0.25 m, d = 0.5 m: h = 0.25 m, ⌈1/0.25⌉ + 1 = 5 centres per axis on the points
            // themselves. Along an axis the 5 centres hold 2, 3, 3, 3, 2 points (13), so the 125 clusters hold
            // 13³ = 2197 memberships: mean 2197/125. None is weak (the smallest is a 2×2×2 cube).
            float3[] points = TestMeshes.Grid(5, 0.25f);
            ClusterSet clusters = ClusterBuilder.Build(points, 0.5f);
            AssertWellFormed(clusters, points.Length);
            Assert.That(clusters.Count, Is.EqualTo(125));
            Assert.That(clusters.Particles.Length, Is.EqualTo(2197));
            Assert.That(clusters.MeanSize, Is.EqualTo(2197f / 125f));
            Assert.That(clusters.WeakClusterCount, Is.EqualTo(0));
        }

        [Test]
        public void Clusters_OverlapWhenSmallerThanTheBody()
        {
            // 6³ points at 0.25 m (E = 1.25 m), d = 0.6 m, a size that is not a multiple of the spacing: h = 0.3 m,
            // ⌈1.25/0.3⌉ + 1 = 6 centres per axis at −0.125 + 0.3·i. A point 0.25·m is on a cube's face when
            // 0.25·m = −0.125 + 0.3·(i ± 1), i.e. 10·m + 5 = 12·(i ± 1), which has no integer solution: every point
            // is at least 0.025 m from every face, far beyond the rounding of 0.6f (≈ 2e-8 m per centre) and of the
            // double arithmetic. Along an axis the centres hold 1, 2, 3, 3, 2, 1 points; a cluster with a one-point
            // axis is planar, and every point is also in a cluster of ≥ 2 points per axis, so only those 4³ = 64
            // remain, with (2 + 3 + 3 + 2)³ = 1000 memberships.
            float3[] points = TestMeshes.Grid(6, 0.25f);
            ClusterSet clusters = ClusterBuilder.Build(points, 0.6f);
            AssertWellFormed(clusters, points.Length);
            Assert.That(clusters.Count, Is.EqualTo(64));
            Assert.That(clusters.Particles.Length, Is.EqualTo(1000));
            Assert.That(clusters.WeakClusterCount, Is.EqualTo(0));
            Assert.That(Coverage(clusters, points.Length), Has.Some.GreaterThan(1), "some particle is shared by clusters");
        }

        [Test]
        public void Clusters_DropWeakClustersWhoseParticlesStayCovered()
        {
            // 3³ points at 0.5 m, d = 0.5 m: centres every 0.25 m from 0 to 1. A centre on a grid line holds one
            // point per axis, a centre between lines two; only the 2³ centres between lines on all axes give
            // 2×2×2 cubes. Every point is a corner of one of them, so all other (weak) clusters go.
            float3[] points = TestMeshes.Grid(3, 0.5f);
            ClusterSet clusters = ClusterBuilder.Build(points, 0.5f);
            AssertWellFormed(clusters, points.Length);
            Assert.That(clusters.Count, Is.EqualTo(8));
            Assert.That(clusters.MeanSize, Is.EqualTo(8f));
            Assert.That(clusters.WeakClusterCount, Is.EqualTo(0));
        }

        [Test]
        public void Clusters_KeepAWeakClusterThatAloneCoversAParticle()
        {
            // The 8 corners of a unit cube with d = 0.5 m: no cube of half-size 0.25 m holds two corners, so
            // each corner is a one-particle cluster (its 8 identical copies merged) that cannot be dropped.
            float3[] corners = TestMeshes.Grid(2, 1f);
            ClusterSet clusters = ClusterBuilder.Build(corners, 0.5f);
            AssertWellFormed(clusters, corners.Length);
            Assert.That(clusters.Count, Is.EqualTo(8));
            Assert.That(clusters.MeanSize, Is.EqualTo(1f));
            Assert.That(clusters.WeakClusterCount, Is.EqualTo(8));
        }

        [Test]
        public void IsWeak_FlagsSmallAndPlanarClustersOnly()
        {
            float3[] points = TestMeshes.Grid(2, 1f);
            Assert.That(ClusterBuilder.IsWeak(points, new[] { 0, 1, 2 }), Is.True, "3 particles");
            Assert.That(ClusterBuilder.IsWeak(points, new[] { 0, 1, 2, 3 }), Is.True, "the face z = 0");
            Assert.That(ClusterBuilder.IsWeak(points, new[] { 0, 1, 2, 4 }), Is.False, "a corner tetrahedron");
        }
    }
}
