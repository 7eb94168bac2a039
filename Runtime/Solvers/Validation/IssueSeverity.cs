namespace SoftBodyDynamics.Solvers
{
    /// <summary>How serious a <see cref="ValidationIssue"/> is.</summary>
    public enum IssueSeverity : byte
    {
        /// <summary>The body or fluid is built, but something in the input is suspicious or an optional step was skipped.</summary>
        Warning = 0,
        /// <summary>The body or fluid cannot be built (or simulated) from this input.</summary>
        Error = 1,
    }
}
