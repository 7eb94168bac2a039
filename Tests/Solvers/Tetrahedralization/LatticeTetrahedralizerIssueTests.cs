using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Each failure of the tetrahedralisation gives its specific code and index, and no mesh.</summary>
    public class LatticeTetrahedralizerIssueTests
    {
        static TetrahedralizationResult BuildCube(TetrahedralizationSettings settings)
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            return LatticeTetrahedralizer.Build(vertices, triangles, settings);
        }

        static void AssertFailsWith(TetrahedralizationResult result, IssueCode code, int index)
        {
            int count = 0;
            foreach (ValidationIssue issue in result.Issues)
            {
                if (issue.Code != code)
                    continue;
                count++;
                Assert.That(issue.Severity, Is.EqualTo(IssueSeverity.Error));
                Assert.That(issue.Index, Is.EqualTo(index));
                Assert.That(issue.Message, Is.Not.Empty);
            }
            Assert.That(count, Is.EqualTo(1), $"one {code} expected in: {string.Join("; ", result.Issues)}");
            Assert.That(result.Succeeded, Is.False);
            Assert.That(result.Mesh, Is.Null);
            Assert.That(result.Embedding, Is.Null);
        }

        [Test]
        public void OpenMesh_VolumeMeshNotClosed_NamesFirstBoundaryTriangle()
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            int[] open = new int[triangles.Length - 6];
            System.Array.Copy(triangles, open, open.Length);
            TetrahedralizationResult result = LatticeTetrahedralizer.Build(vertices, open, TetrahedralizationSettings.Default);
            // The last face (triangles 10 and 11) is removed; its four neighbours' triangles are the boundary.
            MeshTopology topology = MeshTopology.Analyse(TestMeshes.WeldAtDefaultTolerance(vertices, open, out int[] welded).Positions, welded);
            AssertFailsWith(result, TetrahedralMeshIssueCode.VolumeMeshNotClosed, topology.FirstBoundaryTriangle);
        }

        [Test]
        public void FlippedTriangle_VolumeMeshInconsistentWinding()
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            int[] flipped = TestMeshes.FlipTriangle(triangles, 4);
            TetrahedralizationResult result = LatticeTetrahedralizer.Build(vertices, flipped, TetrahedralizationSettings.Default);
            MeshTopology topology = MeshTopology.Analyse(TestMeshes.WeldAtDefaultTolerance(vertices, flipped, out int[] welded).Positions, welded);
            AssertFailsWith(result, TetrahedralMeshIssueCode.VolumeMeshInconsistentWinding, topology.FirstInconsistentTriangle);
        }

        [Test]
        public void NaNVertex_NonFiniteVertex()
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            vertices[5].y = float.NaN;
            AssertFailsWith(LatticeTetrahedralizer.Build(vertices, triangles, TetrahedralizationSettings.Default), MeshBuildIssueCode.NonFiniteVertex, 5);
        }

        [Test]
        public void AllVerticesEqual_ZeroSize()
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            for (int v = 0; v < vertices.Length; v++)
                vertices[v] = new float3(1f, 2f, 3f);
            AssertFailsWith(LatticeTetrahedralizer.Build(vertices, triangles, TetrahedralizationSettings.Default), MeshBuildIssueCode.ZeroSize, -1);
        }

        [Test]
        public void MoreNodesThanLimit_TooManyNodes()
        {
            TetrahedralizationSettings settings = TetrahedralizationSettings.Default;
            settings.Resolution = 2;
            settings.MaxNodes = 26; // a 2 × 2 × 2 block has 27 nodes
            AssertFailsWith(BuildCube(settings), TetrahedralMeshIssueCode.TooManyNodes, -1);
            settings.MaxNodes = 27;
            Assert.That(BuildCube(settings).Succeeded, Is.True);
        }

        [TestCase(0)]
        [TestCase(129)]
        public void ResolutionOutsideRange_TetResolutionOutOfRange(int resolution)
        {
            TetrahedralizationSettings settings = TetrahedralizationSettings.Default;
            settings.Resolution = resolution;
            AssertFailsWith(BuildCube(settings), TetrahedralMeshIssueCode.TetResolutionOutOfRange, -1);
            Assert.That(settings.Sanitized().Resolution, Is.EqualTo(resolution < 1 ? 1 : 128));
        }

        [Test]
        public void MaxNodesZero_MaxNodesInvalid()
        {
            TetrahedralizationSettings settings = TetrahedralizationSettings.Default;
            settings.MaxNodes = 0;
            AssertFailsWith(BuildCube(settings), TetrahedralMeshIssueCode.MaxNodesInvalid, -1);
        }

        [Test]
        public void NegativeWeldTolerance_WeldToleranceInvalid()
        {
            TetrahedralizationSettings settings = TetrahedralizationSettings.Default;
            settings.WeldTolerance = -1f;
            AssertFailsWith(BuildCube(settings), MeshBuildIssueCode.WeldToleranceInvalid, -1);
        }
    }
}
