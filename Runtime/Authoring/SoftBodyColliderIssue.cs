using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>What can be wrong with an authored soft-body collider. The values are stable; new codes take new numbers.</summary>
    public enum SoftBodyColliderIssueCode
    {
        /// <summary>The shape is not one of plane, sphere, box or capsule.</summary>
        ShapeInvalid = 1,
        /// <summary>A size, radius, height or the centre is NaN or infinite.</summary>
        SizeNotFinite = 2,
        /// <summary>A box size or a radius is zero or negative, or a capsule height is negative.</summary>
        SizeNotPositive = 3,
        /// <summary>The transform's position, rotation or scale is NaN or infinite.</summary>
        TransformNotFinite = 4,
        /// <summary>A scale factor the shape depends on is zero: the collider would have no volume.</summary>
        ScaleZero = 5,
        /// <summary>Warning: a sphere (or a capsule across its axis) is scaled non-uniformly; the largest factor is used.</summary>
        NonUniformScale = 6,
        /// <summary>Warning: a capsule's height is less than its diameter, so it is a sphere.</summary>
        CapsuleShorterThanDiameter = 7,
    }

    /// <summary>One problem with an authored collider: what, how bad, and a sentence saying what to do.</summary>
    public struct SoftBodyColliderIssue
    {
        public SoftBodyColliderIssueCode Code;
        public SoftBodyIssueSeverity Severity;
        public string Message;

        public SoftBodyColliderIssue(SoftBodyColliderIssueCode code, SoftBodyIssueSeverity severity, string message)
        {
            Code = code;
            Severity = severity;
            Message = message;
        }

        /// <summary>True when any issue in <paramref name="issues"/> is an error.</summary>
        public static bool AnyError(List<SoftBodyColliderIssue> issues)
        {
            foreach (SoftBodyColliderIssue issue in issues)
                if (issue.Severity == SoftBodyIssueSeverity.Error)
                    return true;
            return false;
        }

        public override string ToString() => $"{Severity} {Code}: {Message}";
    }
}
