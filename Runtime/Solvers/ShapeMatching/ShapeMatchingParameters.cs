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
        /// <summary>
        /// Gravity, substeps, contacts, sleep and the guard, shared by every method. Substeps are the fewest per step (1–64):
        /// the step adds substeps until ω·h ≤ <see cref="MaxSubstepPhase"/>, up to 64.
        /// </summary>
        public ParticleBodySettings Body;
        /// <summary>
        /// Largest phase ω·h (rad) of one substep; the step uses as many substeps as that needs (at most 64).
        /// It bounds the error of the static sag, ≈ ζωh + (ωh)²/12 relative; frequency and decay are exact at any h.
        /// Smaller = more accurate and slower. Default 0.5 rad.
        /// </summary>
        public float MaxSubstepPhase;
        /// <summary>Plastic flow of the rest shape (Müller et al. 2005, §4.5).</summary>
        public PlasticityParameters Plasticity;
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
            p.Body = Body.Sanitized(MaxSubsteps);
            p.MaxSubstepPhase = MaxSubstepPhase > 0f && math.isfinite(MaxSubstepPhase) ? MaxSubstepPhase : d.MaxSubstepPhase;
            bool plasticOk = math.isfinite(Plasticity.Yield) && math.isfinite(Plasticity.Creep) && math.isfinite(Plasticity.MaxDeformation)
                             && Plasticity.Yield >= 0f && Plasticity.Creep >= 0f && Plasticity.MaxDeformation >= 0f;
            p.Plasticity = plasticOk ? Plasticity : PlasticityParameters.None;
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
            Body = ParticleBodySettings.Default(4),
            MaxSubstepPhase = 0.5f,
            Plasticity = PlasticityParameters.None,
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
