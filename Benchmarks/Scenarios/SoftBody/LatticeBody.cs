using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// A box of particles on a regular lattice with overlapping cubic clusters, as in lattice shape
    /// matching: cluster (a, b, c) holds the particles whose lattice indices lie in
    /// [a·stride, a·stride + size) on each axis, with stride = size − overlap. A fixture with known
    /// geometry for tests and benchmarks, independent of mesh import.
    /// </summary>
    public static class LatticeBody
    {
        /// <param name="counts">Particles per axis.</param>
        /// <param name="spacing">Lattice spacing (m).</param>
        /// <param name="clusterSize">Particles per cluster edge; ≥ the largest count gives one cluster.</param>
        /// <param name="totalMass">Mass of the body (kg), spread uniformly.</param>
        public static ShapeMatchingModelData Create(int3 counts, float spacing, int clusterSize, float totalMass,
            bool buildQuadratic = false)
        {
            int n = counts.x * counts.y * counts.z;
            var rest = new float3[n];
            var masses = new float[n];
            float3 origin = -0.5f * spacing * new float3(counts.x - 1, counts.y - 1, counts.z - 1);
            for (int z = 0, i = 0; z < counts.z; z++)
            for (int y = 0; y < counts.y; y++)
            for (int x = 0; x < counts.x; x++, i++)
            {
                rest[i] = origin + spacing * new float3(x, y, z);
                masses[i] = totalMass / n;
            }
            var offsets = new List<int> { 0 };
            var members = new List<int>();
            var size = new int3(math.min(clusterSize, counts.x), math.min(clusterSize, counts.y), math.min(clusterSize, counts.z));
            var stride = new int3(Stride(size.x), Stride(size.y), Stride(size.z));
            for (int cz = 0; ; cz += stride.z)
            {
                int z0 = math.min(cz, counts.z - size.z);
                for (int cy = 0; ; cy += stride.y)
                {
                    int y0 = math.min(cy, counts.y - size.y);
                    for (int cx = 0; ; cx += stride.x)
                    {
                        int x0 = math.min(cx, counts.x - size.x);
                        for (int z = z0; z < z0 + size.z; z++)
                        for (int y = y0; y < y0 + size.y; y++)
                        for (int x = x0; x < x0 + size.x; x++)
                            members.Add(x + counts.x * (y + counts.y * z));
                        offsets.Add(members.Count);
                        if (x0 + size.x >= counts.x) break;
                    }
                    if (y0 + size.y >= counts.y) break;
                }
                if (z0 + size.z >= counts.z) break;
            }
            return ShapeMatchingModelData.Create(rest, masses, offsets.ToArray(), members.ToArray(), buildQuadratic);
        }

        /// <summary>Neighbouring clusters share half their width (at least one layer).</summary>
        static int Stride(int size) => math.max(1, size - math.max(1, size / 2));
    }
}
