using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The immutable, shareable part of a mass-spring body (a blob in ECS): rest shape, masses, springs, and the two
    /// parallel layouts of the springs (<see cref="ElementIncidence"/> for the force gather, <see cref="GraphColoring"/>
    /// for the XPBD projection). Views only; the memory belongs to the caller (<see cref="MassSpringModelData"/> or a blob).
    /// </summary>
    public readonly ref struct MassSpringModel
    {
        /// <summary>Rest positions x⁰ᵢ in body space (m).</summary>
        public readonly ReadOnlySpan<float3> RestPositions;
        /// <summary>Centre of mass of the rest shape (m, body space).</summary>
        public readonly float3 RestCenter;
        /// <summary>Particle masses mᵢ (kg), all &gt; 0.</summary>
        public readonly ReadOnlySpan<float> Masses;
        /// <summary>Inverse masses wᵢ (1/kg), 0 for pinned particles.</summary>
        public readonly ReadOnlySpan<float> InverseMasses;
        /// <summary>The springs.</summary>
        public readonly ReadOnlySpan<Spring> Springs;
        /// <summary>Incidence offsets: particle i's slots are <see cref="IncidenceSlots"/>[Offsets[i] .. Offsets[i + 1]); slot 2e is spring e's A, 2e + 1 its B.</summary>
        public readonly ReadOnlySpan<int> IncidenceOffsets;
        /// <summary>Incidence slots, grouped by particle, increasing.</summary>
        public readonly ReadOnlySpan<int> IncidenceSlots;
        /// <summary>Colour c holds springs <see cref="ColorSprings"/>[ColorOffsets[c] .. ColorOffsets[c + 1]); no two share a particle.</summary>
        public readonly ReadOnlySpan<int> ColorOffsets;
        /// <summary>Spring indices grouped by colour.</summary>
        public readonly ReadOnlySpan<int> ColorSprings;

        public MassSpringModel(ReadOnlySpan<float3> restPositions, float3 restCenter, ReadOnlySpan<float> masses,
            ReadOnlySpan<float> inverseMasses, ReadOnlySpan<Spring> springs, ReadOnlySpan<int> incidenceOffsets,
            ReadOnlySpan<int> incidenceSlots, ReadOnlySpan<int> colorOffsets, ReadOnlySpan<int> colorSprings)
        {
            RestPositions = restPositions;
            RestCenter = restCenter;
            Masses = masses;
            InverseMasses = inverseMasses;
            Springs = springs;
            IncidenceOffsets = incidenceOffsets;
            IncidenceSlots = incidenceSlots;
            ColorOffsets = colorOffsets;
            ColorSprings = colorSprings;
        }

        /// <summary>Number of particles.</summary>
        public int ParticleCount => RestPositions.Length;
        /// <summary>Number of springs.</summary>
        public int SpringCount => Springs.Length;
        /// <summary>Number of colours of the springs.</summary>
        public int ColorCount => ColorOffsets.Length - 1;
    }
}
