using System;
using System.Collections.Generic;
using NUnit.Framework;
using Unity.Mathematics;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Building the network (unique sorted edges, bending springs, bad edges reported) and degenerate springs at run time (row 11).</summary>
    public class MassSpringNetworkTests
    {
        static TetrahedralMesh TwoTets() => new TetrahedralMesh(
            new[] { new float3(0, 0, 0), new float3(1, 0, 0), new float3(0, 1, 0), new float3(0, 0, 1), new float3(1, 1, 1) },
            new[] { new int4(0, 1, 2, 3), new int4(1, 2, 3, 4) });

        [Test]
        public void Build_UniqueSortedEdgesAndBendingSprings()
        {
            var issues = new List<ValidationIssue>();
            MassSpringNetwork network = MassSpringNetwork.Build(TwoTets(), MassSpringBuildSettings.Default, issues);
            Assert.IsEmpty(issues);
            // 6 + 6 edges, 3 shared (the common face 1-2-3): 9 springs, sorted by (A, B), A < B.
            Assert.AreEqual(9, network.Springs.Length);
            for (int e = 1; e < network.Springs.Length; e++)
            {
                Spring p = network.Springs[e - 1], s = network.Springs[e];
                Assert.Less(s.A, s.B);
                Assert.IsTrue(p.A < s.A || (p.A == s.A && p.B < s.B));
            }
            // Edge 1-2 is in both tetrahedra: its support volume is the sum of both (1/6 + 1/3 m³).
            int shared = Array.FindIndex(network.Springs, s => s.A == 1 && s.B == 2);
            Assert.That(network.SupportVolumes[shared], Is.EqualTo(1f / 6f + 1f / 3f).Within(1e-6f));
            Assert.That(network.Springs[shared].RestLength, Is.EqualTo(math.sqrt(2f)).Within(1e-6f));

            MassSpringNetwork bent = MassSpringNetwork.Build(TwoTets(), new MassSpringBuildSettings { BendingSprings = true }, issues);
            Assert.AreEqual(10, bent.Springs.Length);
            Assert.AreEqual(9, bent.StructuralCount);
            Assert.AreEqual(0, bent.Springs[9].A);
            Assert.AreEqual(4, bent.Springs[9].B);
        }

        [Test]
        public void Spring_ZeroLengthAndDuplicateEdgesReportedAtBuild()
        {
            // A doubled tetrahedron (back-to-back duplicate, in another node order) and one with a repeated node.
            var mesh = new TetrahedralMesh(
                new[] { new float3(0, 0, 0), new float3(1, 0, 0), new float3(0, 1, 0), new float3(0, 0, 1), new float3(1, 1, 1) },
                new[] { new int4(0, 1, 2, 3), new int4(1, 0, 3, 2), new int4(1, 2, 3, 3) });
            var issues = new List<ValidationIssue>();
            MassSpringNetwork network = MassSpringNetwork.Build(mesh, MassSpringBuildSettings.Default, issues);
            Assert.IsNotNull(network);
            Assert.IsTrue(issues.Exists(i => i.Code == MassSpringIssueCode.DuplicateTetrahedron && i.Index == 1), string.Join("\n", issues));
            Assert.IsTrue(issues.Exists(i => i.Code == MassSpringIssueCode.ZeroLengthEdge && i.Index == 2), string.Join("\n", issues));
            // The duplicate counts once: 6 edges, the first tetrahedron's volume only.
            Assert.AreEqual(6, network.Springs.Length);
            int edge = Array.FindIndex(network.Springs, s => s.A == 0 && s.B == 1);
            Assert.That(network.SupportVolumes[edge], Is.EqualTo(1f / 6f).Within(1e-6f));
            foreach (Spring s in network.Springs)
                Assert.Greater(s.RestLength, 0f);
            // Node 4 belongs to no tetrahedron.
            Assert.IsTrue(issues.Exists(i => i.Code == MassSpringIssueCode.IsolatedNode && i.Index == 4));

            var bad = new List<ValidationIssue>();
            Assert.IsNull(MassSpringNetwork.Build(new TetrahedralMesh(mesh.Positions, new[] { new int4(0, 1, 2, 9) }), default, bad));
            Assert.AreEqual((IssueCode)MassSpringIssueCode.TetrahedronIndexOutOfRange, bad[0].Code);
        }

        [Test]
        public void Spring_ZeroLengthAndCoincident()
        {
            float3 restA = float3.zero, restB = new float3(0.5f, 0f, 0f);
            float3 p = new float3(0.3f, -0.2f, 0.7f);
            // Coincident endpoints, rest length 0.5: finite, along the rest direction, |F| = k |L − L₀| = k L₀.
            var spring = new Spring(0, 1, 0.5f, 100f, 3f);
            float3 f = SpringForces.Force(spring, p, p, float3.zero, float3.zero, restA, restB);
            Assert.IsTrue(math.all(math.isfinite(f)));
            Assert.That(math.length(f), Is.LessThanOrEqualTo(100f * 0.5f * (1f + 1e-6f)));
            // Rest length 0: the linear form k (x_B − x_A): zero when coincident, |F| = k ‖Δx‖ otherwise.
            var zero = new Spring(0, 1, 0f, 100f, 0f);
            Assert.AreEqual(float3.zero, SpringForces.Force(zero, p, p, float3.zero, float3.zero, restA, restA));
            float3 d = new float3(1e-3f, 2e-3f, -1e-3f);
            Assert.That(math.length(SpringForces.Force(zero, float3.zero, d, float3.zero, float3.zero, restA, restA)),
                Is.EqualTo(100f * math.length(d)).Within(1e-6f * 100f * math.length(d)));
            // Nearly coincident (1e-12 m): the rest direction again, never 0/0.
            float3 g = SpringForces.Force(spring, p, p + new float3(1e-12f, 0f, 0f), new float3(1, 0, 0), float3.zero, restA, restB);
            Assert.IsTrue(math.all(math.isfinite(g)));

            // Every integrator steps a pair that starts coincident without a NaN, and pushes it apart.
            foreach (MassSpringIntegrator integrator in Enum.GetValues(typeof(MassSpringIntegrator)))
            {
                var data = MassSpringModelData.Create(new[] { restA, restB }, new[] { 1f, 1f }, new[] { spring });
                var body = new MassSpringTestBody(data);
                body.Positions[0] = body.Positions[1] = p;
                MassSpringParameters parameters = MassSpringTestBody.Plain(integrator);
                for (int n = 0; n < 20; n++)
                    Assert.IsFalse(body.Step(parameters, 0.01f).Reset, integrator.ToString());
                Assert.IsTrue(math.all(math.isfinite(body.Positions[0])) && math.all(math.isfinite(body.Positions[1])));
                Assert.Greater(math.distance(body.Positions[0], body.Positions[1]), 0.05f, integrator.ToString());
            }
        }
    }
}
