using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The immutable, shareable part of a shape-matching body (a blob in ECS): rest shape, masses and
    /// overlapping clusters in compressed-row form, with their precomputed rest matrices. Views only;
    /// the memory belongs to the caller (managed arrays in <see cref="ShapeMatchingModelData"/>, blob
    /// arrays in ECS).
    /// </summary>
    public readonly ref struct ShapeMatchingModel
    {
        /// <summary>Rest positions x⁰ᵢ in body space (m), one per particle.</summary>
        public readonly ReadOnlySpan<float3> RestPositions;
        /// <summary>Particle masses mᵢ (kg), all &gt; 0.</summary>
        public readonly ReadOnlySpan<float> Masses;
        /// <summary>1/nᵢ, nᵢ = number of clusters containing particle i (0 for a particle in no cluster).</summary>
        public readonly ReadOnlySpan<float> InverseClusterCounts;
        /// <summary>Cluster c owns <c>ClusterParticles[ClusterOffsets[c] .. ClusterOffsets[c + 1]]</c>; length = clusters + 1.</summary>
        public readonly ReadOnlySpan<int> ClusterOffsets;
        /// <summary>Particle indices of every cluster, concatenated.</summary>
        public readonly ReadOnlySpan<int> ClusterParticles;
        /// <summary>Weight wᵢ = mᵢ/nᵢ of each entry of <see cref="ClusterParticles"/> (kg).</summary>
        public readonly ReadOnlySpan<float> ClusterWeights;
        /// <summary>Rest data of each cluster, computed with the weights wᵢ.</summary>
        public readonly ReadOnlySpan<ClusterRestData> ClusterRest;
        /// <summary>
        /// Scaled Ã_qq⁻¹ of the quadratic mode, 9 blocks of 3×3 per cluster (block (j,k) at
        /// <c>9c + 3j + k</c>); empty when the model was built without the quadratic mode.
        /// </summary>
        public readonly ReadOnlySpan<float3x3> QuadraticInverse;
        /// <summary>Rest data of the whole body with the plain masses: its centre and rotation place the body.</summary>
        public readonly ClusterRestData BodyRest;
        /// <summary>
        /// Inverse masses wᵢ (1/kg), 0 for a pinned particle (it stays where it is placed); empty when no particle is
        /// pinned, which keeps the step exactly as without pins (see <see cref="ParticleBody.InverseMasses"/>).
        /// </summary>
        public readonly ReadOnlySpan<float> InverseMasses;

        public ShapeMatchingModel(ReadOnlySpan<float3> restPositions, ReadOnlySpan<float> masses,
            ReadOnlySpan<float> inverseClusterCounts, ReadOnlySpan<int> clusterOffsets, ReadOnlySpan<int> clusterParticles,
            ReadOnlySpan<float> clusterWeights, ReadOnlySpan<ClusterRestData> clusterRest,
            ReadOnlySpan<float3x3> quadraticInverse, in ClusterRestData bodyRest)
            : this(restPositions, masses, inverseClusterCounts, clusterOffsets, clusterParticles, clusterWeights, clusterRest,
                quadraticInverse, bodyRest, default)
        {
        }

        /// <param name="inverseMasses">wᵢ per particle, 0 = pinned; empty when none is pinned.</param>
        public ShapeMatchingModel(ReadOnlySpan<float3> restPositions, ReadOnlySpan<float> masses,
            ReadOnlySpan<float> inverseClusterCounts, ReadOnlySpan<int> clusterOffsets, ReadOnlySpan<int> clusterParticles,
            ReadOnlySpan<float> clusterWeights, ReadOnlySpan<ClusterRestData> clusterRest,
            ReadOnlySpan<float3x3> quadraticInverse, in ClusterRestData bodyRest, ReadOnlySpan<float> inverseMasses)
        {
            InverseMasses = inverseMasses;
            RestPositions = restPositions;
            Masses = masses;
            InverseClusterCounts = inverseClusterCounts;
            ClusterOffsets = clusterOffsets;
            ClusterParticles = clusterParticles;
            ClusterWeights = clusterWeights;
            ClusterRest = clusterRest;
            QuadraticInverse = quadraticInverse;
            BodyRest = bodyRest;
        }

        public int ParticleCount => RestPositions.Length;
        public int ClusterCount => ClusterRest.Length;
        public bool HasQuadratic => QuadraticInverse.Length == ClusterRest.Length * QuadraticShapeMatching.BlocksPerCluster
                                    && ClusterRest.Length > 0;
    }
}
