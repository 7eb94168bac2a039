using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Per-body tunables of shape matching (a component in ECS). Units are in each doc comment.</summary>
    public struct ShapeMatchingParameters
    {
        /// <summary>Rigid, linear or quadratic goals.</summary>
        public ShapeMatchingMode Mode;
        /// <summary>
        /// α ∈ [0, 1]: fraction of the way to the goal positions covered per step of <c>dt</c>
        /// (Müller et al. 2005, eq. 3). 1 = stiff, 0.05 = very soft. Substeps use
        /// α_sub = 1 − (1 − α)^(1/substeps), so the stiffness does not change with the substep count.
        /// </summary>
        public float Stiffness;
        /// <summary>β ∈ [0, 1]: blend of the linear or quadratic transform into the rotation (eq. 8). 0 = rigid goals.</summary>
        public float Beta;
        /// <summary>
        /// Rate (1/s) at which velocity that differs from the body's rigid motion decays:
        /// each substep vᵢ += (1 − e^(−damping·h))·(v_cm + ω × rᵢ − vᵢ). Rigid motion (momentum,
        /// angular momentum) is untouched; wobble, sway and bending decay. 0 = none.
        /// </summary>
        public float Damping;
        /// <summary>Uniform acceleration on every particle: gravity plus any wind-like force per mass (m/s²).</summary>
        public float3 Acceleration;
        /// <summary>Substeps per step (1–64). More substeps: stiffer contacts, less tunnelling, more cost.</summary>
        public int Substeps;
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
        /// A copy the step can trust: NaN or out-of-range values are replaced by the nearest valid value
        /// (or the default where none is nearer). Authoring reports such values as errors before they get
        /// here (<c>ShapeMatchingParameterValidation</c>); this only keeps the simulation from exploding.
        /// </summary>
        public ShapeMatchingParameters Sanitized()
        {
            var d = Default;
            var p = this;
            p.Stiffness = math.isnan(Stiffness) ? d.Stiffness : math.saturate(Stiffness);
            p.Beta = math.isnan(Beta) ? d.Beta : math.saturate(Beta);
            p.Damping = math.isfinite(Damping) ? math.max(0f, Damping) : d.Damping;
            p.Acceleration = math.all(math.isfinite(Acceleration)) ? Acceleration : float3.zero;
            p.Substeps = math.clamp(Substeps, 1, 64);
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

        /// <summary>A jelly-like default: linear mode, α = 0.2, β = 0.5, 4 substeps, Earth gravity.</summary>
        public static ShapeMatchingParameters Default => new ShapeMatchingParameters
        {
            Mode = ShapeMatchingMode.Linear,
            Stiffness = 0.2f,
            Beta = 0.5f,
            Damping = 1f,
            Acceleration = new float3(0f, -9.81f, 0f),
            Substeps = 4,
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
