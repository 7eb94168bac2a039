using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Selections of the nodes of the study's bodies (boxes of <see cref="BoxTetrahedra"/>) and their volume.</summary>
    public static class StudyBox
    {
        /// <summary>Flags of the nodes whose coordinate <paramref name="axis"/> is within a hundredth of a cell of <paramref name="value"/>.</summary>
        public static bool[] NodesAt(TetrahedralMesh mesh, int axis, float value, float tolerance)
        {
            var flags = new bool[mesh.NodeCount];
            for (int i = 0; i < flags.Length; i++)
                flags[i] = Math.Abs(mesh.Positions[i][axis] - value) <= tolerance;
            return flags;
        }

        /// <summary>Index of the node nearest to <paramref name="point"/>.</summary>
        public static int Nearest(TetrahedralMesh mesh, float3 point)
        {
            int best = 0;
            for (int i = 1; i < mesh.NodeCount; i++)
                if (math.distancesq(mesh.Positions[i], point) < math.distancesq(mesh.Positions[best], point))
                    best = i;
            return best;
        }

        /// <summary>Σ of the tetrahedra's signed volumes at positions <paramref name="x"/> (m³).</summary>
        public static double Volume(TetrahedralMesh mesh, ReadOnlySpan<float3> x)
        {
            double v = 0;
            foreach (int4 t in mesh.Tetrahedra)
                v += TetrahedralMesh.SignedVolume(x[t.x], x[t.y], x[t.z], x[t.w]);
            return v;
        }
    }
}
