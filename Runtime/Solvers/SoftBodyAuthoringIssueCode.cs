namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Problems of a soft body's authoring that belong to no single method (<c>SoftBodyAuthoringValidation</c>).
    /// The numbers are unique across domains and stable (they may be stored); new codes take new numbers. An
    /// <see cref="IssueCode"/> carries any domain's code.
    /// </summary>
    public enum SoftBodyAuthoringIssueCode
    {
        /// <summary>The authoring component's method is not one of Shape Matching, Mass Spring or FEM.</summary>
        MethodInvalid = 190,
    }
}
