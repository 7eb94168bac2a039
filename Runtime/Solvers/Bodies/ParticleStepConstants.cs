using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Everything one step of a particle body needs besides its arrays, computed once per step on the CPU: the
    /// substep count and length, the coefficients of the exact oscillator rule (<see cref="OscillatorDiscretization"/>),
    /// gravity, contact settings and the guard's limits. A plain blittable struct, the layout a compute kernel's
    /// constant buffer will mirror.
    /// </summary>
    public struct ParticleStepConstants
    {
        /// <summary>Step length dt (s).</summary>
        public float Dt;
        /// <summary>Substep length h = dt / substeps (s).</summary>
        public float H;
        /// <summary>Substeps in the step.</summary>
        public int Substeps;
        /// <summary>α: fraction of the way to the goal (or constraint target) added per substep.</summary>
        public float Pull;
        /// <summary>D: fraction of the non-rigid velocity kept per substep (1 = undamped).</summary>
        public float VelocityRetention;
        /// <summary>Uniform acceleration on every particle (m/s²).</summary>
        public float3 Gravity;
        /// <summary>Contact settings of every substep (radius, friction, restitution, bounce threshold, depenetration cap, origin).</summary>
        public ContactProjection.Settings Contact;
        /// <summary>Speed above which the guard resets the body (m/s).</summary>
        public float MaxSpeed;
        /// <summary>Mass-weighted RMS speed below which the body counts as still (m/s); 0 = never sleeps.</summary>
        public float SleepSpeed;
        /// <summary>Time still before the body sleeps (s).</summary>
        public float SleepDelay;

        /// <summary>
        /// Constants of a step of <paramref name="dt"/> for a material of angular frequency <paramref name="omega"/> (rad/s)
        /// and damping ratio <paramref name="zeta"/>: at least <paramref name="minSubsteps"/> substeps, and enough that
        /// ω·h ≤ <paramref name="maxSubstepPhase"/>, up to <paramref name="maxSubsteps"/>.
        /// </summary>
        public static ParticleStepConstants For(float dt, float omega, float zeta, int minSubsteps, float maxSubstepPhase,
            int maxSubsteps, float3 gravity)
        {
            int substeps = OscillatorDiscretization.SubstepsFor(omega, dt, minSubsteps, maxSubstepPhase, maxSubsteps);
            float h = dt / substeps;
            OscillatorDiscretization.Coefficients k = OscillatorDiscretization.Compute(omega, zeta, h);
            return new ParticleStepConstants
            {
                Dt = dt,
                H = h,
                Substeps = substeps,
                Pull = k.Pull,
                VelocityRetention = k.VelocityRetention,
                Gravity = gravity,
                // Resting contacts must not bounce: ignore approach speeds one substep of acceleration can produce.
                Contact = new ContactProjection.Settings { BounceThreshold = 2f * math.length(gravity) * h },
            };
        }

        /// <summary>
        /// Constants of a step of <paramref name="dt"/> in exactly <paramref name="substeps"/> substeps with no shared
        /// velocity damping and no pull (methods that damp in their own stage: mass-spring, FEM), gravity
        /// <paramref name="gravity"/>, contact and guard settings as given.
        /// </summary>
        /// <param name="maxDepenetrationSpeed">Largest push-out speed of a particle that starts a substep inside a collider (m/s).</param>
        public static ParticleStepConstants Undamped(float dt, int substeps, float3 gravity, float particleRadius, float friction,
            float restitution, float maxDepenetrationSpeed, float maxSpeed, float sleepSpeed, float sleepDelay)
        {
            float h = dt / substeps;
            return new ParticleStepConstants
            {
                Dt = dt,
                H = h,
                Substeps = substeps,
                Pull = 0f,
                VelocityRetention = 1f,
                Gravity = gravity,
                // Resting contacts must not bounce: ignore approach speeds one substep of acceleration can produce.
                Contact = new ContactProjection.Settings
                {
                    BounceThreshold = 2f * math.length(gravity) * h,
                    Radius = particleRadius,
                    Friction = friction,
                    Restitution = restitution,
                    MaxDepenetration = maxDepenetrationSpeed * h,
                },
                MaxSpeed = maxSpeed,
                SleepSpeed = sleepSpeed,
                SleepDelay = sleepDelay,
            };
        }
    }
}
