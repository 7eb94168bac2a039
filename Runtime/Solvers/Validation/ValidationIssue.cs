using System.Collections.Generic;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One problem a validator found in a body's or a fluid's input (mesh, build settings, parameters, collider, tap):
    /// what (<see cref="Code"/>, its domain's enum), how bad (<see cref="Severity"/>), where (<see cref="Index"/>) and
    /// what to do about it (<see cref="Message"/>).
    /// </summary>
    public struct ValidationIssue
    {
        /// <summary>What is wrong.</summary>
        public IssueCode Code;
        /// <summary>Error (the body or fluid is not built) or warning.</summary>
        public IssueSeverity Severity;
        /// <summary>The vertex or triangle index the issue is about (named in <see cref="Message"/>), or −1.</summary>
        public int Index;
        /// <summary>A specific, actionable sentence for the user.</summary>
        public string Message;

        public ValidationIssue(IssueCode code, IssueSeverity severity, int index, string message)
        {
            Code = code;
            Severity = severity;
            Index = index;
            Message = message;
        }

        /// <summary>An error about <paramref name="index"/> (−1 when it concerns no single element).</summary>
        public static ValidationIssue Error(IssueCode code, int index, string message) =>
            new ValidationIssue(code, IssueSeverity.Error, index, message);

        /// <summary>A warning about <paramref name="index"/> (−1 when it concerns no single element).</summary>
        public static ValidationIssue Warning(IssueCode code, int index, string message) =>
            new ValidationIssue(code, IssueSeverity.Warning, index, message);

        /// <summary>True when any issue in <paramref name="issues"/> from index <paramref name="start"/> on is an error.</summary>
        public static bool AnyError(List<ValidationIssue> issues, int start = 0)
        {
            for (int i = start; i < issues.Count; i++)
                if (issues[i].Severity == IssueSeverity.Error)
                    return true;
            return false;
        }

        public override string ToString() => $"{Severity} {Code}: {Message}";
    }
}
