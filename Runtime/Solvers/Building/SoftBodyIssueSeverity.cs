namespace SoftBodyDynamics.Solvers
{
    /// <summary>How serious a <see cref="SoftBodyIssue"/> is.</summary>
    public enum SoftBodyIssueSeverity : byte
    {
        /// <summary>The body is built, but something in the input is suspicious or an optional step was skipped.</summary>
        Warning = 0,
        /// <summary>The body cannot be built (or simulated) from this input.</summary>
        Error = 1,
    }
}
