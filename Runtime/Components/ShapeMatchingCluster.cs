using SoftBodyDynamics.Solvers;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>Runtime state of one shape-matching cluster (rotation warm start, plastic deformation, rest data in use).</summary>
    [InternalBufferCapacity(0)]
    public struct ShapeMatchingCluster : IBufferElementData
    {
        /// <summary>The cluster state.</summary>
        public ClusterState Value;
    }
}
