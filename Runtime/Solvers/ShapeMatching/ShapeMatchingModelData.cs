using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Managed storage of a <see cref="ShapeMatchingModel"/>, built once at bake or set-up time (not a
    /// hot path). The baker copies these arrays into a blob; tests and benchmarks use them directly.
    /// </summary>
    public sealed class ShapeMatchingModelData
    {
        public float3[] RestPositions;
        public float[] Masses;
        public float[] InverseClusterCounts;
        public int[] ClusterOffsets;
        public int[] ClusterParticles;
        public float[] ClusterWeights;
        public ClusterRestData[] ClusterRest;
        public float3x3[] QuadraticInverse;
        public ClusterRestData BodyRest;
        /// <summary>Inverse masses wᵢ (1/kg), 0 = pinned; null or empty when no particle is pinned (<see cref="PinParticles"/>).</summary>
        public float[] InverseMasses;

        public int ParticleCount => RestPositions.Length;
        public int ClusterCount => ClusterRest.Length;

        public ShapeMatchingModel AsModel() => new ShapeMatchingModel(RestPositions, Masses, InverseClusterCounts,
            ClusterOffsets, ClusterParticles, ClusterWeights, ClusterRest, QuadraticInverse, BodyRest, InverseMasses);

        /// <summary>
        /// Pins the particles whose flag is set (wᵢ = 0: they stay where the body is placed) and gives the others
        /// wᵢ = 1/mᵢ; no flag set removes the pins.
        /// </summary>
        /// <param name="pinned">One flag per particle.</param>
        public void PinParticles(ReadOnlySpan<bool> pinned)
        {
            bool any = false;
            for (int i = 0; i < pinned.Length; i++)
                any |= pinned[i];
            if (!any)
            {
                InverseMasses = null;
                return;
            }
            InverseMasses = new float[ParticleCount];
            for (int i = 0; i < ParticleCount; i++)
                InverseMasses[i] = pinned[i] ? 0f : 1f / Masses[i];
        }

        /// <summary>
        /// Precomputes everything the step needs from a rest shape and its clusters: nᵢ, the weights
        /// wᵢ = mᵢ/nᵢ, each cluster's rest data and, when <paramref name="buildQuadratic"/> is set,
        /// the scaled 9×9 inverses of the quadratic mode. The inputs are not validated here: the
        /// builder (<c>SoftBodyBuilder</c>) rejects bad meshes, masses and clusters with specific errors first.
        /// </summary>
        /// <param name="restPositions">Rest positions (m).</param>
        /// <param name="masses">Particle masses (kg, &gt; 0).</param>
        /// <param name="clusterOffsets">CSR offsets, length clusters + 1, starting at 0.</param>
        /// <param name="clusterParticles">Particle indices of each cluster, concatenated; no duplicates within a cluster.</param>
        /// <param name="buildQuadratic">Also build Ã_qq⁻¹ (324 bytes per cluster) for the quadratic mode.</param>
        public static ShapeMatchingModelData Create(float3[] restPositions, float[] masses, int[] clusterOffsets,
            int[] clusterParticles, bool buildQuadratic) =>
            Create(restPositions, masses, clusterOffsets, clusterParticles, buildQuadratic, null);

        /// <summary>
        /// As <see cref="Create(float3[], float[], int[], int[], bool)"/>, with the particles flagged in
        /// <paramref name="pinned"/> pinned (wᵢ = 0, see <see cref="InverseMasses"/>) and weighted
        /// <see cref="PinnedClusterWeight"/> × mᵢ in the cluster fits; null or no flag set = no pins (the same model as without).
        /// </summary>
        public static ShapeMatchingModelData Create(float3[] restPositions, float[] masses, int[] clusterOffsets,
            int[] clusterParticles, bool buildQuadratic, bool[] pinned)
        {
            bool anyPinned = pinned != null && Array.IndexOf(pinned, true) >= 0;
            int n = restPositions.Length;
            int clusters = clusterOffsets.Length - 1;
            var data = new ShapeMatchingModelData
            {
                RestPositions = (float3[])restPositions.Clone(),
                Masses = (float[])masses.Clone(),
                InverseClusterCounts = new float[n],
                ClusterOffsets = (int[])clusterOffsets.Clone(),
                ClusterParticles = (int[])clusterParticles.Clone(),
                ClusterWeights = new float[clusterParticles.Length],
                ClusterRest = new ClusterRestData[clusters],
                QuadraticInverse = buildQuadratic ? new float3x3[clusters * QuadraticShapeMatching.BlocksPerCluster] : Array.Empty<float3x3>(),
            };
            var counts = new int[n];
            foreach (int i in clusterParticles)
                counts[i]++;
            for (int i = 0; i < n; i++)
                data.InverseClusterCounts[i] = counts[i] > 0 ? 1f / counts[i] : 0f;
            for (int k = 0; k < clusterParticles.Length; k++)
                data.ClusterWeights[k] = masses[clusterParticles[k]] * data.InverseClusterCounts[clusterParticles[k]];

            for (int c = 0; c < clusters; c++)
            {
                int start = clusterOffsets[c], count = clusterOffsets[c + 1] - start;
                var members = new ReadOnlySpan<int>(data.ClusterParticles, start, count);
                var weights = new ReadOnlySpan<float>(data.ClusterWeights, start, count);
                data.ClusterRest[c] = ShapeMatching.ComputeRestData(data.RestPositions, members, weights);
                if (buildQuadratic)
                {
                    ref ClusterRestData rest = ref data.ClusterRest[c];
                    rest.QuadraticValid = QuadraticShapeMatching.ComputeRestInverse(data.RestPositions, members,
                        weights, rest.RestCenter, float3x3.identity, rest.LengthScale,
                        new Span<float3x3>(data.QuadraticInverse, c * QuadraticShapeMatching.BlocksPerCluster,
                            QuadraticShapeMatching.BlocksPerCluster), out _, out rest.QuadraticMeanSquare, out rest.QuadraticMeanCross);
                }
            }
            data.BodyRest = ShapeMatching.ComputeRestData(restPositions, masses);
            if (anyPinned)
                data.PinParticles(pinned);
            return data;
        }
    }
}
