using System.Collections.Generic;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One problem found in a soft body's mesh, build settings or parameters: what (<see cref="Code"/>),
    /// how bad (<see cref="Severity"/>), where (<see cref="Index"/>) and what to do about it (<see cref="Message"/>).
    /// </summary>
    public struct SoftBodyIssue
    {
        /// <summary>What is wrong.</summary>
        public SoftBodyIssueCode Code;
        /// <summary>Error (the body is not built) or warning.</summary>
        public SoftBodyIssueSeverity Severity;
        /// <summary>The vertex or triangle index the issue is about (named in <see cref="Message"/>), or −1.</summary>
        public int Index;
        /// <summary>A specific, actionable sentence for the user.</summary>
        public string Message;

        public SoftBodyIssue(SoftBodyIssueCode code, SoftBodyIssueSeverity severity, int index, string message)
        {
            Code = code;
            Severity = severity;
            Index = index;
            Message = message;
        }

        /// <summary>An error about <paramref name="index"/> (−1 when it concerns no single element).</summary>
        public static SoftBodyIssue Error(SoftBodyIssueCode code, int index, string message) =>
            new SoftBodyIssue(code, SoftBodyIssueSeverity.Error, index, message);

        /// <summary>A warning about <paramref name="index"/> (−1 when it concerns no single element).</summary>
        public static SoftBodyIssue Warning(SoftBodyIssueCode code, int index, string message) =>
            new SoftBodyIssue(code, SoftBodyIssueSeverity.Warning, index, message);

        /// <summary>True when any issue in <paramref name="issues"/> from index <paramref name="start"/> on is an error.</summary>
        public static bool AnyError(List<SoftBodyIssue> issues, int start = 0)
        {
            for (int i = start; i < issues.Count; i++)
                if (issues[i].Severity == SoftBodyIssueSeverity.Error)
                    return true;
            return false;
        }

        public override string ToString() => $"{Severity} {Code}: {Message}";
    }
}
