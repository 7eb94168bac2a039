namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>How the shape-matching benchmark lattices are split into clusters.</summary>
    public enum ShapeMatchingClusterLayout
    {
        /// <summary>The whole body is one cluster (Müller et al. 2005): one matrix solve per substep.</summary>
        Single,
        /// <summary>
        /// Overlapping cubic clusters of <see cref="ShapeMatchingBenchmarkBody.ClusterEdge"/>³ lattice points that
        /// share half their width with each neighbour (lattice shape matching): an interior particle is in 8 clusters.
        /// </summary>
        Overlapping,
    }
}
