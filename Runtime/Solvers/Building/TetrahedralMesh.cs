using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// A volume mesh of tetrahedra: the shared topology of mass-spring and finite-element bodies. Every tetrahedron
    /// (a, b, c, d) is positively oriented: (b − a) · ((c − a) × (d − a)) &gt; 0. Managed arrays; built at bake time.
    /// </summary>
    public sealed class TetrahedralMesh
    {
        /// <summary>Rest positions of the nodes (m, body space).</summary>
        public float3[] Positions;
        /// <summary>Node indices of each tetrahedron, positively oriented.</summary>
        public int4[] Tetrahedra;

        public TetrahedralMesh(float3[] positions, int4[] tetrahedra)
        {
            Positions = positions;
            Tetrahedra = tetrahedra;
        }

        public int NodeCount => Positions.Length;
        public int TetrahedronCount => Tetrahedra.Length;

        /// <summary>Signed volume (b − a) · ((c − a) × (d − a)) / 6 of the tetrahedron (a, b, c, d) (m³); positive when positively oriented.</summary>
        public static float SignedVolume(float3 a, float3 b, float3 c, float3 d) => math.dot(b - a, math.cross(c - a, d - a)) / 6f;
    }

    /// <summary>Where a render vertex sits in a tetrahedral mesh: four nodes and barycentric weights that sum to 1.</summary>
    public struct EmbeddedVertex
    {
        /// <summary>Nodes of the tetrahedron that holds the vertex (or the nearest one).</summary>
        public int4 Nodes;
        /// <summary>Barycentric weights of the nodes; the vertex is Σ wₖ x_{Nodes[k]}.</summary>
        public float4 Weights;
    }
}
