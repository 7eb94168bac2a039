using System.Collections.Generic;
using static System.FormattableString;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Checks <see cref="MassSpringParameters"/> for values the solver cannot use, one issue per bad field, by the rule every
    /// method follows: the fields it shares with the other particle bodies get the same codes and messages (<see cref="ParameterChecks"/>).
    /// </summary>
    public static class MassSpringParameterValidation
    {
        /// <summary>Appends an error for every bad field; returns true when none was added.</summary>
        public static bool Validate(in MassSpringParameters p, List<ValidationIssue> issues)
        {
            int before = issues.Count;
            if ((uint)p.Integrator > (uint)MassSpringIntegrator.Xpbd)
                ParameterChecks.Error(issues, MassSpringIssueCode.IntegratorInvalid,
                    Invariant($"Integrator is {(int)p.Integrator}, which is not Symplectic Euler, Verlet, Implicit Euler or XPBD."));
            ParameterChecks.Count(issues, MassSpringIssueCode.IterationsOutOfRange, "Substeps", p.Body.Substeps, MassSpringParameters.MaxSubsteps, "substeps per step");
            ParameterChecks.Count(issues, MassSpringIssueCode.IterationsOutOfRange, "Iterations", p.Iterations, MassSpringParameters.MaxIterations,
                "XPBD iterations per substep");
            ParameterChecks.Count(issues, MassSpringIssueCode.IterationsOutOfRange, "CgIterations", p.CgIterations, MassSpringParameters.MaxCgIterations,
                "conjugate-gradient iterations per substep");
            ParameterChecks.CgTolerance(issues, MassSpringIssueCode.CgToleranceInvalid, p.CgTolerance, MassSpringParameters.Default.CgTolerance, true);
            ParameterChecks.Contact(issues, p.Body.Acceleration, p.Body.MaxDepenetrationSpeed, MassSpringParameters.Default.Body.MaxDepenetrationSpeed,
                p.Body.ParticleRadius, p.Body.Friction, p.Body.Restitution);
            ParameterChecks.Guard(issues, p.Body.SleepSpeed, p.Body.SleepDelay, p.Body.MaxSpeed, null);
            return !ValidationIssue.AnyError(issues, before);
        }
    }
}
