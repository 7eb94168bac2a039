using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Per-body tunables of a mass-spring body (a component in ECS). Units are in each doc comment.</summary>
    public struct MassSpringParameters
    {
        /// <summary>Time integrator (<see cref="MassSpringIntegrator"/>). Default: symplectic Euler.</summary>
        public MassSpringIntegrator Integrator;
        /// <summary>
        /// Gravity, substeps, contacts, sleep and the guard, shared by every method. Substeps per step (1–256):
        /// h = dt / Substeps. The explicit integrators need h below <see cref="MassSpringStability.MaxStableStep"/>; XPBD gets
        /// stiffer and more accurate with more substeps.
        /// </summary>
        public ParticleBodySettings Body;
        /// <summary>XPBD constraint iterations per substep (1–64). Default 1: many small substeps beat many iterations (Macklin et al. 2019).</summary>
        public int Iterations;
        /// <summary>Implicit Euler: most conjugate-gradient iterations per substep (1–1000).</summary>
        public int CgIterations;
        /// <summary>Implicit Euler: CG stops when ‖r‖ ≤ tolerance · ‖b‖ (dimensionless, relative residual). Default 1e-4.</summary>
        public float CgTolerance;

        /// <summary>Most substeps per step.</summary>
        public const int MaxSubsteps = 256;
        /// <summary>Most XPBD iterations per substep.</summary>
        public const int MaxIterations = 64;
        /// <summary>Most CG iterations per substep.</summary>
        public const int MaxCgIterations = 1000;

        /// <summary>A copy the step can trust: NaN or out-of-range values replaced by the nearest valid value (or the default).</summary>
        public MassSpringParameters Sanitized()
        {
            var d = Default;
            var p = this;
            if ((uint)Integrator > (uint)MassSpringIntegrator.Xpbd)
                p.Integrator = d.Integrator;
            p.Body = Body.Sanitized(MaxSubsteps);
            p.Iterations = math.clamp(Iterations, 1, MaxIterations);
            p.CgIterations = math.clamp(CgIterations, 1, MaxCgIterations);
            p.CgTolerance = CgTolerance >= 0f && math.isfinite(CgTolerance) ? CgTolerance : d.CgTolerance;
            return p;
        }

        /// <summary>Symplectic Euler, 8 substeps, 1 XPBD iteration, 50 CG iterations at 1e-4, Earth gravity, the shape-matching contact and sleep defaults.</summary>
        public static MassSpringParameters Default => new MassSpringParameters
        {
            Integrator = MassSpringIntegrator.SymplecticEuler,
            Body = ParticleBodySettings.Default(8),
            Iterations = 1,
            CgIterations = 50,
            CgTolerance = 1e-4f,
        };
    }
}
