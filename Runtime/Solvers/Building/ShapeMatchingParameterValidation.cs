using System.Collections.Generic;
using Unity.Mathematics;
using static System.FormattableString;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Checks <see cref="ShapeMatchingParameters"/> for values the solver cannot use, with one issue per bad field.</summary>
    public static class ShapeMatchingParameterValidation
    {
        /// <summary>Fewest and most substeps per step.</summary>
        public const int MinSubsteps = 1, MaxSubsteps = ShapeMatchingParameters.MaxSubsteps;

        /// <summary>Largest plausible particle radius (m); a larger one is nearly always a unit mistake.</summary>
        public const float MaxParticleRadius = ParameterChecks.MaxParticleRadius;

        /// <summary>Appends an issue for every bad field (an error, or a warning for values that work but do less than they say); returns true when no error was added.</summary>
        public static bool Validate(in ShapeMatchingParameters p, List<ValidationIssue> issues)
        {
            int before = issues.Count;

            if ((uint)p.Mode > (uint)ShapeMatchingMode.Quadratic)
                Error(issues, ShapeMatchingIssueCode.ModeInvalid, Invariant($"Mode is {(int)p.Mode}, which is not Rigid, Linear or Quadratic."));

            if (Finite(issues, "Frequency", p.Frequency, "in Hz"))
            {
                if (p.Frequency < 0f || p.Frequency > ShapeMatchingParameters.MaxFrequency)
                    Error(issues, ShapeMatchingIssueCode.FrequencyOutOfRange, Invariant(
                        $"Frequency is {p.Frequency} Hz; it must be from 0 to {ShapeMatchingParameters.MaxFrequency} Hz (2 Hz = soft jelly, 20 Hz = firm rubber)."));
                else if (p.Frequency == 0f)
                    issues.Add(ValidationIssue.Warning(ShapeMatchingIssueCode.FrequencyZero, -1,
                        "Frequency is 0 Hz: the body will not hold its shape and collapses like loose particles. Use a value above 0 (2 Hz = soft jelly)."));
            }
            if (Finite(issues, "Beta", p.Beta, "in [0, 1]"))
            {
                if (p.Beta < 0f || p.Beta > 1f)
                    Error(issues, ShapeMatchingIssueCode.BetaOutOfRange, Invariant($"Beta is {p.Beta}; it must be in [0, 1] (0 = rigid goals, 1 = fully deformable)."));
                else if (p.Beta > ShapeMatchingParameters.MaxBeta && p.Mode != ShapeMatchingMode.Rigid)
                    issues.Add(ValidationIssue.Warning(ShapeMatchingIssueCode.BetaLimited, -1, Invariant(
                        $"Beta is {p.Beta}; it acts as {ShapeMatchingParameters.MaxBeta}: at 1 the shear and stretch the goals follow have no restoring force, and round-off would drift them without bound.")));
            }
            if (Finite(issues, "DampingRatio", p.DampingRatio, "of at least 0")
                && (p.DampingRatio < 0f || p.DampingRatio > ShapeMatchingParameters.MaxDampingRatio))
                Error(issues, ShapeMatchingIssueCode.DampingRatioOutOfRange, Invariant(
                    $"DampingRatio is {p.DampingRatio}; it must be from 0 to {ShapeMatchingParameters.MaxDampingRatio} (0 = undamped, 1 = critically damped; negative damping adds energy)."));
            if (Finite(issues, "MaxSubstepPhase", p.MaxSubstepPhase, "above 0 rad") && p.MaxSubstepPhase <= 0f)
                Error(issues, ShapeMatchingIssueCode.MaxSubstepPhaseNotPositive, Invariant(
                    $"MaxSubstepPhase is {p.MaxSubstepPhase} rad; it must be above 0 (default {ShapeMatchingParameters.Default.MaxSubstepPhase} rad)."));
            if (p.Body.Substeps < MinSubsteps || p.Body.Substeps > MaxSubsteps)
                Error(issues, ShapeMatchingIssueCode.SubstepsOutOfRange, Invariant($"Substeps is {p.Body.Substeps}; it must be from {MinSubsteps} to {MaxSubsteps}."));
            ParameterChecks.Contact(issues, p.Body.Acceleration, p.Body.MaxDepenetrationSpeed, ShapeMatchingParameters.Default.Body.MaxDepenetrationSpeed,
                p.Body.ParticleRadius, p.Body.Friction, p.Body.Restitution);
            Plasticity(issues, "Plasticity.Yield", p.Plasticity.Yield);
            Plasticity(issues, "Plasticity.Creep", p.Plasticity.Creep);
            Plasticity(issues, "Plasticity.MaxDeformation", p.Plasticity.MaxDeformation);
            if (p.Mode == ShapeMatchingMode.Rigid && p.Plasticity.Enabled)
                issues.Add(ValidationIssue.Warning(ShapeMatchingIssueCode.PlasticityIgnoredInRigidMode, -1,
                    "Plasticity is set, but the mode is Rigid: rigid goals cannot hold a dent, so the body stays elastic. Use Linear or Quadratic for plastic bodies."));
            ParameterChecks.Guard(issues, p.Body.SleepSpeed, p.Body.SleepDelay, p.Body.MaxSpeed, p.RotationIterations);

            return !ValidationIssue.AnyError(issues, before);
        }

        static void Plasticity(List<ValidationIssue> issues, string field, float value)
        {
            if (Finite(issues, field, value, "of at least 0") && value < 0f)
                Error(issues, ShapeMatchingIssueCode.PlasticityNegative, Invariant($"{field} is {value}; it must be at least 0 (all plasticity fields 0 = elastic)."));
        }

        static bool Finite(List<ValidationIssue> issues, string field, float value, string expected) =>
            ParameterChecks.Finite(issues, field, value, expected);

        static void Error(List<ValidationIssue> issues, IssueCode code, string message) => ParameterChecks.Error(issues, code, message);
    }
}
