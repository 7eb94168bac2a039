using System.Collections.Generic;
using static System.FormattableString;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Checks <see cref="FemParameters"/> for values the solver cannot use, one issue per bad field, by the rule every method
    /// follows: the fields it shares with the other particle bodies get the same codes and messages (<see cref="ParameterChecks"/>).
    /// </summary>
    public static class FemParameterValidation
    {
        /// <summary>Appends an error for every bad field; returns true when none was added.</summary>
        public static bool Validate(in FemParameters p, List<SoftBodyIssue> issues)
        {
            int before = issues.Count;
            if ((uint)p.Model > (uint)FemMaterialModel.NeoHookean)
                ParameterChecks.Error(issues, SoftBodyIssueCode.FemModelInvalid, Invariant($"Model is {(int)p.Model}, which is not Co-Rotational or Neo-Hookean."));
            if ((uint)p.Integrator > (uint)FemIntegrator.Xpbd)
                ParameterChecks.Error(issues, SoftBodyIssueCode.FemModelInvalid, Invariant($"Integrator is {(int)p.Integrator}, which is not Symplectic Euler, Implicit Euler or XPBD."));
            Range(issues, "Substeps", p.Substeps, FemParameters.MaxSubsteps, "substeps per step");
            Range(issues, "Iterations", p.Iterations, FemParameters.MaxIterations, "XPBD iterations per substep");
            Range(issues, "CgIterations", p.CgIterations, FemParameters.MaxCgIterations, "conjugate-gradient iterations per substep");
            Range(issues, "NewtonIterations", p.NewtonIterations, FemImplicitEuler.MaxNewtonIterations, "Newton iterations per substep");
            if (ParameterChecks.Finite(issues, "CgTolerance", p.CgTolerance, "in (0, 1)") && !(p.CgTolerance > 0f && p.CgTolerance < 1f))
                ParameterChecks.Error(issues, SoftBodyIssueCode.FemCgToleranceInvalid, Invariant(
                    $"CgTolerance is {p.CgTolerance}; it must be a relative residual above 0 and below 1 (default {FemParameters.Default.CgTolerance})."));
            if (ParameterChecks.Finite(issues, "DampingFrequency", p.DampingFrequency, "of at least 0 rad/s") && p.DampingFrequency < 0f)
                ParameterChecks.Error(issues, SoftBodyIssueCode.FemDampingFrequencyInvalid, Invariant(
                    $"DampingFrequency is {p.DampingFrequency} rad/s; it must be at least 0 (0 = the model's own estimate)."));
            ParameterChecks.Contact(issues, p.Acceleration, p.MaxDepenetrationSpeed, FemParameters.Default.MaxDepenetrationSpeed,
                p.ParticleRadius, p.Friction, p.Restitution);
            ParameterChecks.Guard(issues, p.SleepSpeed, p.SleepDelay, p.MaxSpeed, p.RotationIterations);
            return !SoftBodyIssue.AnyError(issues, before);
        }

        static void Range(List<SoftBodyIssue> issues, string field, int value, int max, string what)
        {
            if (value < 1 || value > max)
                ParameterChecks.Error(issues, SoftBodyIssueCode.FemIterationsOutOfRange, Invariant($"{field} is {value}; it must be from 1 to {max} {what}."));
        }
    }
}
