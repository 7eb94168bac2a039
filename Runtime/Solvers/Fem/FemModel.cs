using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The immutable part of a finite-element body as spans (a blob in ECS): rest shape, lumped masses, elements,
    /// their incidence and colouring, and the material. Obtained from <see cref="FemModelData.AsModel"/>.
    /// <para>
    /// Linear tetrahedra (4 nodes, one integration point: <see cref="Elements"/>) or quadratic ones (<see cref="QuadraticTet"/>:
    /// 10 nodes in <see cref="ElementNodes"/>, 4 integration points with their shape-function gradients and volumes;
    /// <see cref="Elements"/> then holds the corner tetrahedra). Per-element values have <see cref="NodesPerElement"/>
    /// slots (slot = <see cref="NodesPerElement"/> × element + node); rotations and tangents are per integration point
    /// (point = <see cref="PointsPerElement"/> × element + q).
    /// </para>
    /// </summary>
    public readonly ref struct FemModel
    {
        /// <summary>Rest positions of the nodes (m, body space).</summary>
        public readonly ReadOnlySpan<float3> RestPositions;
        /// <summary>Lumped node masses mᵢ = ρ Σ V_t / 4 over the node's tetrahedra (kg), all &gt; 0.</summary>
        public readonly ReadOnlySpan<float> Masses;
        /// <summary>Inverse masses wᵢ (1/kg), 0 for a pinned node.</summary>
        public readonly ReadOnlySpan<float> InverseMasses;
        /// <summary>The tetrahedra (quadratic elements: their corner tetrahedra).</summary>
        public readonly ReadOnlySpan<TetElement> Elements;
        /// <summary><see cref="ElementIncidence.Offsets"/> of the elements' nodes (slot = <see cref="NodesPerElement"/> × element + node).</summary>
        public readonly ReadOnlySpan<int> IncidenceOffsets;
        /// <summary><see cref="ElementIncidence.Slots"/> of the elements' corners.</summary>
        public readonly ReadOnlySpan<int> IncidenceSlots;
        /// <summary><see cref="GraphColoring.ColorOffsets"/> of the elements.</summary>
        public readonly ReadOnlySpan<int> ColorOffsets;
        /// <summary><see cref="GraphColoring.Elements"/>: element indices grouped by colour.</summary>
        public readonly ReadOnlySpan<int> ColorElements;
        /// <summary>
        /// kᵢ = Σ_points V_q (μ + (μ + λ)/3) |∇Nᵢ|² (N/m): one third of the trace of node i's diagonal block of the rest
        /// stiffness K₀, invariant under the element rotations.
        /// </summary>
        public readonly ReadOnlySpan<float> StiffnessDiagonal;
        /// <summary>Centre of mass of the rest shape (m, body space).</summary>
        public readonly float3 RestCenter;
        /// <summary>Shear modulus μ (Pa).</summary>
        public readonly float Mu;
        /// <summary>First Lamé parameter λ (Pa) of linear elasticity (the Neo-Hookean model uses λ + μ, see <see cref="FemElasticity.NeoHookeanLambda"/>).</summary>
        public readonly float Lambda;
        /// <summary>Damping ratio ζ of the material at the reference frequency (dimensionless).</summary>
        public readonly float DampingRatio;
        /// <summary>Default reference frequency ω_ref = π √(μ/ρ) / L (rad/s), L the longest side of the rest bounds: the damping frequency when the parameters give none.</summary>
        public readonly float DefaultDampingFrequency;
        /// <summary>Quadratic elements: 10 node indices per element (<see cref="QuadraticTet"/> order). Empty for linear ones.</summary>
        public readonly ReadOnlySpan<int> ElementNodes;
        /// <summary>Quadratic elements: per integration point its 10 shape-function gradients ∇N_a (1/m) at rest (point p at 10p). Empty for linear ones.</summary>
        public readonly ReadOnlySpan<float3> PointGradients;
        /// <summary>Quadratic elements: per integration point its quadrature weight times the rest volume (m³). Empty for linear ones.</summary>
        public readonly ReadOnlySpan<float> PointVolumes;
        /// <summary><see cref="FemRestFactor"/>: free nodes in factor order (rank → node). Empty = no factor (block-Jacobi preconditioning).</summary>
        public readonly ReadOnlySpan<int> FactorNodes;
        /// <summary><see cref="FemRestFactor"/>: start of each factor row's envelope in <see cref="FactorValues"/> (3 rows per free node, plus one).</summary>
        public readonly ReadOnlySpan<int> FactorRowStarts;
        /// <summary><see cref="FemRestFactor"/>: the Cholesky factor L of M + c₀ K₀, row envelopes.</summary>
        public readonly ReadOnlySpan<float> FactorValues;

        public FemModel(ReadOnlySpan<float3> restPositions, ReadOnlySpan<float> masses, ReadOnlySpan<float> inverseMasses,
            ReadOnlySpan<TetElement> elements, ReadOnlySpan<int> incidenceOffsets, ReadOnlySpan<int> incidenceSlots,
            ReadOnlySpan<int> colorOffsets, ReadOnlySpan<int> colorElements, ReadOnlySpan<float> stiffnessDiagonal,
            float3 restCenter, float mu, float lambda, float dampingRatio, float defaultDampingFrequency,
            ReadOnlySpan<int> elementNodes = default, ReadOnlySpan<float3> pointGradients = default, ReadOnlySpan<float> pointVolumes = default,
            ReadOnlySpan<int> factorNodes = default, ReadOnlySpan<int> factorRowStarts = default, ReadOnlySpan<float> factorValues = default)
        {
            FactorNodes = factorNodes;
            FactorRowStarts = factorRowStarts;
            FactorValues = factorValues;
            ElementNodes = elementNodes;
            PointGradients = pointGradients;
            PointVolumes = pointVolumes;
            RestPositions = restPositions;
            Masses = masses;
            InverseMasses = inverseMasses;
            Elements = elements;
            IncidenceOffsets = incidenceOffsets;
            IncidenceSlots = incidenceSlots;
            ColorOffsets = colorOffsets;
            ColorElements = colorElements;
            StiffnessDiagonal = stiffnessDiagonal;
            RestCenter = restCenter;
            Mu = mu;
            Lambda = lambda;
            DampingRatio = dampingRatio;
            DefaultDampingFrequency = defaultDampingFrequency;
        }

        /// <summary>Number of nodes (particles).</summary>
        public int ParticleCount => RestPositions.Length;
        /// <summary>Number of tetrahedra.</summary>
        public int ElementCount => Elements.Length;
        /// <summary>True when the model holds a <see cref="FemRestFactor"/> (the implicit step's preconditioner).</summary>
        public bool HasRestFactor => FactorValues.Length > 0;
        /// <summary>True for quadratic (10-node) elements.</summary>
        public bool IsQuadratic => ElementNodes.Length > 0;
        /// <summary>Nodes (slots) per element: 4 or 10.</summary>
        public int NodesPerElement => IsQuadratic ? QuadraticTet.NodeCount : 4;
        /// <summary>Integration points per element: 1 or 4.</summary>
        public int PointsPerElement => IsQuadratic ? QuadraticTet.PointCount : 1;
        /// <summary>Integration points (rotations, tangents) of the body.</summary>
        public int PointCount => PointsPerElement * ElementCount;
        /// <summary>Element slots of the body.</summary>
        public int SlotCount => NodesPerElement * ElementCount;
        /// <summary>Number of element colours.</summary>
        public int ColorCount => ColorOffsets.Length - 1;
    }
}
