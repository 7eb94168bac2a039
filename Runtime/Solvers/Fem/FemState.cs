using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The mutable part of one finite-element body (dynamic buffers in ECS) and the scratch its step needs. Views
    /// only. Per-particle spans have the model's node count; rotations, multipliers and tangents one entry per integration
    /// point (<see cref="FemModel.PointCount"/>: the element count for linear elements), slots
    /// <see cref="FemModel.SlotCount"/> entries.
    /// <see cref="FemSolver.Initialize"/> uses no scratch: the scratch spans may be empty there.
    /// </summary>
    public readonly ref struct FemState
    {
        /// <summary>Node positions xᵢ (m, relative to <see cref="ParticleBodyStatus.Origin"/>).</summary>
        public readonly Span<float3> Positions;
        /// <summary>Node velocities vᵢ (m/s).</summary>
        public readonly Span<float3> Velocities;
        /// <summary>Per integration point: its rotation R, the warm start of the next extraction. Kept between steps.</summary>
        public readonly Span<quaternion> Rotations;
        /// <summary>Scratch: predicted positions of the shared step.</summary>
        public readonly Span<float3> Predicted;
        /// <summary>Scratch: contact normals of the shared step.</summary>
        public readonly Span<float3> ContactNormals;
        /// <summary>Scratch of the stage, one float3 per particle (forces, right-hand side, XPBD positions).</summary>
        public readonly Span<float3> Forces;
        /// <summary>Scratch of the implicit solve: <see cref="WorkVectors"/> × particles (Δv, r, z, p, q of conjugate gradients and the two halves of the block-Jacobi preconditioner).</summary>
        public readonly Span<float3> Work;
        /// <summary>Scratch: per element node value (slot = <see cref="FemModel.NodesPerElement"/> × e + node), gathered per node.</summary>
        public readonly Span<float3> Slots;
        /// <summary>Scratch: per element XPBD multipliers (x = λ_D, y = λ_H) of the substep.</summary>
        public readonly Span<float3> Multipliers;
        /// <summary>
        /// Scratch of the Neo-Hookean implicit step: per element its projected Hessian, <see cref="NeoHookeanTangent.Float3Count"/>
        /// float3s (element e at <see cref="NeoHookeanTangent.Float3Count"/> × e). May be empty for the other integrators.
        /// </summary>
        public readonly Span<float3> Tangents;
        /// <summary>
        /// Kept between steps, optional: per node the last implicit substep's velocity change Δv (m/s), the first guess of the
        /// next conjugate-gradient solve when the model has a <see cref="FemRestFactor"/>. Empty = every solve starts from 0
        /// (the same solution to the tolerance, more iterations).
        /// </summary>
        public readonly Span<float3> WarmStart;

        /// <summary>Vectors of the conjugate-gradient solve: Δv, r, z, p, q and the preconditioner's two.</summary>
        public const int WorkVectors = 7;
        /// <summary>Scratch float3s per particle: predicted positions, contact normals, forces, and <see cref="WorkVectors"/>.</summary>
        public const int ScratchPerParticle = 3 + WorkVectors;
        /// <summary>
        /// Scratch float3s per integration point: 4 slots, the multipliers and the Neo-Hookean tangent
        /// (<see cref="NeoHookeanTangent.Float3Count"/>); a quadratic element's 10 slots fit in its 4 points' 16.
        /// </summary>
        public const int ScratchPerElement = 5 + NeoHookeanTangent.Float3Count;

        /// <summary>
        /// The state over its buffers, one particle scratch of <see cref="ScratchPerParticle"/> × particles and one element
        /// scratch of <see cref="ScratchPerElement"/> × integration points (one rotation each; the layout the ECS job and the
        /// benchmarks share), and the optional <paramref name="warmStart"/> (see <see cref="WarmStart"/>).
        /// </summary>
        public static FemState FromScratch(Span<float3> positions, Span<float3> velocities, Span<quaternion> rotations,
            Span<float3> particleScratch, Span<float3> elementScratch, Span<float3> warmStart = default)
        {
            int n = positions.Length, e = rotations.Length;
            return new FemState(positions, velocities, rotations, particleScratch.Slice(0, n), particleScratch.Slice(n, n),
                particleScratch.Slice(2 * n, n), particleScratch.Slice(3 * n, WorkVectors * n),
                elementScratch.Slice(0, 4 * e), elementScratch.Slice(4 * e, e),
                elementScratch.Slice(5 * e, NeoHookeanTangent.Float3Count * e), warmStart);
        }

        /// <summary>The state over explicit spans (see the fields); <paramref name="tangents"/> may be left empty unless the Neo-Hookean implicit step runs.</summary>
        public FemState(Span<float3> positions, Span<float3> velocities, Span<quaternion> rotations, Span<float3> predicted,
            Span<float3> contactNormals, Span<float3> forces, Span<float3> work, Span<float3> slots, Span<float3> multipliers,
            Span<float3> tangents = default, Span<float3> warmStart = default)
        {
            WarmStart = warmStart;
            Positions = positions;
            Velocities = velocities;
            Rotations = rotations;
            Predicted = predicted;
            ContactNormals = contactNormals;
            Forces = forces;
            Work = work;
            Slots = slots;
            Multipliers = multipliers;
            Tangents = tangents;
        }
    }
}
