using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The settings every particle body has, whatever its method: gravity, substeps, contacts, sleep and the guard's speed
    /// limit. Each method's parameters nest one (<see cref="ShapeMatchingParameters.Body"/>,
    /// <see cref="MassSpringParameters.Body"/>, <see cref="FemParameters.Body"/>); the world's settings (a
    /// <c>ParticleWorldSettings</c> singleton) replace its gravity and raise its substeps. Units are in each doc comment.
    /// </summary>
    public struct ParticleBodySettings
    {
        /// <summary>Uniform acceleration on every particle: gravity plus any wind-like force per mass (m/s²).</summary>
        public float3 Acceleration;
        /// <summary>
        /// Substeps per step (at least 1, at most the method's limit): the fewest for shape matching, which adds substeps until
        /// its phase limit holds; exactly this many for mass-spring and FEM. More substeps: stiffer contacts, less tunnelling,
        /// more cost.
        /// </summary>
        public int Substeps;
        /// <summary>
        /// Largest speed (m/s) at which a particle that starts a substep inside a collider is pushed out. A body spawned inside
        /// a collider leaves it at this speed, whole and along one direction, instead of being shot out. Default 2 m/s.
        /// </summary>
        public float MaxDepenetrationSpeed;
        /// <summary>Particle radius used against colliders (m).</summary>
        public float ParticleRadius;
        /// <summary>
        /// Coulomb friction coefficient μ against colliders (0 = ice, 1 = rubber on concrete). FEM's implicit integrator holds
        /// frictionless contact nodes in its solve; with friction they are pushed out after it.
        /// </summary>
        public float Friction;
        /// <summary>Restitution e ∈ [0, 1] of particle–collider contacts (0 = no bounce).</summary>
        public float Restitution;
        /// <summary>The body sleeps after its particles' mass-weighted RMS speed stayed below this for <see cref="SleepDelay"/> (m/s). 0 = never sleeps.</summary>
        public float SleepSpeed;
        /// <summary>Time below <see cref="SleepSpeed"/> before sleeping (s).</summary>
        public float SleepDelay;
        /// <summary>
        /// Speed above which the state counts as absurd and the NaN guard resets the body (m/s). An explicit integrator past
        /// its stable step trips it.
        /// </summary>
        public float MaxSpeed;

        /// <summary>Earth gravity, <paramref name="substeps"/> substeps, 2 cm particles, μ = 0.5, e = 0.1, 2 m/s depenetration, sleep below 0.02 m/s for 1 s, guard at 500 m/s.</summary>
        public static ParticleBodySettings Default(int substeps) => new ParticleBodySettings
        {
            Acceleration = new float3(0f, -9.81f, 0f),
            Substeps = substeps,
            MaxDepenetrationSpeed = 2f,
            ParticleRadius = 0.02f,
            Friction = 0.5f,
            Restitution = 0.1f,
            SleepSpeed = 0.02f,
            SleepDelay = 1f,
            MaxSpeed = 500f,
        };

        /// <summary>
        /// A copy the step can trust: substeps clamped to [1, <paramref name="maxSubsteps"/>], a non-finite acceleration
        /// becomes zero, negative radius, friction or sleep values become 0, restitution is clamped to [0, 1], and any other
        /// invalid value (NaN, a non-positive depenetration speed or speed limit) becomes the default.
        /// </summary>
        public ParticleBodySettings Sanitized(int maxSubsteps)
        {
            ParticleBodySettings d = Default(1);
            ParticleBodySettings p = this;
            p.Acceleration = math.all(math.isfinite(Acceleration)) ? Acceleration : float3.zero;
            p.Substeps = math.clamp(Substeps, 1, maxSubsteps);
            p.MaxDepenetrationSpeed = MaxDepenetrationSpeed > 0f && math.isfinite(MaxDepenetrationSpeed) ? MaxDepenetrationSpeed : d.MaxDepenetrationSpeed;
            p.ParticleRadius = math.isfinite(ParticleRadius) ? math.max(0f, ParticleRadius) : d.ParticleRadius;
            p.Friction = math.isfinite(Friction) ? math.max(0f, Friction) : d.Friction;
            p.Restitution = math.isnan(Restitution) ? d.Restitution : math.saturate(Restitution);
            p.SleepSpeed = math.isfinite(SleepSpeed) ? math.max(0f, SleepSpeed) : d.SleepSpeed;
            p.SleepDelay = math.isfinite(SleepDelay) ? math.max(0f, SleepDelay) : d.SleepDelay;
            p.MaxSpeed = MaxSpeed > 0f && math.isfinite(MaxSpeed) ? MaxSpeed : d.MaxSpeed;
            return p;
        }
    }
}
