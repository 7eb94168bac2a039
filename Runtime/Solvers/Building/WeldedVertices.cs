using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Result of <see cref="MeshWelding.Weld"/>: one particle per group of coincident render vertices.</summary>
    public sealed class WeldedVertices
    {
        /// <summary>Particle positions (m), in order of each particle's first vertex.</summary>
        public float3[] Positions;
        /// <summary>The render-vertex binding: render vertex v is drawn at particle <c>VertexToParticle[v]</c>.</summary>
        public int[] VertexToParticle;
        /// <summary>The weld distance that was used (m).</summary>
        public float Tolerance;

        /// <summary>Number of particles.</summary>
        public int ParticleCount => Positions.Length;
    }
}
