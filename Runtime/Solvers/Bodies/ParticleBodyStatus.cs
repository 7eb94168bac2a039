using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Per-body bookkeeping of the step: placement, sleep and the NaN guard (a component in ECS).</summary>
    public struct ParticleBodyStatus
    {
        /// <summary>Centre of mass at the end of the last good step (m, world).</summary>
        public float3 Center;
        /// <summary>
        /// World position (m) the particle positions are relative to: zero while the body stays within
        /// <see cref="ShapeMatchingSolver.RebaseDistance"/> of the world origin, else whole metres near the body.
        /// World position of particle i = Origin + xᵢ.
        /// </summary>
        public float3 Origin;
        /// <summary>Centre of mass relative to <see cref="Origin"/> (m), at full float32 resolution.</summary>
        public float3 LocalCenter;
        /// <summary>Best-fit rotation of the whole body from its rest pose at the end of the last good step.</summary>
        public quaternion Rotation;
        /// <summary>Seconds the fastest particle has stayed below the sleep speed.</summary>
        public float StillTime;
        /// <summary>True while the body sleeps: it is not stepped until a force, an impulse or a contact wakes it.</summary>
        public bool Asleep;
        /// <summary>External acceleration (gravity + extra) of the last step, to wake the body when it changes (m/s²).</summary>
        public float3 LastAcceleration;
        /// <summary>How many times the NaN guard has reset this body.</summary>
        public int ResetCount;
        /// <summary>Steps taken while awake.</summary>
        public uint StepCount;
    }
}
