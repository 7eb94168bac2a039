using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Each issue code from a minimal bad input, with its index; any error leaves no model.</summary>
    public class SoftBodyBuilderIssueTests
    {
        static SoftBodyBuildResult BuildCube(SoftBodyBuildSettings settings)
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            return SoftBodyBuilder.Build(vertices, triangles, settings);
        }

        static ValidationIssue Single(SoftBodyBuildResult result, IssueCode code)
        {
            ValidationIssue found = default;
            int count = 0;
            foreach (ValidationIssue issue in result.Issues)
                if (issue.Code == code)
                {
                    found = issue;
                    count++;
                }
            Assert.That(count, Is.EqualTo(1), $"one {code} issue expected in: {string.Join("; ", result.Issues)}");
            return found;
        }

        static ValidationIssue AssertFailsWith(SoftBodyBuildResult result, IssueCode code, int index)
        {
            ValidationIssue issue = Single(result, code);
            Assert.That(issue.Severity, Is.EqualTo(IssueSeverity.Error));
            Assert.That(issue.Index, Is.EqualTo(index));
            Assert.That(issue.Message, Is.Not.Empty);
            Assert.That(result.Succeeded, Is.False);
            Assert.That(result.Model, Is.Null);
            return issue;
        }

        static ValidationIssue AssertWarns(SoftBodyBuildResult result, IssueCode code, int index)
        {
            ValidationIssue issue = Single(result, code);
            Assert.That(issue.Severity, Is.EqualTo(IssueSeverity.Warning));
            Assert.That(issue.Index, Is.EqualTo(index));
            Assert.That(result.Succeeded, Is.True);
            return issue;
        }

        [Test]
        public void EmptyMesh_WhenThereAreNoVertices()
        {
            SoftBodyBuildResult result = SoftBodyBuilder.Build(new float3[0], new int[0], SoftBodyBuildSettings.Default);
            AssertFailsWith(result, MeshBuildIssueCode.EmptyMesh, -1);
        }

        [Test]
        public void EmptyMesh_WhenThereAreNoTriangles()
        {
            TestMeshes.UnityCube(out float3[] vertices, out _);
            SoftBodyBuildResult result = SoftBodyBuilder.Build(vertices, new int[0], SoftBodyBuildSettings.Default);
            AssertFailsWith(result, MeshBuildIssueCode.EmptyMesh, -1);
        }

        [Test]
        public void NonFiniteVertex_ReportsTheVertex([Values(float.NaN, float.PositiveInfinity, float.NegativeInfinity)] float bad)
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            vertices[17].y = bad;
            ValidationIssue issue = AssertFailsWith(SoftBodyBuilder.Build(vertices, triangles, SoftBodyBuildSettings.Default),
                MeshBuildIssueCode.NonFiniteVertex, 17);
            Assert.That(issue.Message, Does.StartWith(float.IsNaN(bad) ? "Vertex 17 has a non-finite position (NaN)." : "Vertex 17 has a non-finite position (infinity)."));
        }

        [Test]
        public void NonFiniteVertex_ReportsTheFirstOfSeveral()
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            vertices[17].x = float.NaN;
            vertices[5].z = float.PositiveInfinity;
            ValidationIssue issue = AssertFailsWith(SoftBodyBuilder.Build(vertices, triangles, SoftBodyBuildSettings.Default),
                MeshBuildIssueCode.NonFiniteVertex, 5);
            Assert.That(issue.Message, Does.Contain("2 vertices"));
        }

        [Test]
        public void TriangleCountNotMultipleOfThree_WhenAnIndexIsMissing()
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            SoftBodyBuildResult result = SoftBodyBuilder.Build(vertices, new System.ReadOnlySpan<int>(triangles, 0, 35), SoftBodyBuildSettings.Default);
            AssertFailsWith(result, MeshBuildIssueCode.TriangleCountNotMultipleOfThree, -1);
        }

        [Test]
        public void TriangleIndexOutOfRange_ReportsTheFirstTriangle([Values(24, -1, int.MaxValue)] int badIndex)
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            triangles[3 * 7 + 1] = badIndex;
            triangles[3 * 9] = badIndex;
            ValidationIssue issue = AssertFailsWith(SoftBodyBuilder.Build(vertices, triangles, SoftBodyBuildSettings.Default),
                MeshBuildIssueCode.TriangleIndexOutOfRange, 7);
            Assert.That(issue.Message, Does.StartWith($"Triangle 7 refers to vertex {badIndex}, but the mesh has 24 vertices"));
        }

        [Test]
        public void ZeroSize_WhenAllVerticesCoincide()
        {
            var vertices = new[] { new float3(1f, 2f, 3f), new float3(1f, 2f, 3f), new float3(1f, 2f, 3f) };
            SoftBodyBuildResult result = SoftBodyBuilder.Build(vertices, new[] { 0, 1, 2 }, SoftBodyBuildSettings.Default);
            AssertFailsWith(result, MeshBuildIssueCode.ZeroSize, -1);
        }

        [Test]
        public void ZeroSize_WhenTheWeldDistanceSwallowsTheMesh()
        {
            SoftBodyBuildSettings settings = SoftBodyBuildSettings.Default;
            settings.WeldDistance = 10f;
            AssertFailsWith(BuildCube(settings), MeshBuildIssueCode.ZeroSize, -1);
        }

        [Test]
        public void DegenerateTriangles_WarnsWithTheFirstTriangle()
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] cube);
            int[] triangles = new int[cube.Length + 3];
            cube.CopyTo(triangles, 0);
            new[] { 0, 0, 1 }.CopyTo(triangles, cube.Length);
            AssertWarns(SoftBodyBuilder.Build(vertices, triangles, SoftBodyBuildSettings.Default), MeshBuildIssueCode.DegenerateTriangles, 12);
        }

        [Test]
        public void NonManifoldEdges_WarnsWithTheFirstTriangle()
        {
            // A cube plus a fin (triangle 12) on the edge between corners 0 and 1: that edge now has three triangles.
            TestMeshes.UnityCube(out float3[] cube, out int[] cubeTriangles);
            float3[] vertices = new float3[cube.Length + 1];
            cube.CopyTo(vertices, 0);
            vertices[cube.Length] = new float3(2f, 0f, 0f);
            int[] triangles = new int[cubeTriangles.Length + 3];
            cubeTriangles.CopyTo(triangles, 0);
            new[] { 0, 1, cube.Length }.CopyTo(triangles, cubeTriangles.Length);
            int first = FirstTriangleUsingEdge(cubeTriangles, vertices, vertices[0], vertices[1]);
            AssertWarns(SoftBodyBuilder.Build(vertices, triangles, SoftBodyBuildSettings.Default), MeshBuildIssueCode.NonManifoldEdges, first);
        }

        /// <summary>Lowest triangle with corners at both positions (render vertices are split, so positions identify the edge).</summary>
        static int FirstTriangleUsingEdge(int[] triangles, float3[] vertices, float3 a, float3 b)
        {
            for (int t = 0; t < triangles.Length / 3; t++)
            {
                bool hasA = false, hasB = false;
                for (int k = 0; k < 3; k++)
                {
                    hasA |= vertices[triangles[3 * t + k]].Equals(a);
                    hasB |= vertices[triangles[3 * t + k]].Equals(b);
                }
                if (hasA && hasB)
                    return t;
            }
            return -1;
        }

        [Test]
        public void NotClosed_WarnsAndSkipsInteriorParticles()
        {
            TestMeshes.OpenQuad(out float3[] vertices, out int[] triangles);
            SoftBodyBuildSettings settings = SoftBodyBuildSettings.Default;
            settings.AddInteriorParticles = true;
            SoftBodyBuildResult result = SoftBodyBuilder.Build(vertices, triangles, settings);
            AssertWarns(result, MeshBuildIssueCode.NotClosed, 0);
            Assert.That(result.InteriorParticleCount, Is.EqualTo(0));
        }

        [Test]
        public void NotClosed_IsNotReportedWithoutInteriorParticles()
        {
            TestMeshes.OpenQuad(out float3[] vertices, out int[] triangles);
            SoftBodyBuildResult result = SoftBodyBuilder.Build(vertices, triangles, SoftBodyBuildSettings.Default);
            Assert.That(result.Succeeded, Is.True);
            Assert.That(result.Issues, Has.None.Matches<ValidationIssue>(i => i.Code == MeshBuildIssueCode.NotClosed));
        }

        [Test]
        public void InconsistentWinding_WarnsAndSkipsInteriorParticles()
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            SoftBodyBuildSettings settings = SoftBodyBuildSettings.Default;
            settings.AddInteriorParticles = true;
            SoftBodyBuildResult result = SoftBodyBuilder.Build(vertices, TestMeshes.FlipTriangle(triangles, 0), settings);
            AssertWarns(result, MeshBuildIssueCode.InconsistentWinding, 0);
            Assert.That(result.InteriorParticleCount, Is.EqualTo(0));
        }

        [Test]
        public void TotalMassNotPositive_ForZeroNegativeOrNonFiniteMass([Values(0f, -1f, float.NaN, float.PositiveInfinity)] float mass)
        {
            SoftBodyBuildSettings settings = SoftBodyBuildSettings.Default;
            settings.TotalMass = mass;
            AssertFailsWith(BuildCube(settings), MeshBuildIssueCode.TotalMassNotPositive, -1);
        }

        [Test]
        public void ClusterSizeInvalid_ForNegativeOrNonFinite([Values(-0.5f, float.NaN, float.PositiveInfinity)] float size)
        {
            SoftBodyBuildSettings settings = SoftBodyBuildSettings.Default;
            settings.ClusterSize = size;
            AssertFailsWith(BuildCube(settings), MeshBuildIssueCode.ClusterSizeInvalid, -1);
        }

        [Test]
        public void ClusterSizeInvalid_WhenTheClusterLatticeWouldBeTooFine()
        {
            // 1 m / (1e-7 m / 2) = 2e7 centres per side, above the 2²⁰ limit.
            SoftBodyBuildSettings settings = SoftBodyBuildSettings.Default;
            settings.ClusterSize = 1e-7f;
            AssertFailsWith(BuildCube(settings), MeshBuildIssueCode.ClusterSizeInvalid, -1);
        }

        [Test]
        public void InteriorSpacingInvalid_ForNegativeOrNonFinite([Values(-0.1f, float.NaN, float.NegativeInfinity)] float spacing)
        {
            SoftBodyBuildSettings settings = SoftBodyBuildSettings.Default;
            settings.AddInteriorParticles = true;
            settings.InteriorSpacing = spacing;
            AssertFailsWith(BuildCube(settings), MeshBuildIssueCode.InteriorSpacingInvalid, -1);
        }

        [Test]
        public void InteriorSpacingInvalid_WhenTheLatticeWouldBeTooLarge()
        {
            // 1 m / 1e-3 m → 1001³ ≈ 1e9 lattice points, above the 2²⁴ limit.
            SoftBodyBuildSettings settings = SoftBodyBuildSettings.Default;
            settings.AddInteriorParticles = true;
            settings.InteriorSpacing = 1e-3f;
            AssertFailsWith(BuildCube(settings), MeshBuildIssueCode.InteriorSpacingInvalid, -1);
        }

        [Test]
        public void WeldToleranceInvalid_ForNegativeOrNonFiniteTolerance([Values(-1e-5f, float.NaN, float.PositiveInfinity)] float tolerance)
        {
            SoftBodyBuildSettings relative = SoftBodyBuildSettings.Default;
            relative.WeldTolerance = tolerance;
            AssertFailsWith(BuildCube(relative), MeshBuildIssueCode.WeldToleranceInvalid, -1);
            SoftBodyBuildSettings absolute = SoftBodyBuildSettings.Default;
            absolute.WeldDistance = tolerance;
            AssertFailsWith(BuildCube(absolute), MeshBuildIssueCode.WeldToleranceInvalid, -1);
        }

        [Test]
        public void MaxParticlesInvalid_ForNonPositiveLimit([Values(0, -5)] int max)
        {
            SoftBodyBuildSettings settings = SoftBodyBuildSettings.Default;
            settings.MaxParticles = max;
            AssertFailsWith(BuildCube(settings), MeshBuildIssueCode.MaxParticlesInvalid, -1);
        }

        [Test]
        public void TooManyParticles_FromTheSurface()
        {
            SoftBodyBuildSettings settings = SoftBodyBuildSettings.Default;
            settings.MaxParticles = 7;
            ValidationIssue issue = AssertFailsWith(BuildCube(settings), MeshBuildIssueCode.TooManyParticles, -1);
            Assert.That(issue.Message, Does.Contain("8 particles").And.Contain("the limit is 7"));
        }

        [Test]
        public void TooManyParticles_FromTheInterior()
        {
            // 8 surface + 27 interior particles at 0.25 m spacing exceed a limit of 20; sampling stops at
            // 20 − 8 + 1 = 13 interior points, so the message gives a lower bound of 21.
            SoftBodyBuildSettings settings = SoftBodyBuildSettings.Default;
            settings.AddInteriorParticles = true;
            settings.InteriorSpacing = 0.25f;
            settings.MaxParticles = 20;
            ValidationIssue issue = AssertFailsWith(BuildCube(settings), MeshBuildIssueCode.TooManyParticles, -1);
            Assert.That(issue.Message, Does.Contain("at least 21 particles").And.Contain("the limit is 20"));
        }

        [Test]
        public void WeakClusters_WarnsWhenOnlyWeakClustersCoverSomeParticles()
        {
            // The 8 welded corners with 0.5 m clusters: each corner is alone in its clusters (see ClusterBuilderTests).
            SoftBodyBuildSettings settings = SoftBodyBuildSettings.Default;
            settings.ClusterSize = 0.5f;
            SoftBodyBuildResult result = BuildCube(settings);
            AssertWarns(result, MeshBuildIssueCode.WeakClusters, -1);
            Assert.That(result.ClusterCount, Is.EqualTo(8));
        }

        [Test]
        public void MultipleSettingErrors_AreAllReported()
        {
            SoftBodyBuildSettings settings = SoftBodyBuildSettings.Default;
            settings.TotalMass = -1f;
            settings.ClusterSize = float.NaN;
            SoftBodyBuildResult result = BuildCube(settings);
            Single(result, MeshBuildIssueCode.TotalMassNotPositive);
            Single(result, MeshBuildIssueCode.ClusterSizeInvalid);
            Assert.That(result.Succeeded, Is.False);
        }
    }
}
