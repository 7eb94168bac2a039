using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// A structured mesh of the box [0, Lx] × [0, Ly] (× [0, Lz]) in quadratic Lagrange elements: 27-node hexahedra
    /// (Q2, 3-D) or 9-node quadrilaterals (Q2, 2-D plane strain), nx × ny (× nz) equal elements. Nodes lie on the
    /// grid of (2nx + 1) × (2ny + 1) (× (2nz + 1)) points with spacing half an element, numbered with x slowest
    /// (node = (i·Ny + j)·Nz + k), which keeps the bandwidth of the assembled matrices near 2 node planes for a beam
    /// along x. Element e = (ex·ny + ey)·nz + ez; its local node a = (ax·3 + ay)·3 + az, ax, ay, az ∈ {0, 1, 2}
    /// at grid point (2ex + ax, 2ey + ay, 2ez + az).
    /// </summary>
    public sealed class FemBoxMesh
    {
        /// <summary>2 (plane strain) or 3.</summary>
        public readonly int Dimension;
        /// <summary>Elements along x, y, z (z is 1 in 2-D).</summary>
        public readonly int ElementsX, ElementsY, ElementsZ;
        /// <summary>Grid nodes along x, y, z (2n + 1; 1 along z in 2-D).</summary>
        public readonly int NodesX, NodesY, NodesZ;
        /// <summary>Box edge lengths (m); in 2-D, SizeZ is the out-of-plane thickness the integrals carry.</summary>
        public readonly double SizeX, SizeY, SizeZ;
        /// <summary>Nodes per element: 27 (3-D) or 9 (2-D).</summary>
        public readonly int NodesPerElement;
        /// <summary>Rest positions, Dimension doubles per node (m).</summary>
        public readonly double[] Positions;
        /// <summary>Element connectivity, NodesPerElement node indices per element.</summary>
        public readonly int[] Elements;

        /// <summary>Node count.</summary>
        public int NodeCount => NodesX * NodesY * NodesZ;
        /// <summary>Element count.</summary>
        public int ElementCount => ElementsX * ElementsY * ElementsZ;
        /// <summary>Degrees of freedom: Dimension per node.</summary>
        public int DofCount => NodeCount * Dimension;

        FemBoxMesh(int dimension, int nx, int ny, int nz, double lx, double ly, double lz)
        {
            if (nx < 1 || ny < 1 || nz < 1 || !(lx > 0) || !(ly > 0) || !(lz > 0))
                throw new ArgumentOutOfRangeException(nameof(nx), "Element counts must be ≥ 1 and sizes > 0.");
            Dimension = dimension;
            ElementsX = nx; ElementsY = ny; ElementsZ = dimension == 3 ? nz : 1;
            SizeX = lx; SizeY = ly; SizeZ = lz;
            NodesX = 2 * nx + 1; NodesY = 2 * ny + 1; NodesZ = dimension == 3 ? 2 * nz + 1 : 1;
            NodesPerElement = dimension == 3 ? 27 : 9;
            Positions = new double[NodeCount * dimension];
            for (int i = 0; i < NodesX; i++)
            for (int j = 0; j < NodesY; j++)
            for (int k = 0; k < NodesZ; k++)
            {
                int n = Node(i, j, k);
                Positions[n * dimension] = lx * i / (NodesX - 1);
                Positions[n * dimension + 1] = ly * j / (NodesY - 1);
                if (dimension == 3)
                    Positions[n * dimension + 2] = lz * k / (NodesZ - 1);
            }
            Elements = new int[ElementCount * NodesPerElement];
            int azCount = dimension == 3 ? 3 : 1;
            for (int ex = 0; ex < ElementsX; ex++)
            for (int ey = 0; ey < ElementsY; ey++)
            for (int ez = 0; ez < ElementsZ; ez++)
            {
                int e = (ex * ElementsY + ey) * ElementsZ + ez;
                int a = 0;
                for (int ax = 0; ax < 3; ax++)
                for (int ay = 0; ay < 3; ay++)
                for (int az = 0; az < azCount; az++)
                    Elements[e * NodesPerElement + a++] = Node(2 * ex + ax, 2 * ey + ay, dimension == 3 ? 2 * ez + az : 0);
            }
        }

        /// <summary>A 3-D box of nx × ny × nz 27-node hexahedra.</summary>
        public static FemBoxMesh Box(double lx, double ly, double lz, int nx, int ny, int nz) => new FemBoxMesh(3, nx, ny, nz, lx, ly, lz);

        /// <summary>A 2-D plane-strain rectangle of nx × ny 9-node quadrilaterals, of out-of-plane thickness (m).</summary>
        public static FemBoxMesh Rectangle(double lx, double ly, int nx, int ny, double thickness = 1) => new FemBoxMesh(2, nx, ny, 1, lx, ly, thickness);

        /// <summary>The node at grid point (i, j, k) (k = 0 in 2-D).</summary>
        public int Node(int i, int j, int k) => (i * NodesY + j) * NodesZ + k;

        /// <summary>Element edge lengths (m).</summary>
        public double ElementSizeX => SizeX / ElementsX;
        /// <summary>Element edge length along y (m).</summary>
        public double ElementSizeY => SizeY / ElementsY;
        /// <summary>Element edge length along z (m); the thickness in 2-D.</summary>
        public double ElementSizeZ => Dimension == 3 ? SizeZ / ElementsZ : SizeZ;
    }
}
