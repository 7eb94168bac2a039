using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Where a tap's particles start.</summary>
    public enum FluidTapShape : byte
    {
        /// <summary>One point at the tap's position.</summary>
        Point = 0,
        /// <summary>A disc of <see cref="FluidTapSettings.Radius"/> across the flow (the tap's local XY plane).</summary>
        Disc = 1,
        /// <summary>A ball of <see cref="FluidTapSettings.Radius"/>.</summary>
        Sphere = 2,
        /// <summary>A box of <see cref="FluidTapSettings.HalfExtents"/> in the tap's frame.</summary>
        Box = 3,
    }

    /// <summary>How a tap's steady flow is given.</summary>
    public enum FluidTapRateMode : byte
    {
        /// <summary><see cref="FluidTapSettings.Rate"/> particles per second.</summary>
        ParticlesPerSecond = 0,
        /// <summary><see cref="FluidTapSettings.VolumeFlow"/> litres per second, converted with the particle volume Δx³.</summary>
        LitresPerSecond = 1,
    }

    /// <summary>A burst: <see cref="Count"/> particles at <see cref="Time"/>, repeated <see cref="Cycles"/> times every <see cref="Interval"/>.</summary>
    [System.Serializable]
    public struct FluidTapBurst
    {
        /// <summary>Time of the first cycle after the tap starts (s, after the start delay; per loop when looping).</summary>
        public float Time;
        /// <summary>Particles per cycle.</summary>
        public int Count;
        /// <summary>Number of cycles (≥ 1).</summary>
        public int Cycles;
        /// <summary>Time between cycles (s, &gt; 0 when Cycles &gt; 1).</summary>
        public float Interval;
    }

    /// <summary>
    /// A tap (emitter) of one fluid: shape, flow, timing and the particles' lifetime. Units in each doc comment. The
    /// flow leaves along the tap's local +Z axis.
    /// </summary>
    public struct FluidTapSettings
    {
        /// <summary>World position of the tap (m).</summary>
        public float3 Position;
        /// <summary>World rotation; the flow leaves along its local +Z.</summary>
        public quaternion Rotation;
        /// <summary>Shape the particles start in.</summary>
        public FluidTapShape Shape;
        /// <summary>Disc or sphere radius (m). Default 0.05 m.</summary>
        public float Radius;
        /// <summary>Box half extents (m).</summary>
        public float3 HalfExtents;
        /// <summary>Half-angle of the cone of directions around +Z (degrees, 0 = a straight jet, below 180).</summary>
        public float ConeAngle;
        /// <summary>Mean start speed (m/s). Default 1 m/s.</summary>
        public float Speed;
        /// <summary>Start speed varies uniformly by ± this (m/s, at most <see cref="Speed"/>).</summary>
        public float SpeedRandom;
        /// <summary>Whether <see cref="Rate"/> or <see cref="VolumeFlow"/> sets the steady flow.</summary>
        public FluidTapRateMode RateMode;
        /// <summary>Steady flow in particles per second.</summary>
        public float Rate;
        /// <summary>Steady flow in litres per second (1 L = 1e-3 m³; one particle carries Δx³).</summary>
        public float VolumeFlow;
        /// <summary>Pulsing period (s); 0 = a steady flow.</summary>
        public float PulsePeriod;
        /// <summary>Fraction of each pulse period the tap is open, in (0, 1].</summary>
        public float PulseDutyCycle;
        /// <summary>How long the tap runs after its start delay (s); 0 = forever.</summary>
        public float Duration;
        /// <summary>Start again (with the bursts) every <see cref="Duration"/>.</summary>
        public bool Looping;
        /// <summary>Time before the tap starts (s).</summary>
        public float StartDelay;
        /// <summary>Seconds of flow simulated before the first frame, so the scene starts with the flow established (s).</summary>
        public float Prewarm;
        /// <summary>The tap pauses while the fluid holds this many particles (0 = up to the fluid's budget).</summary>
        public int MaxAlive;
        /// <summary>Mean lifetime of a particle (s); 0 = lives until a drain or gameplay removes it.</summary>
        public float Lifetime;
        /// <summary>Lifetime varies uniformly by ± this (s, at most <see cref="Lifetime"/>).</summary>
        public float LifetimeRandom;
        /// <summary>Attribute the particles start with (temperature in K for lava looks).</summary>
        public float Attribute;
        /// <summary>Seed of the tap's random numbers (jitter, directions, speeds, lifetimes).</summary>
        public uint Seed;

        /// <summary>A disc tap of 5 cm radius pouring 200 particles/s at 1 m/s, forever.</summary>
        public static FluidTapSettings Default => new FluidTapSettings
        {
            Rotation = quaternion.identity,
            Shape = FluidTapShape.Disc,
            Radius = 0.05f,
            HalfExtents = new float3(0.05f),
            ConeAngle = 0f,
            Speed = 1f,
            RateMode = FluidTapRateMode.ParticlesPerSecond,
            Rate = 200f,
            VolumeFlow = 0.1f,
            PulseDutyCycle = 1f,
            Attribute = 293f,
            Seed = 1,
        };

        /// <summary>Steady flow in particles per second for particle spacing <paramref name="spacing"/> (m).</summary>
        public float ParticlesPerSecond(float spacing) =>
            RateMode == FluidTapRateMode.LitresPerSecond ? VolumeFlow * 1e-3f / (spacing * spacing * spacing) : Rate;

        /// <summary>A copy the emitter can trust: NaN or out-of-range values replaced by the nearest valid value (or the default).</summary>
        public FluidTapSettings Sanitized()
        {
            FluidTapSettings d = Default;
            FluidTapSettings s = this;
            if (!math.all(math.isfinite(Position)))
                s.Position = float3.zero;
            float4 q = Rotation.value;
            s.Rotation = math.all(math.isfinite(q)) && math.dot(q, q) > 1e-12f ? math.normalize(Rotation) : quaternion.identity;
            if ((uint)Shape > (uint)FluidTapShape.Box)
                s.Shape = d.Shape;
            s.Radius = Finite.NonNegative(Radius);
            s.HalfExtents = new float3(Finite.NonNegative(HalfExtents.x), Finite.NonNegative(HalfExtents.y), Finite.NonNegative(HalfExtents.z));
            s.ConeAngle = math.isfinite(ConeAngle) ? math.clamp(ConeAngle, 0f, 179f) : 0f;
            s.Speed = Finite.NonNegative(Speed);
            s.SpeedRandom = math.min(Finite.NonNegative(SpeedRandom), s.Speed);
            if ((uint)RateMode > (uint)FluidTapRateMode.LitresPerSecond)
                s.RateMode = d.RateMode;
            s.Rate = Finite.NonNegative(Rate);
            s.VolumeFlow = Finite.NonNegative(VolumeFlow);
            s.PulsePeriod = Finite.NonNegative(PulsePeriod);
            s.PulseDutyCycle = PulseDutyCycle > 0f && math.isfinite(PulseDutyCycle) ? math.min(PulseDutyCycle, 1f) : 1f;
            s.Duration = Finite.NonNegative(Duration);
            s.StartDelay = Finite.NonNegative(StartDelay);
            s.Prewarm = Finite.NonNegative(Prewarm);
            s.MaxAlive = math.max(0, MaxAlive);
            s.Lifetime = Finite.NonNegative(Lifetime);
            s.LifetimeRandom = math.min(Finite.NonNegative(LifetimeRandom), s.Lifetime);
            s.Attribute = math.isfinite(Attribute) ? Attribute : d.Attribute;
            return s;
        }

    }
}
