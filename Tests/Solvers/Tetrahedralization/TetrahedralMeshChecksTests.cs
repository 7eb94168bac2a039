using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Each defect of a supplied tetrahedral mesh gives its code, severity and the tetrahedron or node concerned.</summary>
    public class TetrahedralMeshChecksTests
    {
        static TetrahedralMesh Box() => BoxTetrahedra.Create(new float3(1f), new int3(2, 2, 2), float3.zero);

        static ValidationIssue Single(List<ValidationIssue> issues, IssueCode code)
        {
            ValidationIssue found = default;
            int count = 0;
            foreach (ValidationIssue issue in issues)
                if (issue.Code == code)
                {
                    found = issue;
                    count++;
                }
            Assert.That(count, Is.EqualTo(1), $"one {code} expected in: {string.Join("; ", issues)}");
            return found;
        }

        [Test]
        public void BoxMesh_NoIssues()
        {
            var issues = new List<ValidationIssue>();
            Assert.That(TetrahedralMeshChecks.Check(Box(), issues), Is.True);
            Assert.That(issues, Is.Empty);
        }

        [Test]
        public void SwappedNodes_TetrahedronInverted_NamesTetrahedron()
        {
            TetrahedralMesh mesh = Box();
            int4 q = mesh.Tetrahedra[7];
            mesh.Tetrahedra[7] = new int4(q.y, q.x, q.z, q.w);
            var issues = new List<ValidationIssue>();
            Assert.That(TetrahedralMeshChecks.Check(mesh, issues), Is.False);
            ValidationIssue issue = Single(issues, TetrahedralMeshIssueCode.TetrahedronInverted);
            Assert.That(issue.Index, Is.EqualTo(7));
            Assert.That(issue.Severity, Is.EqualTo(IssueSeverity.Error));
        }

        [Test]
        public void RepeatedNode_TetrahedronDegenerate()
        {
            TetrahedralMesh mesh = Box();
            int4 q = mesh.Tetrahedra[3];
            mesh.Tetrahedra[3] = new int4(q.x, q.y, q.y, q.w);
            var issues = new List<ValidationIssue>();
            Assert.That(TetrahedralMeshChecks.Check(mesh, issues), Is.False);
            Assert.That(Single(issues, TetrahedralMeshIssueCode.TetrahedronDegenerate).Index, Is.EqualTo(3));
        }

        [Test]
        public void FlatTetrahedron_TetrahedronDegenerate()
        {
            var mesh = new TetrahedralMesh(new[] { new float3(0, 0, 0), new float3(1, 0, 0), new float3(0, 1, 0), new float3(0.3f, 0.3f, 0f) },
                new[] { new int4(0, 1, 2, 3) });
            var issues = new List<ValidationIssue>();
            Assert.That(TetrahedralMeshChecks.Check(mesh, issues), Is.False);
            Assert.That(Single(issues, TetrahedralMeshIssueCode.TetrahedronDegenerate).Index, Is.EqualTo(0));
        }

        [Test]
        public void IndexOutOfRange_TetrahedronIndexOutOfRange()
        {
            TetrahedralMesh mesh = Box();
            mesh.Tetrahedra[5] = new int4(0, 1, 2, mesh.NodeCount);
            var issues = new List<ValidationIssue>();
            Assert.That(TetrahedralMeshChecks.Check(mesh, issues), Is.False);
            Assert.That(Single(issues, TetrahedralMeshIssueCode.TetrahedronIndexOutOfRange).Index, Is.EqualTo(5));
        }

        [Test]
        public void NaNNode_NonFiniteNode()
        {
            TetrahedralMesh mesh = Box();
            mesh.Positions[4].z = float.NaN;
            var issues = new List<ValidationIssue>();
            Assert.That(TetrahedralMeshChecks.Check(mesh, issues), Is.False);
            Assert.That(Single(issues, TetrahedralMeshIssueCode.NonFiniteNode).Index, Is.EqualTo(4));
        }

        [Test]
        public void Empty_EmptyTetrahedralMesh()
        {
            var issues = new List<ValidationIssue>();
            Assert.That(TetrahedralMeshChecks.Check(new TetrahedralMesh(new float3[0], new int4[0]), issues), Is.False);
            Single(issues, TetrahedralMeshIssueCode.EmptyTetrahedralMesh);
        }

        [Test]
        public void ExtraNode_UnusedNodesWarning()
        {
            TetrahedralMesh box = Box();
            var positions = new float3[box.NodeCount + 1];
            box.Positions.CopyTo(positions, 0);
            positions[box.NodeCount] = new float3(5f);
            var issues = new List<ValidationIssue>();
            Assert.That(TetrahedralMeshChecks.Check(new TetrahedralMesh(positions, box.Tetrahedra), issues), Is.True);
            ValidationIssue issue = Single(issues, TetrahedralMeshIssueCode.UnusedNodes);
            Assert.That(issue.Index, Is.EqualTo(box.NodeCount));
            Assert.That(issue.Severity, Is.EqualTo(IssueSeverity.Warning));
        }

        /// <summary>Quality 1 for the regular tetrahedron, 6√2·(1/6)/(10/6)^{3/2} ≈ 0.657 for a Kuhn cube tetrahedron.</summary>
        [Test]
        public void Quality_RegularIsOne_KuhnIsPointSixFiveSeven()
        {
            float s = 1f / math.sqrt(2f);
            Assert.That(TetrahedralMeshChecks.Quality(new float3(1, 0, -s), new float3(-1, 0, -s), new float3(0, 1, s), new float3(0, -1, s)),
                Is.EqualTo(1.0).Within(1e-6).Or.EqualTo(-1.0).Within(1e-6));
            Assert.That(TetrahedralMeshChecks.Quality(new float3(0, 0, 0), new float3(1, 0, 0), new float3(1, 1, 0), new float3(1, 1, 1)),
                Is.EqualTo(System.Math.Sqrt(2.0) / System.Math.Pow(10.0 / 6.0, 1.5)).Within(1e-9));
        }

        [Test]
        public void ThinTetrahedron_SliverWarning_NamesWorst()
        {
            // Apexes 0.2 above and 0.02 below a unit right triangle: quality ≈ 0.33 (not a sliver) and ≈ 0.034.
            var mesh = new TetrahedralMesh(
                new[] { new float3(0, 0, 0), new float3(1, 0, 0), new float3(0, 1, 0), new float3(0.3f, 0.3f, 0.2f), new float3(0.3f, 0.3f, -0.02f) },
                new[] { new int4(0, 1, 2, 3), new int4(0, 2, 1, 4) });
            double q0 = TetrahedralMeshChecks.Quality(mesh.Positions[0], mesh.Positions[1], mesh.Positions[2], mesh.Positions[3]);
            double q1 = TetrahedralMeshChecks.Quality(mesh.Positions[0], mesh.Positions[2], mesh.Positions[1], mesh.Positions[4]);
            Assert.That(q0, Is.GreaterThan(TetrahedralMeshChecks.SliverQuality));
            Assert.That(q1, Is.GreaterThan(0.0).And.LessThan(TetrahedralMeshChecks.SliverQuality));
            var issues = new List<ValidationIssue>();
            Assert.That(TetrahedralMeshChecks.Check(mesh, issues), Is.True);
            ValidationIssue issue = Single(issues, TetrahedralMeshIssueCode.TetrahedronSliver);
            Assert.That(issue.Index, Is.EqualTo(1));
            Assert.That(issue.Severity, Is.EqualTo(IssueSeverity.Warning));
        }
    }
}
