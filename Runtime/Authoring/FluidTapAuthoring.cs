using SoftBodyDynamics.Solvers;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// A tap (emitter) pouring into a <see cref="FluidAuthoring"/>: particles start in its shape and leave along this
    /// GameObject's forward (+Z) axis. Placed by the Transform's position and rotation at bake time.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("Soft Body Dynamics/Fluid Tap")]
    public sealed class FluidTapAuthoring : MonoBehaviour
    {
        [Tooltip("The fluid this tap pours into.")]
        public FluidAuthoring fluid;

        [Tooltip("Where particles start: a point, a disc across the flow, a ball or a box.")]
        public FluidTapShape shape = FluidTapShape.Disc;

        [Tooltip("Disc or sphere radius (m).")]
        [Min(0f)]
        public float radius = 0.05f;

        [Tooltip("Box size (m).")]
        public Vector3 boxSize = new Vector3(0.1f, 0.1f, 0.1f);

        [Tooltip("Half-angle of the cone of directions around forward (degrees, 0 = a straight jet, below 180).")]
        [Range(0f, 179f)]
        public float coneAngle;

        [Tooltip("Mean start speed (m/s).")]
        [Min(0f)]
        public float speed = 1f;

        [Tooltip("The start speed varies by ± this (m/s, at most the speed).")]
        [Min(0f)]
        public float speedRandom;

        [Tooltip("Give the flow in particles per second, or in litres per second (converted with the fluid's particle spacing).")]
        public FluidTapRateMode rateMode = FluidTapRateMode.ParticlesPerSecond;

        [Tooltip("Steady flow (particles/s).")]
        [Min(0f)]
        public float rate = 200f;

        [Tooltip("Steady flow (L/s).")]
        [Min(0f)]
        public float volumeFlow = 0.1f;

        [Tooltip("Bursts: count particles at a time (s after start), repeated for cycles at an interval (s). At most 4.")]
        public FluidTapBurst[] bursts = new FluidTapBurst[0];

        [Tooltip("Pulsing period (s); 0 = a steady flow.")]
        [Min(0f)]
        public float pulsePeriod;

        [Tooltip("Fraction of each pulse period the tap is open (0–1].")]
        [Range(0.01f, 1f)]
        public float pulseDutyCycle = 1f;

        [Tooltip("How long the tap runs after its start delay (s); 0 = forever.")]
        [Min(0f)]
        public float duration;

        [Tooltip("Start again, with the bursts, every duration.")]
        public bool looping;

        [Tooltip("Time before the tap starts (s).")]
        [Min(0f)]
        public float startDelay;

        [Tooltip("Seconds of flow simulated before the first frame, so the scene starts with the flow established (s).")]
        [Min(0f)]
        public float prewarm;

        [Tooltip("The tap pauses while the fluid holds this many particles (0 = up to the fluid's budget).")]
        [Min(0)]
        public int maxAlive;

        [Tooltip("Mean particle lifetime (s); 0 = until a drain or gameplay removes it.")]
        [Min(0f)]
        public float lifetime = 5f;

        [Tooltip("Lifetime varies by ± this (s, at most the lifetime).")]
        [Min(0f)]
        public float lifetimeRandom = 0.5f;

        [Tooltip("Attribute the particles start with (temperature in K for lava looks).")]
        public float attribute = 293f;

        [Tooltip("Seed of the tap's random numbers.")]
        public uint seed = 1;

        /// <summary>The tap's settings in world space.</summary>
        public FluidTapSettings ToSettings() => new FluidTapSettings
        {
            Position = UnityMathConversions.ToFloat3(transform.position),
            Rotation = UnityMathConversions.ToQuaternion(transform.rotation),
            Shape = shape,
            Radius = radius,
            HalfExtents = 0.5f * UnityMathConversions.ToFloat3(boxSize),
            ConeAngle = coneAngle,
            Speed = speed,
            SpeedRandom = speedRandom,
            RateMode = rateMode,
            Rate = rate,
            VolumeFlow = volumeFlow,
            PulsePeriod = pulsePeriod,
            PulseDutyCycle = pulseDutyCycle,
            Duration = duration,
            Looping = looping,
            StartDelay = startDelay,
            Prewarm = prewarm,
            MaxAlive = maxAlive,
            Lifetime = lifetime,
            LifetimeRandom = lifetimeRandom,
            Attribute = attribute,
            Seed = seed,
        };

        /// <summary>Steady-state alive particles (rate × lifetime with bursts), for the inspector read-out; needs the fluid for the spacing.</summary>
        public double SteadyStateAlive() =>
            fluid == null ? double.NaN : FluidTapSchedule.SteadyStateAlive(ToSettings(), bursts ?? new FluidTapBurst[0], fluid.particleSpacing);

        void OnDrawGizmos()
        {
            // The flow: lines from the tap to the rim of the cone as far as the particles travel in 0.25 s.
            Gizmos.color = new Color(0.3f, 0.7f, 1f, 0.9f);
            Unity.Mathematics.quaternion rotation = UnityMathConversions.ToQuaternion(transform.rotation);
            Unity.Mathematics.float3 origin = UnityMathConversions.ToFloat3(transform.position);
            float length = Unity.Mathematics.math.max(0.05f, 0.25f * speed);
            float spread = length * (float)System.Math.Tan(Unity.Mathematics.math.min(coneAngle, 80f) * System.Math.PI / 180.0)
                + (shape == FluidTapShape.Point ? 0f : radius);
            Unity.Mathematics.float3 tip = origin + Unity.Mathematics.math.rotate(rotation, new Unity.Mathematics.float3(0f, 0f, length));
            Gizmos.DrawLine(transform.position, UnityMathConversions.ToVector3(tip));
            for (int k = 0; k < 8; k++)
            {
                float a = k * Unity.Mathematics.math.PI / 4f;
                var local = new Unity.Mathematics.float3(spread * Unity.Mathematics.math.cos(a), spread * Unity.Mathematics.math.sin(a), length);
                Gizmos.DrawLine(transform.position, UnityMathConversions.ToVector3(origin + Unity.Mathematics.math.rotate(rotation, local)));
            }
            if (shape == FluidTapShape.Sphere || shape == FluidTapShape.Disc)
                Gizmos.DrawWireSphere(transform.position, radius);
            else if (shape == FluidTapShape.Box)
                Gizmos.DrawWireCube(transform.position, boxSize);
        }
    }
}
