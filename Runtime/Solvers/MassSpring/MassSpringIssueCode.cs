namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Problems of a mass-spring network, its material and its parameters (<see cref="MassSpringNetwork"/>, <see cref="MassSpringCalibration"/>, <see cref="MassSpringStability"/>, <see cref="MassSpringParameterValidation"/>).
    /// The numbers are unique across domains and stable (they may be stored); new codes take new numbers. An
    /// <see cref="IssueCode"/> carries any domain's code.
    /// </summary>
    public enum MassSpringIssueCode
    {
        /// <summary>The tetrahedral mesh has no nodes or no tetrahedra.</summary>
        EmptyMesh = 120,
        /// <summary>A tetrahedron refers to a node that does not exist. Index: the first such tetrahedron.</summary>
        TetrahedronIndexOutOfRange = 121,
        /// <summary>A node position is NaN or infinite. Index: the first such node.</summary>
        NonFiniteNode = 122,
        /// <summary>
        /// Warning: an edge has zero rest length (a tetrahedron repeats a node, or two nodes coincide). Its spring is
        /// left out: it has no direction to act along. Index: the first such tetrahedron.
        /// </summary>
        ZeroLengthEdge = 123,
        /// <summary>
        /// Warning: a tetrahedron appears twice (the same four nodes, e.g. doubled back-to-back geometry). The copy is
        /// merged: its edges and volume count once. Index: the first copy.
        /// </summary>
        DuplicateTetrahedron = 124,
        /// <summary>Warning: a tetrahedron has zero volume; it adds no stiffness or mass. Index: the first such tetrahedron.</summary>
        DegenerateTetrahedron = 125,
        /// <summary>Warning: a node belongs to no tetrahedron: it gets no spring and the mean mass, and falls freely. Index: the first such node.</summary>
        IsolatedNode = 126,
        /// <summary>No spring is left after the zero-length edges were removed.</summary>
        NoSprings = 127,
        /// <summary>The material is invalid (E ≤ 0, ν outside [0, 0.5), ρ ≤ 0 or ζ &lt; 0, or not finite).</summary>
        MaterialInvalid = 128,
        /// <summary>
        /// Warning: the springs are too stiff for the substep of an explicit integrator (symplectic Euler, Verlet):
        /// h exceeds <see cref="MassSpringStability.MaxStableStep"/> and the body would blow up (the guard resets it).
        /// Use more substeps, softer springs, or the ImplicitEuler or Xpbd integrator.
        /// </summary>
        StepAboveStableLimit = 129,
        /// <summary>The mass-spring integrator is not one of the defined values.</summary>
        IntegratorInvalid = 130,
        /// <summary>Mass-spring substeps (1–256), XPBD iterations (1–64) or CG iterations (1–1000) out of range.</summary>
        IterationsOutOfRange = 131,
        /// <summary>The mass-spring conjugate-gradient tolerance is not a finite relative residual above 0 and below 1.</summary>
        CgToleranceInvalid = 132,
    }
}
