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
        /// <summary>Substeps per step (1–256). Symplectic Euler needs h = dt/substeps below <see cref="FemStability.MaxStableStep(in FemModel, FemMaterialModel)"/>.</summary>
        public int Substeps;
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
        /// <summary>Uniform acceleration on every node: gravity plus any wind-like force per mass (m/s²).</summary>
        public float3 Acceleration;
        /// <summary>Largest speed (m/s) at which a node that starts a substep inside a collider is pushed out. Default 2 m/s.</summary>
        public float MaxDepenetrationSpeed;
        /// <summary>Node radius used against colliders (m).</summary>
        public float ParticleRadius;
        /// <summary>
        /// Coulomb friction coefficient against colliders (dimensionless). At 0 the implicit integrator holds its contact nodes
        /// in its solve (a pressed body settles at its equilibrium); with friction they are pushed out after the solve.
        /// </summary>
        public float Friction;
        /// <summary>Restitution e ∈ [0, 1] of node–collider contacts.</summary>
        public float Restitution;
        /// <summary>The body sleeps after its nodes' mass-weighted RMS speed stayed below this for <see cref="SleepDelay"/> (m/s). 0 = never sleeps.</summary>
        public float SleepSpeed;
        /// <summary>Time below <see cref="SleepSpeed"/> before sleeping (s).</summary>
        public float SleepDelay;
        /// <summary>Speed above which the state counts as absurd and the guard resets the body (m/s).</summary>
        public float MaxSpeed;
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
            p.Substeps = math.clamp(Substeps, 1, MaxSubsteps);
            p.Iterations = math.clamp(Iterations, 1, MaxIterations);
            p.CgIterations = math.clamp(CgIterations, 1, MaxCgIterations);
            p.NewtonIterations = math.clamp(NewtonIterations, 1, FemImplicitEuler.MaxNewtonIterations);
            p.CgTolerance = CgTolerance > 0f && math.isfinite(CgTolerance) ? CgTolerance : d.CgTolerance;
            p.DampingFrequency = DampingFrequency > 0f && math.isfinite(DampingFrequency) ? DampingFrequency : 0f;
            p.Acceleration = math.all(math.isfinite(Acceleration)) ? Acceleration : float3.zero;
            p.MaxDepenetrationSpeed = MaxDepenetrationSpeed > 0f && math.isfinite(MaxDepenetrationSpeed) ? MaxDepenetrationSpeed : d.MaxDepenetrationSpeed;
            p.ParticleRadius = math.isfinite(ParticleRadius) ? math.max(0f, ParticleRadius) : d.ParticleRadius;
            p.Friction = math.isfinite(Friction) ? math.max(0f, Friction) : d.Friction;
            p.Restitution = math.isnan(Restitution) ? d.Restitution : math.saturate(Restitution);
            p.SleepSpeed = math.isfinite(SleepSpeed) ? math.max(0f, SleepSpeed) : d.SleepSpeed;
            p.SleepDelay = math.isfinite(SleepDelay) ? math.max(0f, SleepDelay) : d.SleepDelay;
            p.MaxSpeed = MaxSpeed > 0f && math.isfinite(MaxSpeed) ? MaxSpeed : d.MaxSpeed;
            p.RotationIterations = math.clamp(RotationIterations, 1, 100);
            return p;
        }

        /// <summary>Co-rotational, implicit Euler, 2 substeps, CG 64 iterations at 1e-3, 1 Newton iteration, damping at the model's ω_ref, Earth gravity.</summary>
        public static FemParameters Default => new FemParameters
        {
            Model = FemMaterialModel.CoRotational,
            Integrator = FemIntegrator.ImplicitEuler,
            Substeps = 2,
            Iterations = 1,
            CgIterations = 64,
            NewtonIterations = 1,
            CgTolerance = 1e-3f,
            DampingFrequency = 0f,
            Acceleration = new float3(0f, -9.81f, 0f),
            MaxDepenetrationSpeed = 2f,
            ParticleRadius = 0.02f,
            Friction = 0.5f,
            Restitution = 0.1f,
            SleepSpeed = 0.02f,
            SleepDelay = 1f,
            MaxSpeed = 500f,
            RotationIterations = RotationExtraction.DefaultMaxIterations,
        };
    }
}
