using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Per-body tunables of a mass-spring body (a component in ECS). Units are in each doc comment.</summary>
    public struct MassSpringParameters
    {
        /// <summary>Time integrator (<see cref="MassSpringIntegrator"/>). Default: symplectic Euler.</summary>
        public MassSpringIntegrator Integrator;
        /// <summary>
        /// Substeps per step (1–256): h = dt / Substeps. The explicit integrators need h below
        /// <see cref="MassSpringStability.MaxStableStep"/>; XPBD gets stiffer and more accurate with more substeps.
        /// </summary>
        public int Substeps;
        /// <summary>XPBD constraint iterations per substep (1–64). Default 1: many small substeps beat many iterations (Macklin et al. 2019).</summary>
        public int Iterations;
        /// <summary>Implicit Euler: most conjugate-gradient iterations per substep (1–1000).</summary>
        public int CgIterations;
        /// <summary>Implicit Euler: CG stops when ‖r‖ ≤ tolerance · ‖b‖ (dimensionless, relative residual). Default 1e-4.</summary>
        public float CgTolerance;
        /// <summary>Uniform acceleration on every particle: gravity plus any wind-like force per mass (m/s²).</summary>
        public float3 Acceleration;
        /// <summary>Largest speed (m/s) at which a particle that starts a substep inside a collider is pushed out. Default 2 m/s.</summary>
        public float MaxDepenetrationSpeed;
        /// <summary>Particle radius used against colliders (m).</summary>
        public float ParticleRadius;
        /// <summary>Coulomb friction coefficient μ against colliders (0 = ice, 1 = rubber on concrete).</summary>
        public float Friction;
        /// <summary>Restitution e ∈ [0, 1] of particle–collider contacts (0 = no bounce).</summary>
        public float Restitution;
        /// <summary>The body sleeps after its mass-weighted RMS speed stayed below this for <see cref="SleepDelay"/> (m/s). 0 = never sleeps.</summary>
        public float SleepSpeed;
        /// <summary>Time below <see cref="SleepSpeed"/> before sleeping (s).</summary>
        public float SleepDelay;
        /// <summary>Speed above which the state counts as absurd and the guard resets the body (m/s). An explicit integrator past its stable step trips it.</summary>
        public float MaxSpeed;

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
            p.Substeps = math.clamp(Substeps, 1, MaxSubsteps);
            p.Iterations = math.clamp(Iterations, 1, MaxIterations);
            p.CgIterations = math.clamp(CgIterations, 1, MaxCgIterations);
            p.CgTolerance = CgTolerance >= 0f && math.isfinite(CgTolerance) ? CgTolerance : d.CgTolerance;
            p.Acceleration = math.all(math.isfinite(Acceleration)) ? Acceleration : float3.zero;
            p.MaxDepenetrationSpeed = MaxDepenetrationSpeed > 0f && math.isfinite(MaxDepenetrationSpeed) ? MaxDepenetrationSpeed : d.MaxDepenetrationSpeed;
            p.ParticleRadius = math.isfinite(ParticleRadius) ? math.max(0f, ParticleRadius) : d.ParticleRadius;
            p.Friction = math.isfinite(Friction) ? math.max(0f, Friction) : d.Friction;
            p.Restitution = math.isnan(Restitution) ? d.Restitution : math.saturate(Restitution);
            p.SleepSpeed = math.isfinite(SleepSpeed) ? math.max(0f, SleepSpeed) : d.SleepSpeed;
            p.SleepDelay = math.isfinite(SleepDelay) ? math.max(0f, SleepDelay) : d.SleepDelay;
            p.MaxSpeed = MaxSpeed > 0f && math.isfinite(MaxSpeed) ? MaxSpeed : d.MaxSpeed;
            return p;
        }

        /// <summary>Symplectic Euler, 8 substeps, 1 XPBD iteration, 50 CG iterations at 1e-4, Earth gravity, the shape-matching contact and sleep defaults.</summary>
        public static MassSpringParameters Default => new MassSpringParameters
        {
            Integrator = MassSpringIntegrator.SymplecticEuler,
            Substeps = 8,
            Iterations = 1,
            CgIterations = 50,
            CgTolerance = 1e-4f,
            Acceleration = new float3(0f, -9.81f, 0f),
            MaxDepenetrationSpeed = 2f,
            ParticleRadius = 0.02f,
            Friction = 0.5f,
            Restitution = 0.1f,
            SleepSpeed = 0.02f,
            SleepDelay = 1f,
            MaxSpeed = 500f,
        };
    }
}
