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
        public static bool Validate(in FemParameters p, List<ValidationIssue> issues)
        {
            int before = issues.Count;
            if ((uint)p.Model > (uint)FemMaterialModel.NeoHookean)
                ParameterChecks.Error(issues, FemIssueCode.ModelInvalid, Invariant($"Model is {(int)p.Model}, which is not Co-Rotational or Neo-Hookean."));
            if ((uint)p.Integrator > (uint)FemIntegrator.Xpbd)
                ParameterChecks.Error(issues, FemIssueCode.ModelInvalid, Invariant($"Integrator is {(int)p.Integrator}, which is not Symplectic Euler, Implicit Euler or XPBD."));
            ParameterChecks.Count(issues, FemIssueCode.IterationsOutOfRange, "Substeps", p.Body.Substeps, FemParameters.MaxSubsteps, "substeps per step");
            ParameterChecks.Count(issues, FemIssueCode.IterationsOutOfRange, "Iterations", p.Iterations, FemParameters.MaxIterations, "XPBD iterations per substep");
            ParameterChecks.Count(issues, FemIssueCode.IterationsOutOfRange, "CgIterations", p.CgIterations, FemParameters.MaxCgIterations,
                "conjugate-gradient iterations per substep");
            ParameterChecks.Count(issues, FemIssueCode.IterationsOutOfRange, "NewtonIterations", p.NewtonIterations, FemImplicitEuler.MaxNewtonIterations,
                "Newton iterations per substep");
            ParameterChecks.CgTolerance(issues, FemIssueCode.CgToleranceInvalid, p.CgTolerance, FemParameters.Default.CgTolerance, false);
            if (ParameterChecks.Finite(issues, "DampingFrequency", p.DampingFrequency, "of at least 0 rad/s") && p.DampingFrequency < 0f)
                ParameterChecks.Error(issues, FemIssueCode.DampingFrequencyInvalid, Invariant(
                    $"DampingFrequency is {p.DampingFrequency} rad/s; it must be at least 0 (0 = the model's own estimate)."));
            ParameterChecks.Contact(issues, p.Body.Acceleration, p.Body.MaxDepenetrationSpeed, FemParameters.Default.Body.MaxDepenetrationSpeed,
                p.Body.ParticleRadius, p.Body.Friction, p.Body.Restitution);
            ParameterChecks.Guard(issues, p.Body.SleepSpeed, p.Body.SleepDelay, p.Body.MaxSpeed, p.RotationIterations);
            return !ValidationIssue.AnyError(issues, before);
        }

        /// <summary>Appends an error for a bad element order or rest-factor substep; returns true when none was added.</summary>
        public static bool Validate(in FemBuildSettings s, List<ValidationIssue> issues)
        {
            int before = issues.Count;
            if (s.Order != FemElementOrder.Linear && s.Order != FemElementOrder.Quadratic)
                ParameterChecks.Error(issues, FemIssueCode.ElementOrderInvalid, Invariant($"Element order is {(int)s.Order}, which is not Linear or Quadratic."));
            if (s.RestFactor && !(s.Substep > 0f && s.Substep < float.PositiveInfinity))
                ParameterChecks.Error(issues, FemIssueCode.IterationsOutOfRange, Invariant(
                    $"The rest factor's substep is {s.Substep} s; it must be a finite time above 0 (the fixed step over the substeps)."));
            return !ValidationIssue.AnyError(issues, before);
        }
    }
}
