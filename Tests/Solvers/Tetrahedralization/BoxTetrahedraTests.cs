using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>BoxTetrahedra: count, volume, orientation and conformity of the Kuhn-split box.</summary>
    public class BoxTetrahedraTests
    {
        [TestCase(1, 1, 1)]
        [TestCase(3, 2, 4)]
        public void Box_SixTetsPerCell_TotalVolumeIsBoxVolume(int nx, int ny, int nz)
        {
            var size = new float3(2f, 0.5f, 1.5f);
            TetrahedralMesh mesh = BoxTetrahedra.Create(size, new int3(nx, ny, nz), new float3(1f, -2f, 0.25f));
            Assert.That(mesh.TetrahedronCount, Is.EqualTo(nx * ny * nz * 6));
            Assert.That(mesh.NodeCount, Is.EqualTo((nx + 1) * (ny + 1) * (nz + 1)));
            // Sum of 6·nx·ny·nz doubles from float nodes: the boundary nodes carry ≤ 1 ulp (≈ 2.4e-7 at |x| ≈ 2), so the
            // volume is exact to about 1e-6 relative.
            Assert.That(TetrahedralMeshChecks.TotalVolume(mesh), Is.EqualTo(size.x * size.y * size.z).Within(1e-6 * size.x * size.y * size.z));
            TetMeshAssert.AllPositive(mesh);
            int boundary = TetMeshAssert.Conforms(mesh);
            Assert.That(boundary, Is.EqualTo(4 * (nx * ny + ny * nz + nz * nx)));
        }
    }
}
