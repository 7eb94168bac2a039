using SoftBodyDynamics.Solvers;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Immutable, shareable data of a finite-element body (blob asset, tier 1): rest shape, lumped masses, the linear
    /// tetrahedra (nodes, Dm⁻¹, rest volume), their incidence (deterministic force gather) and colouring (per-colour
    /// projection), the Jacobi diagonal of the rest stiffness and the material constants the elements were built
    /// with (μ, λ, ζ); for quadratic elements their 10 nodes and integration points, and the optional rest factor of the
    /// implicit step (<see cref="FemRestFactor"/>). Built at bake time by <see cref="FemShapeBlobFactory"/>; shared by every instance of a prefab.
    /// Access it in place (<c>ref var shape = ref blob.Value;</c>).
    /// </summary>
    public struct FemShapeBlob
    {
        /// <summary>Rest positions of the nodes in mesh space (m).</summary>
        public BlobArray<float3> RestPositions;
        /// <summary>Lumped node masses mᵢ (kg, &gt; 0).</summary>
        public BlobArray<float> Masses;
        /// <summary>Inverse masses wᵢ (1/kg), 0 for a pinned node.</summary>
        public BlobArray<float> InverseMasses;
        /// <summary>The tetrahedra.</summary>
        public BlobArray<TetElement> Elements;
        /// <summary>Incidence offsets of the element corners (slot = 4 × element + corner).</summary>
        public BlobArray<int> IncidenceOffsets;
        /// <summary>Incidence slots, grouped by node, increasing.</summary>
        public BlobArray<int> IncidenceSlots;
        /// <summary>Colour c holds <see cref="ColorElements"/>[ColorOffsets[c] .. ColorOffsets[c + 1]).</summary>
        public BlobArray<int> ColorOffsets;
        /// <summary>Element indices grouped by colour (no two elements of a colour share a node).</summary>
        public BlobArray<int> ColorElements;
        /// <summary>Rotation-invariant diagonal of the rest stiffness per node (N/m): the implicit solve's preconditioner.</summary>
        public BlobArray<float> StiffnessDiagonal;
        /// <summary>Centre of mass of the rest shape (m, mesh space).</summary>
        public float3 RestCenter;
        /// <summary>Shear modulus μ (Pa).</summary>
        public float Mu;
        /// <summary>First Lamé parameter λ (Pa).</summary>
        public float Lambda;
        /// <summary>Damping ratio ζ of the material (dimensionless).</summary>
        public float DampingRatio;
        /// <summary>Reference frequency of the damping when the parameters give none (rad/s).</summary>
        public float DefaultDampingFrequency;
        /// <summary>Quadratic elements: 10 nodes per element (empty for linear ones; <see cref="FemModel.ElementNodes"/>).</summary>
        public BlobArray<int> ElementNodes;
        /// <summary>Quadratic elements: shape-function gradients per integration point (1/m; <see cref="FemModel.PointGradients"/>).</summary>
        public BlobArray<float3> PointGradients;
        /// <summary>Quadratic elements: weight × rest volume per integration point (m³; <see cref="FemModel.PointVolumes"/>).</summary>
        public BlobArray<float> PointVolumes;
        /// <summary>Rest factor: free nodes in factor order (empty = block-Jacobi; <see cref="FemModel.FactorNodes"/>).</summary>
        public BlobArray<int> FactorNodes;
        /// <summary>Rest factor: envelope row starts (<see cref="FemModel.FactorRowStarts"/>).</summary>
        public BlobArray<int> FactorRowStarts;
        /// <summary>Rest factor: the Cholesky factor's envelope values (<see cref="FemModel.FactorValues"/>).</summary>
        public BlobArray<float> FactorValues;

        /// <summary>Number of nodes.</summary>
        public int ParticleCount => RestPositions.Length;
        /// <summary>Number of tetrahedra.</summary>
        public int ElementCount => Elements.Length;
        /// <summary>Integration points (one rotation each): the element count, 4 per element for quadratic ones.</summary>
        public int PointCount => ElementNodes.Length > 0 ? QuadraticTet.PointCount * Elements.Length : Elements.Length;

        /// <summary>The solver's view of this blob (spans over blob memory, no copy). Call it on the blob in place.</summary>
        public FemModel AsModel() => new FemModel(ShapeMatchingShapeBlob.View(ref RestPositions), ShapeMatchingShapeBlob.View(ref Masses),
            ShapeMatchingShapeBlob.View(ref InverseMasses), ShapeMatchingShapeBlob.View(ref Elements), ShapeMatchingShapeBlob.View(ref IncidenceOffsets),
            ShapeMatchingShapeBlob.View(ref IncidenceSlots), ShapeMatchingShapeBlob.View(ref ColorOffsets), ShapeMatchingShapeBlob.View(ref ColorElements),
            ShapeMatchingShapeBlob.View(ref StiffnessDiagonal), RestCenter, Mu, Lambda, DampingRatio, DefaultDampingFrequency,
            ShapeMatchingShapeBlob.View(ref ElementNodes), ShapeMatchingShapeBlob.View(ref PointGradients), ShapeMatchingShapeBlob.View(ref PointVolumes),
            ShapeMatchingShapeBlob.View(ref FactorNodes), ShapeMatchingShapeBlob.View(ref FactorRowStarts), ShapeMatchingShapeBlob.View(ref FactorValues));
    }
}
