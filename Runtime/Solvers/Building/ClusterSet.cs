namespace SoftBodyDynamics.Solvers
{
    /// <summary>Overlapping shape-matching clusters in CSR form, as <see cref="ShapeMatchingModelData.Create"/> takes them.</summary>
    public sealed class ClusterSet
    {
        /// <summary>Cluster c holds <c>Particles[Offsets[c] .. Offsets[c + 1])</c>; length clusters + 1, starting at 0.</summary>
        public int[] Offsets;
        /// <summary>Particle indices of every cluster, ascending and without duplicates within a cluster.</summary>
        public int[] Particles;
        /// <summary>Clusters with fewer than 4 particles or a planar rest shape, kept because they alone cover some particle.</summary>
        public int WeakClusterCount;

        /// <summary>Number of clusters.</summary>
        public int Count => Offsets.Length - 1;

        /// <summary>Mean number of particles per cluster.</summary>
        public float MeanSize => Count > 0 ? (float)Particles.Length / Count : 0f;
    }
}
