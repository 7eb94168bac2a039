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
        /// the scaled 9×9 inverses of the quadratic mode. The builder (<c>SoftBodyBuilder</c>) reports bad meshes,
        /// masses and clusters as issues first; called directly with such input, this throws an
        /// <see cref="ArgumentException"/> that names the first bad value (<see cref="Check"/>).
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
            Check(restPositions, masses, clusterOffsets, clusterParticles, pinned);
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

        /// <summary>
        /// Throws an <see cref="ArgumentException"/> naming the first value <see cref="Create(float3[], float[], int[], int[], bool, bool[])"/>
        /// cannot use: a missing array, a non-finite rest position, a mass that is not finite and above 0, CSR offsets that do not
        /// start at 0, decrease or end past the particle list, or a particle index out of range.
        /// </summary>
        public static void Check(float3[] restPositions, float[] masses, int[] clusterOffsets, int[] clusterParticles, bool[] pinned = null)
        {
            if (restPositions == null || masses == null || clusterOffsets == null || clusterParticles == null)
                throw new ArgumentNullException(restPositions == null ? nameof(restPositions) : masses == null ? nameof(masses)
                    : clusterOffsets == null ? nameof(clusterOffsets) : nameof(clusterParticles));
            int n = restPositions.Length;
            if (masses.Length != n)
                throw new ArgumentException($"{masses.Length} masses for {n} particles: give one mass per particle.", nameof(masses));
            if (pinned != null && pinned.Length != n)
                throw new ArgumentException($"{pinned.Length} pin flags for {n} particles: give one flag per particle, or none.", nameof(pinned));
            for (int i = 0; i < n; i++)
            {
                if (!math.all(math.isfinite(restPositions[i])))
                    throw new ArgumentException($"Rest position {i} is {restPositions[i]}: every rest position must be finite (m).", nameof(restPositions));
                if (!(masses[i] > 0f) || !math.isfinite(masses[i]))
                    throw new ArgumentException($"Mass {i} is {masses[i]} kg: every particle mass must be finite and above 0 kg (pin a particle to hold it still).",
                        nameof(masses));
            }
            if (clusterOffsets.Length < 1 || clusterOffsets[0] != 0)
                throw new ArgumentException("The cluster offsets must start with 0 (CSR: one offset per cluster, then the end).", nameof(clusterOffsets));
            for (int c = 1; c < clusterOffsets.Length; c++)
                if (clusterOffsets[c] < clusterOffsets[c - 1] || clusterOffsets[c] > clusterParticles.Length)
                    throw new ArgumentException($"Cluster offset {c} is {clusterOffsets[c]}: the offsets must not decrease nor pass the {clusterParticles.Length} cluster particles.",
                        nameof(clusterOffsets));
            for (int k = 0; k < clusterParticles.Length; k++)
                if ((uint)clusterParticles[k] >= (uint)n)
                    throw new ArgumentException($"Cluster particle {k} is {clusterParticles[k]}: indices must be from 0 to {n - 1}.", nameof(clusterParticles));
        }
    }
}
