using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The mutable part of one body (dynamic buffers in ECS) and the scratch the step needs. Views
    /// only; every span of particles has the model's particle count, every span of clusters its
    /// cluster count. <see cref="ShapeMatchingSolver.Initialize"/> and
    /// <see cref="ShapeMatchingSolver.PlaceRestShape"/> use no scratch: the three scratch spans may be empty there.
    /// </summary>
    public readonly ref struct ShapeMatchingState
    {
        /// <summary>Particle positions xᵢ (m, world).</summary>
        public readonly Span<float3> Positions;
        /// <summary>Particle velocities vᵢ (m/s, world).</summary>
        public readonly Span<float3> Velocities;
        /// <summary>Per-cluster rotation, plastic deformation and rest data in use.</summary>
        public readonly Span<ClusterState> Clusters;
        /// <summary>
        /// Per-instance copy of the quadratic Ã_qq⁻¹ blocks (9 per cluster) that plastic flow rewrites.
        /// Empty to use the model's (no plasticity, or not in quadratic mode).
        /// </summary>
        public readonly Span<float3x3> QuadraticInverse;
        /// <summary>Scratch: predicted positions x*ᵢ of the substep.</summary>
        public readonly Span<float3> Predicted;
        /// <summary>Scratch: averaged goal positions of the substep.</summary>
        public readonly Span<float3> Goals;
        /// <summary>Scratch: contact normal of each particle in the substep (zero = no contact).</summary>
        public readonly Span<float3> ContactNormals;

        /// <summary>Scratch float3s per particle the step needs: predicted positions, goals, contact normals.</summary>
        public const int ScratchPerParticle = 3;

        /// <summary>
        /// The state over its buffers and one scratch span of <see cref="ScratchPerParticle"/> × particles, split into
        /// predicted positions, goals and contact normals (the layout the ECS job and the Burst benchmark share).
        /// </summary>
        public static ShapeMatchingState FromScratch(Span<float3> positions, Span<float3> velocities, Span<ClusterState> clusters,
            Span<float3x3> quadraticInverse, Span<float3> scratch)
        {
            int n = positions.Length;
            return new ShapeMatchingState(positions, velocities, clusters, quadraticInverse,
                scratch.Slice(0, n), scratch.Slice(n, n), scratch.Slice(2 * n, n));
        }

        public ShapeMatchingState(Span<float3> positions, Span<float3> velocities, Span<ClusterState> clusters,
            Span<float3x3> quadraticInverse, Span<float3> predicted, Span<float3> goals, Span<float3> contactNormals)
        {
            Positions = positions;
            Velocities = velocities;
            Clusters = clusters;
            QuadraticInverse = quadraticInverse;
            Predicted = predicted;
            Goals = goals;
            ContactNormals = contactNormals;
        }
    }
}
