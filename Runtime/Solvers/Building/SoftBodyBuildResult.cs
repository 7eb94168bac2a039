using System.Collections.Generic;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>What <see cref="SoftBodyBuilder.Build"/> produced, and every issue it found.</summary>
    public sealed class SoftBodyBuildResult
    {
        /// <summary>The shape-matching model; null when the build failed.</summary>
        public ShapeMatchingModelData Model;
        /// <summary>Render vertex v follows particle <c>VertexToParticle[v]</c> (a surface particle); null when the input could not be welded.</summary>
        public int[] VertexToParticle;
        /// <summary>The mesh's triangles as particle indices (same order and winding); null when the input could not be welded.</summary>
        public int[] ParticleTriangles;
        /// <summary>Particles from welded vertices: indices 0 .. SurfaceParticleCount − 1.</summary>
        public int SurfaceParticleCount;
        /// <summary>Interior lattice particles, numbered after the surface particles.</summary>
        public int InteriorParticleCount;
        /// <summary>Number of shape-matching clusters.</summary>
        public int ClusterCount;
        /// <summary>Mean particles per cluster.</summary>
        public float MeanClusterSize;
        /// <summary>True when every edge of the welded surface is shared by exactly two triangles.</summary>
        public bool IsClosed;
        /// <summary>Errors and warnings, in the order they were found.</summary>
        public List<ValidationIssue> Issues = new List<ValidationIssue>();

        /// <summary>True when the model was built (no error).</summary>
        public bool Succeeded => Model != null;

        /// <summary>All particles.</summary>
        public int ParticleCount => SurfaceParticleCount + InteriorParticleCount;
    }
}
