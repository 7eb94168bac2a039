using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The arrays every particle body has, whatever holds it together: rest shape and masses (immutable, shared),
    /// positions and velocities (runtime state, relative to <see cref="ParticleBodyStatus.Origin"/>) and the per-substep
    /// scratch of the shared step. Views only; the memory belongs to the caller.
    /// </summary>
    public readonly ref struct ParticleBody
    {
        /// <summary>Rest positions x⁰ᵢ in body space (m).</summary>
        public readonly ReadOnlySpan<float3> RestPositions;
        /// <summary>Centre of mass of the rest shape (m, body space): the point placements refer to.</summary>
        public readonly float3 RestCenter;
        /// <summary>Particle masses mᵢ (kg), all &gt; 0.</summary>
        public readonly ReadOnlySpan<float> Masses;
        /// <summary>
        /// Inverse masses wᵢ = 1/mᵢ (1/kg), 0 for a pinned particle: the step keeps a pinned particle where it is
        /// (its velocity stays zero) and solve stages treat it as infinitely heavy. Empty = no particle is pinned
        /// (the stages then use 1/<see cref="Masses"/>).
        /// </summary>
        public readonly ReadOnlySpan<float> InverseMasses;
        /// <summary>Positions xᵢ relative to the body's origin (m).</summary>
        public readonly Span<float3> Positions;
        /// <summary>Velocities vᵢ (m/s).</summary>
        public readonly Span<float3> Velocities;
        /// <summary>Scratch: predicted positions x*ᵢ of the substep.</summary>
        public readonly Span<float3> Predicted;
        /// <summary>Scratch of the solve stage and the damping, one float3 per particle.</summary>
        public readonly Span<float3> Scratch;
        /// <summary>Scratch: contact normal of each particle in the substep (zero = no contact).</summary>
        public readonly Span<float3> ContactNormals;

        public ParticleBody(ReadOnlySpan<float3> restPositions, float3 restCenter, ReadOnlySpan<float> masses,
            Span<float3> positions, Span<float3> velocities, Span<float3> predicted, Span<float3> scratch, Span<float3> contactNormals)
            : this(restPositions, restCenter, masses, default, positions, velocities, predicted, scratch, contactNormals)
        {
        }

        /// <param name="inverseMasses">wᵢ, 0 for pinned particles; empty when none is pinned.</param>
        public ParticleBody(ReadOnlySpan<float3> restPositions, float3 restCenter, ReadOnlySpan<float> masses, ReadOnlySpan<float> inverseMasses,
            Span<float3> positions, Span<float3> velocities, Span<float3> predicted, Span<float3> scratch, Span<float3> contactNormals)
        {
            InverseMasses = inverseMasses;
            RestPositions = restPositions;
            RestCenter = restCenter;
            Masses = masses;
            Positions = positions;
            Velocities = velocities;
            Predicted = predicted;
            Scratch = scratch;
            ContactNormals = contactNormals;
        }

        public int ParticleCount => Positions.Length;

        /// <summary>True when some particles are pinned (<see cref="InverseMasses"/> given).</summary>
        public bool HasPins => InverseMasses.Length == Positions.Length && Positions.Length > 0;

        /// <summary>wᵢ: 0 for a pinned particle, else 1/mᵢ.</summary>
        public float InverseMass(int i) => HasPins ? InverseMasses[i] : 1f / Masses[i];
    }
}
