using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Per-body tunables of a finite-element body (a component in ECS). Units are in each doc comment.</summary>
    public struct FemParameters
    {
        /// <summary>Constitutive model: co-rotational linear or stable Neo-Hookean.</summary>
        public FemMaterialModel Model;
        /// <summary>Time integrator. The unsupported pair (co-rotational + XPBD) falls back to symplectic Euler and is reported.</summary>
        public FemIntegrator Integrator;
        /// <summary>
        /// Gravity, substeps, contacts, sleep and the guard, shared by every method. Substeps per step (1–256): symplectic Euler
        /// needs h = dt/substeps below <see cref="FemStability.MaxStableStep(in FemModel, FemMaterialModel)"/>.
        /// </summary>
        public ParticleBodySettings Body;
        /// <summary>XPBD constraint iterations per substep (1–64). 1 with many small substeps is the recommended use.</summary>
        public int Iterations;
        /// <summary>Most conjugate-gradient iterations per implicit substep (1–10000).</summary>
        public int CgIterations;
        /// <summary>
        /// Newton iterations per implicit substep of the Neo-Hookean model (1–16). 1 = one linearly implicit solve (like the
        /// co-rotational model); more iterations converge toward the nonlinear backward-Euler step, at one CG solve each.
        /// </summary>
        public int NewtonIterations;
        /// <summary>Relative residual ‖r‖/‖b‖ at which conjugate gradients stop (dimensionless, &gt; 0). Default 1e-3.</summary>
        public float CgTolerance;
        /// <summary>
        /// Reference frequency ω_ref (rad/s) of the Rayleigh damping C = β K, β = 2ζ/ω_ref (ζ the material's damping
        /// ratio): the mode at ω_ref has damping ratio ζ, faster modes more. 0 = the model's estimate π √(μ/ρ) / L.
        /// </summary>
        public float DampingFrequency;
        /// <summary>Rotation-extraction iterations per element and substep (co-rotational; warm-started).</summary>
        public int RotationIterations;

        /// <summary>Most substeps per step.</summary>
        public const int MaxSubsteps = 256;
        /// <summary>Most XPBD iterations per substep.</summary>
        public const int MaxIterations = 64;
        /// <summary>Most conjugate-gradient iterations per substep.</summary>
        public const int MaxCgIterations = 10000;

        /// <summary>A copy the step can trust: NaN or out-of-range values replaced by the nearest valid value or the default.</summary>
        public FemParameters Sanitized()
        {
            var d = Default;
            var p = this;
            if ((uint)Model > (uint)FemMaterialModel.NeoHookean)
                p.Model = d.Model;
            if ((uint)Integrator > (uint)FemIntegrator.Xpbd)
                p.Integrator = d.Integrator;
            p.Body = Body.Sanitized(MaxSubsteps);
            p.Iterations = math.clamp(Iterations, 1, MaxIterations);
            p.CgIterations = math.clamp(CgIterations, 1, MaxCgIterations);
            p.NewtonIterations = math.clamp(NewtonIterations, 1, FemImplicitEuler.MaxNewtonIterations);
            p.CgTolerance = CgTolerance > 0f && math.isfinite(CgTolerance) ? CgTolerance : d.CgTolerance;
            p.DampingFrequency = DampingFrequency > 0f && math.isfinite(DampingFrequency) ? DampingFrequency : 0f;
            p.RotationIterations = math.clamp(RotationIterations, 1, 100);
            return p;
        }

        /// <summary>Co-rotational, implicit Euler, 2 substeps, CG 64 iterations at 1e-3, 1 Newton iteration, damping at the model's ω_ref, Earth gravity.</summary>
        public static FemParameters Default => new FemParameters
        {
            Model = FemMaterialModel.CoRotational,
            Integrator = FemIntegrator.ImplicitEuler,
            Body = ParticleBodySettings.Default(2),
            Iterations = 1,
            CgIterations = 64,
            NewtonIterations = 1,
            CgTolerance = 1e-3f,
            DampingFrequency = 0f,
            RotationIterations = RotationExtraction.DefaultMaxIterations,
        };
    }
}
