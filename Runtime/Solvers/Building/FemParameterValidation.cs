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
            ParameterChecks.Count(issues, SoftBodyIssueCode.FemIterationsOutOfRange, "Substeps", p.Body.Substeps, FemParameters.MaxSubsteps, "substeps per step");
            ParameterChecks.Count(issues, SoftBodyIssueCode.FemIterationsOutOfRange, "Iterations", p.Iterations, FemParameters.MaxIterations, "XPBD iterations per substep");
            ParameterChecks.Count(issues, SoftBodyIssueCode.FemIterationsOutOfRange, "CgIterations", p.CgIterations, FemParameters.MaxCgIterations,
                "conjugate-gradient iterations per substep");
            ParameterChecks.Count(issues, SoftBodyIssueCode.FemIterationsOutOfRange, "NewtonIterations", p.NewtonIterations, FemImplicitEuler.MaxNewtonIterations,
                "Newton iterations per substep");
            ParameterChecks.CgTolerance(issues, SoftBodyIssueCode.FemCgToleranceInvalid, p.CgTolerance, FemParameters.Default.CgTolerance, false);
            if (ParameterChecks.Finite(issues, "DampingFrequency", p.DampingFrequency, "of at least 0 rad/s") && p.DampingFrequency < 0f)
                ParameterChecks.Error(issues, SoftBodyIssueCode.FemDampingFrequencyInvalid, Invariant(
                    $"DampingFrequency is {p.DampingFrequency} rad/s; it must be at least 0 (0 = the model's own estimate)."));
            ParameterChecks.Contact(issues, p.Body.Acceleration, p.Body.MaxDepenetrationSpeed, FemParameters.Default.Body.MaxDepenetrationSpeed,
                p.Body.ParticleRadius, p.Body.Friction, p.Body.Restitution);
            ParameterChecks.Guard(issues, p.Body.SleepSpeed, p.Body.SleepDelay, p.Body.MaxSpeed, p.RotationIterations);
            return !SoftBodyIssue.AnyError(issues, before);
        }

        /// <summary>Appends an error for a bad element order or rest-factor substep; returns true when none was added.</summary>
        public static bool Validate(in FemBuildSettings s, List<SoftBodyIssue> issues)
        {
            int before = issues.Count;
            if (s.Order != FemElementOrder.Linear && s.Order != FemElementOrder.Quadratic)
                ParameterChecks.Error(issues, SoftBodyIssueCode.FemElementOrderInvalid, Invariant($"Element order is {(int)s.Order}, which is not Linear or Quadratic."));
            if (s.RestFactor && !(s.Substep > 0f && s.Substep < float.PositiveInfinity))
                ParameterChecks.Error(issues, SoftBodyIssueCode.FemIterationsOutOfRange, Invariant(
                    $"The rest factor's substep is {s.Substep} s; it must be a finite time above 0 (the fixed step over the substeps)."));
            return !SoftBodyIssue.AnyError(issues, before);
        }
    }
}
