using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Per-body tunables of shape matching (a component in ECS). Units are in each doc comment.</summary>
    public struct ShapeMatchingParameters
    {
        /// <summary>Rigid, linear or quadratic goals.</summary>
        public ShapeMatchingMode Mode;
        /// <summary>
        /// Natural frequency f (Hz) of the deformation the goals resist fully: each particle is pulled toward
        /// its goal with the acceleration ω²(gᵢ − xᵢ), ω = 2πf, the continuous form of Müller et al. 2005,
        /// eq. 3. A time, not a per-frame fraction: the same f wobbles at the same rate and sags by the same
        /// amount at any frame rate and substep count (<see cref="OscillatorDiscretization"/>). Deformations the
        /// linear or quadratic transform follows are resisted by (1 − β): they oscillate at f·√(1 − β).
        /// 2 Hz = soft jelly, 20 Hz = firm rubber.
        /// </summary>
        public float Frequency;
        /// <summary>
        /// Damping ratio ζ (dimensionless) of the same oscillation: the velocity that differs from the body's
        /// rigid motion decays at the rate 2ζω; rigid motion (momentum, angular momentum) is untouched.
        /// 0 = undamped, 0.1 = wobbles for many periods, 1 = critically damped (no overshoot).
        /// </summary>
        public float DampingRatio;
        /// <summary>
        /// β ∈ [0, 1]: blend of the linear or quadratic transform into the rotation (eq. 8). 0 = rigid goals.
        /// Values above <see cref="MaxBeta"/> act as <see cref="MaxBeta"/>.
        /// </summary>
        public float Beta;
        /// <summary>Uniform acceleration on every particle: gravity plus any wind-like force per mass (m/s²).</summary>
        public float3 Acceleration;
        /// <summary>
        /// Fewest substeps per step (1–64). The step adds substeps until ω·h ≤ <see cref="MaxSubstepPhase"/>, up to 64.
        /// More substeps: stiffer contacts, less tunnelling, more cost.
        /// </summary>
        public int Substeps;
        /// <summary>
        /// Largest phase ω·h (rad) of one substep; the step uses as many substeps as that needs (at most 64).
        /// It bounds the error of the static sag, ≈ ζωh + (ωh)²/12 relative; frequency and decay are exact at any h.
        /// Smaller = more accurate and slower. Default 0.5 rad.
        /// </summary>
        public float MaxSubstepPhase;
        /// <summary>
        /// Largest speed (m/s) at which a particle that starts a substep inside a collider is pushed out. A body
        /// spawned inside a collider leaves it at this speed, whole and along one direction, instead of being shot out. Default 2 m/s.
        /// </summary>
        public float MaxDepenetrationSpeed;
        /// <summary>Particle radius used against colliders (m).</summary>
        public float ParticleRadius;
        /// <summary>Coulomb friction coefficient μ against colliders (0 = ice, 1 = rubber on concrete).</summary>
        public float Friction;
        /// <summary>Restitution e ∈ [0, 1] of particle–collider contacts (0 = no bounce).</summary>
        public float Restitution;
        /// <summary>Plastic flow of the rest shape (Müller et al. 2005, §4.5).</summary>
        public PlasticityParameters Plasticity;
        /// <summary>The body sleeps after its particles' mass-weighted RMS speed stayed below this for <see cref="SleepDelay"/> (m/s). 0 = never sleeps.</summary>
        public float SleepSpeed;
        /// <summary>Time below <see cref="SleepSpeed"/> before sleeping (s).</summary>
        public float SleepDelay;
        /// <summary>Speed above which the state counts as absurd and the NaN guard resets the body (m/s).</summary>
        public float MaxSpeed;
        /// <summary>Rotation-extraction iterations per cluster and substep (warm-started).</summary>
        public int RotationIterations;

        /// <summary>
        /// A copy the step can trust, by the rule every method's step follows: a value beyond a limit becomes the limit; any
        /// other invalid value (NaN, a negative frequency or damping ratio) becomes the default, never a different valid
        /// value (a negative frequency is not 0 Hz, which would let the body collapse). The step reports the replacement
        /// (<see cref="ShapeMatchingStepReport.ParametersReplaced"/>); authoring reports the values as errors first
        /// (<c>ShapeMatchingParameterValidation</c>).
        /// </summary>
        public ShapeMatchingParameters Sanitized()
        {
            var d = Default;
            var p = this;
            p.Frequency = Frequency >= 0f && !math.isnan(Frequency) ? math.min(Frequency, MaxFrequency) : d.Frequency;
            p.DampingRatio = DampingRatio >= 0f && !math.isnan(DampingRatio) ? math.min(DampingRatio, MaxDampingRatio) : d.DampingRatio;
            p.Beta = math.isnan(Beta) ? d.Beta : math.clamp(Beta, 0f, MaxBeta);
            p.Acceleration = math.all(math.isfinite(Acceleration)) ? Acceleration : float3.zero;
            p.Substeps = math.clamp(Substeps, 1, MaxSubsteps);
            p.MaxSubstepPhase = MaxSubstepPhase > 0f && math.isfinite(MaxSubstepPhase) ? MaxSubstepPhase : d.MaxSubstepPhase;
            p.MaxDepenetrationSpeed = MaxDepenetrationSpeed > 0f && math.isfinite(MaxDepenetrationSpeed)
                ? MaxDepenetrationSpeed : d.MaxDepenetrationSpeed;
            p.ParticleRadius = math.isfinite(ParticleRadius) ? math.max(0f, ParticleRadius) : d.ParticleRadius;
            p.Friction = math.isfinite(Friction) ? math.max(0f, Friction) : d.Friction;
            p.Restitution = math.isnan(Restitution) ? d.Restitution : math.saturate(Restitution);
            bool plasticOk = math.isfinite(Plasticity.Yield) && math.isfinite(Plasticity.Creep) && math.isfinite(Plasticity.MaxDeformation)
                             && Plasticity.Yield >= 0f && Plasticity.Creep >= 0f && Plasticity.MaxDeformation >= 0f;
            p.Plasticity = plasticOk ? Plasticity : PlasticityParameters.None;
            p.SleepSpeed = math.isfinite(SleepSpeed) ? math.max(0f, SleepSpeed) : d.SleepSpeed;
            p.SleepDelay = math.isfinite(SleepDelay) ? math.max(0f, SleepDelay) : d.SleepDelay;
            p.MaxSpeed = MaxSpeed > 0f && math.isfinite(MaxSpeed) ? MaxSpeed : d.MaxSpeed;
            p.RotationIterations = math.clamp(RotationIterations, 1, 100);
            if (Mode > ShapeMatchingMode.Quadratic)
                p.Mode = d.Mode;
            return p;
        }

        /// <summary>Most substeps per step.</summary>
        public const int MaxSubsteps = 64;
        /// <summary>
        /// Largest β used: at β = 1 the deformations the transform follows have no restoring force at all, and
        /// float32 round-off of the goals (a bias of ~10⁻⁷ that is the same every substep) drifts them without
        /// bound. At 0.99 they still oscillate at f/10 and the round-off offset stays ~10⁻⁵ of the size.
        /// </summary>
        public const float MaxBeta = 0.99f;
        /// <summary>Largest frequency accepted (Hz); beyond it the body is rigid for any practical step.</summary>
        public const float MaxFrequency = 1000f;
        /// <summary>Largest damping ratio accepted.</summary>
        public const float MaxDampingRatio = 100f;

        /// <summary>ω = 2πf (rad/s).</summary>
        public float AngularFrequency => 2f * math.PI * Frequency;

        /// <summary>A jelly-like default: linear mode, 9 Hz, ζ = 0.13, β = 0.5, at least 4 substeps, Earth gravity.</summary>
        public static ShapeMatchingParameters Default => new ShapeMatchingParameters
        {
            Mode = ShapeMatchingMode.Linear,
            Frequency = 9f,
            DampingRatio = 0.13f,
            Beta = 0.5f,
            Acceleration = new float3(0f, -9.81f, 0f),
            Substeps = 4,
            MaxSubstepPhase = 0.5f,
            MaxDepenetrationSpeed = 2f,
            ParticleRadius = 0.02f,
            Friction = 0.5f,
            Restitution = 0.1f,
            Plasticity = PlasticityParameters.None,
            SleepSpeed = 0.02f,
            SleepDelay = 1f,
            MaxSpeed = 500f,
            RotationIterations = RotationExtraction.DefaultMaxIterations,
        };
    }

    /// <summary>Plasticity of Müller et al. 2005, §4.5: the rest shape yields, creeps and is bounded.</summary>
    public struct PlasticityParameters
    {
        /// <summary>Yield: plastic flow starts when ‖S − I‖_F exceeds this (dimensionless strain). 0 with creep 0 = elastic.</summary>
        public float Yield;
        /// <summary>Creep rate (1/s): Sₚ ← (I + h·creep·(S − I)) Sₚ while yielding. 0 = elastic.</summary>
        public float Creep;
        /// <summary>Largest plastic strain ‖Sₚ − I‖_F (dimensionless): the rest shape never drifts further.</summary>
        public float MaxDeformation;

        /// <summary>True when plastic flow can happen.</summary>
        public bool Enabled => Creep > 0f && MaxDeformation > 0f;

        /// <summary>Perfectly elastic.</summary>
        public static PlasticityParameters None => default;
    }
}
