using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Mass, centre of mass and inverse inertia of a body's particles at the start of a substep: what the damping of
    /// the non-rigid velocity and the torque-free projection of a solve stage both need, computed once per substep.
    /// </summary>
    public struct RigidFrame
    {
        /// <summary>Σ mᵢ (kg).</summary>
        public float Mass;
        /// <summary>Σ mᵢ xᵢ / Σ mᵢ (m).</summary>
        public float3 Center;
        /// <summary>I⁻¹ about <see cref="Center"/> (<see cref="RigidMotionDamping.InverseInertia"/>).</summary>
        public float3x3 InverseInertia;

        /// <summary>The frame of positions <paramref name="x"/> with masses <paramref name="mass"/>.</summary>
        public static RigidFrame Of(ReadOnlySpan<float3> x, ReadOnlySpan<float> mass)
        {
            var frame = new RigidFrame();
            float3 sum = float3.zero;
            for (int i = 0; i < x.Length; i++)
            {
                sum += mass[i] * x[i];
                frame.Mass += mass[i];
            }
            frame.Center = frame.Mass > 0f ? sum / frame.Mass : float3.zero;
            frame.InverseInertia = RigidMotionDamping.InverseInertia(x, mass, frame.Center);
            return frame;
        }
    }
}
