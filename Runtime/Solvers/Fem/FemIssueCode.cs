namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Problems of a finite-element model, its material and its parameters (<see cref="FemModelData"/>, <see cref="FemParameterValidation"/>, and the authoring's stability check).
    /// The numbers are unique across domains and stable (they may be stored); new codes take new numbers. An
    /// <see cref="IssueCode"/> carries any domain's code.
    /// </summary>
    public enum FemIssueCode
    {
        /// <summary>The tetrahedral mesh has no nodes or no tetrahedra.</summary>
        MeshEmpty = 140,
        /// <summary>A tetrahedron refers to a node that does not exist, or repeats a node. Index: the tetrahedron.</summary>
        TetrahedronNodeInvalid = 141,
        /// <summary>A tetrahedron has zero volume at rest (its four nodes are coplanar, or a position is not finite). Index: the tetrahedron.</summary>
        TetrahedronDegenerate = 142,
        /// <summary>A tetrahedron is inverted at rest (negative signed volume: nodes in the wrong order). Index: the tetrahedron.</summary>
        TetrahedronInverted = 143,
        /// <summary>
        /// Warning: a sliver tetrahedron, quality 6√2 V / l_rms³ below <see cref="FemModelData.SliverQuality"/> (1 for a
        /// regular tetrahedron): it stiffens the body and shortens the explicit stable step. Index: the tetrahedron.
        /// </summary>
        TetrahedronSliver = 144,
        /// <summary>Warning: a node is used by no tetrahedron; it has no stiffness and is held in place (pinned). Index: the node.</summary>
        NodeUnused = 145,
        /// <summary>The material is invalid (E ≤ 0, ν outside [0, 0.5), ρ ≤ 0 or ζ &lt; 0, or a value not finite).</summary>
        MaterialInvalid = 146,
        /// <summary>The pinned-node list's length differs from the node count.</summary>
        PinnedCountMismatch = 147,
        /// <summary>
        /// Warning: the finite elements are too stiff for the substep of the explicit integrator (symplectic Euler, or an
        /// unsupported model/integrator pair that falls back to it): h exceeds <c>FemStability.MaxStableStep</c>. Use more
        /// substeps, a softer material, a lower resolution, or an unconditionally stable integrator.
        /// </summary>
        StepAboveStableLimit = 191,
        /// <summary>The FEM material model or integrator is not one of the defined values.</summary>
        ModelInvalid = 192,
        /// <summary>FEM substeps (1–256), XPBD iterations (1–64), CG iterations (1–10000) or Newton iterations (1–16) out of range.</summary>
        IterationsOutOfRange = 193,
        /// <summary>The conjugate-gradient tolerance is not a finite relative residual above 0 and below 1.</summary>
        CgToleranceInvalid = 194,
        /// <summary>The Rayleigh damping reference frequency is negative or not finite (0 = the model's estimate).</summary>
        DampingFrequencyInvalid = 195,
        /// <summary>The FEM element order is not Linear or Quadratic.</summary>
        ElementOrderInvalid = 196,
        /// <summary>Warning: the rest factor of the implicit step could not be built; the body uses block-Jacobi preconditioning.</summary>
        RestFactorFailed = 197,
    }
}
