using SoftBodyDynamics.Solvers;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Immutable, shareable data of a mass-spring body (blob asset, tier 1): rest shape, masses, the springs along the
    /// edges of its tetrahedra (Teschner et al. 2003), and the two parallel layouts of the springs: incidence (the
    /// deterministic force gather) and colouring (the Gauss–Seidel/XPBD projection). Built at bake time by
    /// <see cref="MassSpringShapeBlobFactory"/>; every instance of a prefab shares one blob. Access it in place
    /// (<c>ref var shape = ref blob.Value;</c>).
    /// </summary>
    public struct MassSpringShapeBlob
    {
        /// <summary>Rest positions x⁰ᵢ of the particles (tetrahedron nodes) in mesh space (m).</summary>
        public BlobArray<float3> RestPositions;
        /// <summary>Centre of mass of the rest shape (m, mesh space).</summary>
        public float3 RestCenter;
        /// <summary>Particle masses mᵢ (kg, &gt; 0).</summary>
        public BlobArray<float> Masses;
        /// <summary>Inverse masses wᵢ (1/kg), 0 for a pinned particle.</summary>
        public BlobArray<float> InverseMasses;
        /// <summary>The springs: particles, rest length (m), stiffness (N/m), damping (N·s/m).</summary>
        public BlobArray<Spring> Springs;
        /// <summary>Incidence offsets: particle i's slots are <see cref="IncidenceSlots"/>[Offsets[i] .. Offsets[i + 1]).</summary>
        public BlobArray<int> IncidenceOffsets;
        /// <summary>Incidence slots (2 × spring + end), grouped by particle, increasing.</summary>
        public BlobArray<int> IncidenceSlots;
        /// <summary>Colour c holds <see cref="ColorSprings"/>[ColorOffsets[c] .. ColorOffsets[c + 1]).</summary>
        public BlobArray<int> ColorOffsets;
        /// <summary>Spring indices grouped by colour (no two springs of a colour share a particle).</summary>
        public BlobArray<int> ColorSprings;

        /// <summary>Number of particles.</summary>
        public int ParticleCount => RestPositions.Length;
        /// <summary>Number of springs.</summary>
        public int SpringCount => Springs.Length;

        /// <summary>The solver's view of this blob (spans over blob memory, no copy). Call it on the blob in place.</summary>
        public MassSpringModel AsModel() => new MassSpringModel(ShapeMatchingShapeBlob.View(ref RestPositions), RestCenter,
            ShapeMatchingShapeBlob.View(ref Masses), ShapeMatchingShapeBlob.View(ref InverseMasses), ShapeMatchingShapeBlob.View(ref Springs),
            ShapeMatchingShapeBlob.View(ref IncidenceOffsets), ShapeMatchingShapeBlob.View(ref IncidenceSlots),
            ShapeMatchingShapeBlob.View(ref ColorOffsets), ShapeMatchingShapeBlob.View(ref ColorSprings));
    }
}
