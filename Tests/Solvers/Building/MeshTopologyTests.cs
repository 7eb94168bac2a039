using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Closedness, manifoldness, winding and degenerate triangles of welded meshes (integer counts, no tolerances).</summary>
    public class MeshTopologyTests
    {
        static MeshTopology WeldAndAnalyse(float3[] vertices, int[] triangles)
        {
            WeldedVertices welded = TestMeshes.WeldAtDefaultTolerance(vertices, triangles, out int[] particleTriangles);
            return MeshTopology.Analyse(welded.Positions, particleTriangles);
        }

        [Test]
        public void Topology_WeldedCubeIsClosedAndConsistentlyWound()
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            MeshTopology topology = WeldAndAnalyse(vertices, triangles);
            Assert.That(topology.IsClosed, Is.True);
            Assert.That(topology.IsConsistentlyWound, Is.True);
            Assert.That(topology.EdgeCount, Is.EqualTo(18), "12 cube edges + 6 face diagonals");
            Assert.That(topology.DegenerateTriangleCount, Is.EqualTo(0));
        }

        [Test]
        public void Topology_UnweldedCubeIsOpen()
        {
            // Without welding every face is a separate quad: 6 × 4 boundary edges.
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            MeshTopology topology = MeshTopology.Analyse(vertices, triangles);
            Assert.That(topology.IsClosed, Is.False);
            Assert.That(topology.BoundaryEdgeCount, Is.EqualTo(24));
        }

        [Test]
        public void Topology_OpenQuadIsNotClosed()
        {
            TestMeshes.OpenQuad(out float3[] vertices, out int[] triangles);
            MeshTopology topology = WeldAndAnalyse(vertices, triangles);
            Assert.That(topology.IsClosed, Is.False);
            Assert.That(topology.BoundaryEdgeCount, Is.EqualTo(4));
            Assert.That(topology.FirstBoundaryTriangle, Is.EqualTo(0));
            Assert.That(topology.EdgeCount, Is.EqualTo(5));
        }

        [Test]
        public void Topology_EdgeSharedByThreeTrianglesIsNonManifold()
        {
            float3[] vertices =
            {
                new float3(0, 0, 0), new float3(1, 0, 0), new float3(0, 1, 0), new float3(0, -1, 0), new float3(0, 0, 1),
            };
            int[] triangles = { 0, 2, 4, 0, 1, 2, 1, 0, 3, 0, 1, 4 };
            MeshTopology topology = MeshTopology.Analyse(vertices, triangles);
            Assert.That(topology.NonManifoldEdgeCount, Is.EqualTo(1), "edge 0–1 is used by triangles 1, 2 and 3");
            Assert.That(topology.FirstNonManifoldTriangle, Is.EqualTo(1));
            Assert.That(topology.IsClosed, Is.False);
        }

        [Test]
        public void Topology_FlippedTriangleMakesWindingInconsistent()
        {
            TestMeshes.UnityCube(out float3[] vertices, out int[] triangles);
            MeshTopology topology = WeldAndAnalyse(vertices, TestMeshes.FlipTriangle(triangles, 5));
            Assert.That(topology.IsClosed, Is.True, "flipping does not open the surface");
            Assert.That(topology.InconsistentEdgeCount, Is.EqualTo(3), "each edge of the flipped triangle now runs the same way as its neighbour's");
            Assert.That(topology.IsConsistentlyWound, Is.False);
        }

        [Test]
        public void Topology_CountsRepeatedCornerAndZeroAreaTrianglesAsDegenerate()
        {
            TestMeshes.UnityCube(out float3[] cube, out int[] cubeTriangles);
            // Extra triangle 12 repeats vertex 0; triangle 13 has three collinear corners (0, 1 and their midpoint).
            float3[] vertices = new float3[cube.Length + 1];
            cube.CopyTo(vertices, 0);
            vertices[cube.Length] = 0.5f * (cube[0] + cube[1]);
            int[] triangles = new int[cubeTriangles.Length + 6];
            cubeTriangles.CopyTo(triangles, 0);
            new[] { 0, 0, 1, 0, cube.Length, 1 }.CopyTo(triangles, cubeTriangles.Length);

            MeshTopology topology = MeshTopology.Analyse(vertices, triangles);
            Assert.That(topology.DegenerateTriangleCount, Is.EqualTo(2));
            Assert.That(topology.FirstDegenerateTriangle, Is.EqualTo(12));
        }

        [Test]
        public void Topology_WeldedUvSphereIsClosedWithCollapsedPoleTriangles()
        {
            const int rings = 12, segments = 20;
            TestMeshes.UvSphere(rings, segments, out float3[] vertices, out int[] triangles);
            MeshTopology topology = WeldAndAnalyse(vertices, triangles);
            Assert.That(topology.IsClosed, Is.True);
            Assert.That(topology.IsConsistentlyWound, Is.True);
            Assert.That(topology.DegenerateTriangleCount, Is.EqualTo(2 * segments), "one triangle per quad of each pole row");
        }
    }
}
