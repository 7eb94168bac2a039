using System.Collections.Generic;
using Unity.Mathematics;
using static System.FormattableString;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>The checks every particle body's parameters share (contact, guard, sleep), one message per bad field, for every method's validator.</summary>
    static class ParameterChecks
    {
        /// <summary>Largest plausible particle radius (m); a larger one is nearly always a unit mistake.</summary>
        public const float MaxParticleRadius = 100f;

        /// <summary>Adds a <see cref="ParticleBodyIssueCode.ParameterNotFinite"/> error and returns false when <paramref name="value"/> is NaN or infinite.</summary>
        public static bool Finite(List<ValidationIssue> issues, string field, float value, string expected)
        {
            if (math.isfinite(value))
                return true;
            string kind = math.isnan(value) ? "NaN" : "infinite";
            Error(issues, ParticleBodyIssueCode.ParameterNotFinite, Invariant($"{field} is {kind}; set a finite value {expected}."));
            return false;
        }

        public static void Error(List<ValidationIssue> issues, IssueCode code, string message) =>
            issues.Add(ValidationIssue.Error(code, -1, message));

        /// <summary>Acceleration, depenetration speed, particle radius, friction and restitution.</summary>
        public static void Contact(List<ValidationIssue> issues, float3 acceleration, float maxDepenetrationSpeed, float defaultDepenetrationSpeed,
            float particleRadius, float friction, float restitution)
        {
            if (Finite(issues, "MaxDepenetrationSpeed", maxDepenetrationSpeed, "above 0 m/s") && maxDepenetrationSpeed <= 0f)
                Error(issues, ParticleBodyIssueCode.MaxDepenetrationSpeedNotPositive, Invariant(
                    $"MaxDepenetrationSpeed is {maxDepenetrationSpeed} m/s; it must be above 0 (default {defaultDepenetrationSpeed} m/s), or a body inside a collider never leaves it."));
            Finite(issues, "Acceleration.x", acceleration.x, "in m/s²");
            Finite(issues, "Acceleration.y", acceleration.y, "in m/s²");
            Finite(issues, "Acceleration.z", acceleration.z, "in m/s²");
            if (Finite(issues, "ParticleRadius", particleRadius, "in m") && (particleRadius <= 0f || particleRadius > MaxParticleRadius))
                Error(issues, ParticleBodyIssueCode.ParticleRadiusInvalid, Invariant(
                    $"ParticleRadius is {particleRadius} m; it must be above 0 m and at most {MaxParticleRadius} m (check the units: metres)."));
            if (Finite(issues, "Friction", friction, "of at least 0") && friction < 0f)
                Error(issues, ParticleBodyIssueCode.FrictionNegative, Invariant($"Friction is {friction}; it must be at least 0 (0 = ice, 1 = rubber on concrete)."));
            if (Finite(issues, "Restitution", restitution, "in [0, 1]") && (restitution < 0f || restitution > 1f))
                Error(issues, ParticleBodyIssueCode.RestitutionOutOfRange, Invariant($"Restitution is {restitution}; it must be in [0, 1] (0 = no bounce)."));
        }

        /// <summary>Counts from 1 to <paramref name="max"/>: an error of <paramref name="code"/> naming the field otherwise.</summary>
        public static void Count(List<ValidationIssue> issues, IssueCode code, string field, int value, int max, string what)
        {
            if (value < 1 || value > max)
                Error(issues, code, Invariant($"{field} is {value}; it must be from 1 to {max} {what}."));
        }

        /// <summary>A conjugate-gradient tolerance: a finite relative residual below 1, above 0 (or 0 itself where the solver takes 0 as "every iteration").</summary>
        public static void CgTolerance(List<ValidationIssue> issues, IssueCode code, float tolerance, float defaultTolerance, bool zeroRunsEveryIteration)
        {
            bool low = zeroRunsEveryIteration ? tolerance >= 0f : tolerance > 0f;
            if (Finite(issues, "CgTolerance", tolerance, "below 1") && !(low && tolerance < 1f))
                Error(issues, code, Invariant($"CgTolerance is {tolerance}; it must be a relative residual ") +
                    (zeroRunsEveryIteration ? "from 0 (every iteration runs)" : "above 0") + Invariant($" and below 1 (default {defaultTolerance})."));
        }

        /// <summary>Sleep speed and delay, the guard's speed limit, and the rotation-extraction iterations (none: a method without rotations).</summary>
        public static void Guard(List<ValidationIssue> issues, float sleepSpeed, float sleepDelay, float maxSpeed, int? rotationIterations)
        {
            if (Finite(issues, "SleepSpeed", sleepSpeed, "of at least 0 m/s") && sleepSpeed < 0f)
                Error(issues, ParticleBodyIssueCode.SleepSpeedNegative, Invariant($"SleepSpeed is {sleepSpeed} m/s; it must be at least 0 (0 = never sleeps)."));
            if (Finite(issues, "SleepDelay", sleepDelay, "of at least 0 s") && sleepDelay < 0f)
                Error(issues, ParticleBodyIssueCode.SleepDelayNegative, Invariant($"SleepDelay is {sleepDelay} s; it must be at least 0 s."));
            if (Finite(issues, "MaxSpeed", maxSpeed, "above 0 m/s") && maxSpeed <= 0f)
                Error(issues, ParticleBodyIssueCode.MaxSpeedNotPositive, Invariant($"MaxSpeed is {maxSpeed} m/s; it must be above 0 (for example 500 m/s), or every step resets the body."));
            if (rotationIterations.HasValue && rotationIterations.Value < 1)
                Error(issues, ParticleBodyIssueCode.RotationIterationsInvalid, Invariant(
                    $"RotationIterations is {rotationIterations}; it must be at least 1 (default {RotationExtraction.DefaultMaxIterations})."));
        }
    }
}
