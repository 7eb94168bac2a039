using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>How bakers report validation issues: each one logged with the authoring object as context.</summary>
    static class BakeIssueLog
    {
        /// <summary>
        /// Logs every issue as "<paramref name="label"/> on 'name': message" (errors end with "<paramref name="notBaked"/>")
        /// and returns true when any is an error, in which case the caller bakes nothing.
        /// </summary>
        public static bool Report(List<ValidationIssue> issues, string label, Object context, string notBaked)
        {
            foreach (ValidationIssue issue in issues)
            {
                string message = $"{label} on '{context.name}': {issue.Message}";
                if (issue.Severity == IssueSeverity.Error)
                    Debug.LogError(message + " " + notBaked, context);
                else
                    Debug.LogWarning(message, context);
            }
            return ValidationIssue.AnyError(issues);
        }
    }
}
