using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Interior lattice points. Every lattice coordinate in these cases is a multiple of 0.25 m near
    /// small integers, exact in float32, so "strictly inside" is checked with exact comparisons and
    /// the counts follow from the lattice: n = ⌊E/s⌋ + 1 points per axis, centred on the bounds.
    /// </summary>
    public class InteriorSamplingTests
    {
        static List<float3> SampleWelded(float3[] vertices, int[] triangles, float spacing, int maxPoints, out int found)
        {
            WeldedVertices welded = MeshWelding.Weld(vertices, 1e-5f);
            var output = new List<float3>();
            found = InteriorSampling.Sample(welded.Positions, MeshWelding.RemapTriangles(triangles, welded.VertexToParticle), spacing, maxPoints, output);
            return output;
        }

        static IEnumerable<float3> Centres()
        {
            yield return float3.zero;
            yield return new float3(10f, -3f, 7.5f);
        }

        [Test]
        public void Interior_UnitCubeAtQuarterSpacing_Gives27PointsStrictlyInside([ValueSource(nameof(Centres))] float3 center)
        {
            // E = 1, s = 0.25: n = 5 points per axis at centre + {−0.5, −0.25, 0, 0.25, 0.5}. The outer two
            // lie on the faces (not strictly inside), leaving 3³ = 27. The nearest surface particle (a corner)
            // is √3·0.25 ≈ 0.43 m away, beyond s/2 = 0.125 m, so none is skipped.
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles, 1f, center);
            List<float3> points = SampleWelded(vertices, triangles, 0.25f, 1000, out int found);

            Assert.That(found, Is.EqualTo(27));
            Assert.That(points.Count, Is.EqualTo(27));
            foreach (float3 p in points)
            {
                float3 d = math.abs(p - center);
                Assert.That(math.cmax(d), Is.LessThan(0.5f), $"{p} is not strictly inside");
                Assert.That(math.cmax(d), Is.LessThanOrEqualTo(0.25f), $"{p} is not on the lattice");
            }
        }

        [Test]
        public void Interior_InwardFacingCubeGivesTheSamePoints()
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            List<float3> outward = SampleWelded(vertices, triangles, 0.25f, 1000, out _);
            List<float3> inward = SampleWelded(vertices, TestMeshes.Reversed(triangles), 0.25f, 1000, out _);
            Assert.That(inward, Is.EqualTo(outward));
        }

        [Test]
        public void Interior_HollowBox_ExcludesCavityAndItsWalls()
        {
            // Outer cube [−1, 1]³, s = 0.25: n = 9 per axis at −1, −0.75, …, 1; strictly inside the outer cube
            // are 7³ = 343. The cavity [−½, ½]³ holds 5³ = 125 of them, its walls included (the points at ±½
            // lie on the inner faces and edges, on the face diagonals too). 343 − 125 = 218. The inner corners
            // are surface particles, but the nearest remaining lattice point is 0.25 m from one (> s/2).
            TestMeshes.HollowBox(out float3[] vertices, out int[] triangles);
            List<float3> points = SampleWelded(vertices, triangles, 0.25f, 1000, out int found);

            Assert.That(found, Is.EqualTo(218));
            foreach (float3 p in points)
            {
                Assert.That(math.cmax(math.abs(p)), Is.LessThan(1f), $"{p} is outside the box");
                Assert.That(math.cmax(math.abs(p)), Is.GreaterThan(0.5f), $"{p} is in the cavity or on its wall");
            }
        }

        [Test]
        public void Interior_SkipsLatticePointsCloserThanHalfSpacingToASurfaceParticle()
        {
            // A lone surface particle 0.05 m from the lattice point (0.25, 0.25, 0.25), within s/2 = 0.125 m of it
            // and farther than that from every other lattice point (the next is 0.2 m away): 27 − 1 = 26.
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            WeldedVertices welded = MeshWelding.Weld(vertices, 1e-5f);
            var surface = new float3[welded.ParticleCount + 1];
            welded.Positions.CopyTo(surface, 0);
            surface[welded.ParticleCount] = new float3(0.25f, 0.25f, 0.3f);
            var output = new List<float3>();
            int found = InteriorSampling.Sample(surface, MeshWelding.RemapTriangles(triangles, welded.VertexToParticle), 0.25f, 1000, output);

            Assert.That(found, Is.EqualTo(26));
            Assert.That(output, Has.No.Member(new float3(0.25f, 0.25f, 0.25f)));
        }

        [Test]
        public void Interior_StopsOnePastMaxPoints()
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            List<float3> points = SampleWelded(vertices, triangles, 0.25f, 10, out int found);
            Assert.That(found, Is.EqualTo(11));
            Assert.That(points.Count, Is.EqualTo(10));
        }

        static IEnumerable<TestCaseData> ClosedMeshes()
        {
            TestMeshes.Torus(24, 12, new float3(0.3f, -0.2f, 0.1f), out float3[] torus, out int[] torusTriangles);
            yield return new TestCaseData(torus, torusTriangles, 0.1f).SetName("Interior_MatchesPointwiseClassification_Torus");
            TestMeshes.UvSphere(10, 16, out float3[] sphere, out int[] sphereTriangles);
            yield return new TestCaseData(sphere, sphereTriangles, 0.15f).SetName("Interior_MatchesPointwiseClassification_Sphere");
            TestMeshes.HollowBox(out float3[] box, out int[] boxTriangles);
            yield return new TestCaseData(box, boxTriangles, 0.125f).SetName("Interior_MatchesPointwiseClassification_HollowBox");
        }

        /// <summary>
        /// Sampling evaluates w only where a row may meet the surface and carries it elsewhere; this must select
        /// exactly the points that the rule, applied to every lattice point, selects.
        /// </summary>
        [TestCaseSource(nameof(ClosedMeshes))]
        public void Interior_MatchesPointwiseClassification(float3[] vertices, int[] triangles, float spacing)
        {
            WeldedVertices welded = TestMeshes.WeldAtDefaultTolerance(vertices, triangles, out int[] particleTriangles);
            var sampled = new List<float3>();
            InteriorSampling.Sample(welded.Positions, particleTriangles, spacing, int.MaxValue - 1, sampled);

            AxisAlignedBox bounds = AxisAlignedBox.Of(welded.Positions);
            var lattice = new CubicLattice(bounds, spacing);
            var winding = new WindingNumber(welded.Positions, particleTriangles);
            var grid = new PointGrid(bounds.Min, 0.5f * spacing);
            for (int i = 0; i < welded.ParticleCount; i++)
                grid.Add(welded.Positions[i], i);
            var expected = new List<float3>();
            for (int k = 0; k < lattice.CountZ; k++)
            for (int j = 0; j < lattice.CountY; j++)
            for (int i = 0; i < lattice.CountX; i++)
            {
                float3 p = lattice.Point(i, j, k);
                if (winding.TryEvaluate(p, InteriorSampling.OnSurfaceFraction * spacing, out double w) && System.Math.Abs(w) > 0.5
                    && grid.LowestIndexWithin(p, 0.5f * spacing, inclusive: false) < 0)
                    expected.Add(p);
            }
            Assert.That(expected.Count, Is.GreaterThan(0));
            Assert.That(sampled, Is.EqualTo(expected));
        }

        [Test]
        public void Interior_UvSpherePointsAreInsideTheInscribedPolyhedron()
        {
            // A convex polyhedron lies on the inner side of each face plane: (p − a)·n < 0 with n the outward
            // normal. Evaluated in double from float32 inputs (differences exact, each product rounded once),
            // the test's own error stays below 16·2⁻⁵³·|b − a||c − a||p − a|.
            const int rings = 10, segments = 16;
            TestMeshes.UvSphere(rings, segments, out float3[] vertices, out int[] triangles);
            WeldedVertices welded = TestMeshes.WeldAtDefaultTolerance(vertices, triangles, out int[] particleTriangles);
            var output = new List<float3>();
            int found = InteriorSampling.Sample(welded.Positions, particleTriangles, 0.2f, 10000, output);

            Assert.That(found, Is.GreaterThan(0));
            double unitRoundOff = System.Math.Pow(2.0, -53);
            for (int t = 0; t < particleTriangles.Length / 3; t++)
            {
                double[] a = ToDouble(welded.Positions[particleTriangles[3 * t]]);
                double[] u = Minus(ToDouble(welded.Positions[particleTriangles[3 * t + 1]]), a);
                double[] v = Minus(ToDouble(welded.Positions[particleTriangles[3 * t + 2]]), a);
                double[] n = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
                if (Dot(n, n) == 0.0)
                    continue;
                double side = Dot(n, a) > 0.0 ? 1.0 : -1.0;
                foreach (float3 p in output)
                {
                    double[] q = Minus(ToDouble(p), a);
                    double bound = 16.0 * unitRoundOff * System.Math.Sqrt(Dot(u, u) * Dot(v, v) * Dot(q, q));
                    Assert.That(side * Dot(n, q), Is.LessThan(bound), $"{p} is outside face {t}");
                }
            }
        }

        static double[] ToDouble(float3 p) => new double[] { p.x, p.y, p.z };
        static double[] Minus(double[] a, double[] b) => new[] { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
        static double Dot(double[] a, double[] b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
}
