using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// A body as the fluid sees it in a coupled step (<see cref="FluidCoupling.Step"/>): a rigid shape that moves with the
    /// body's momentum, feels gravity and the fluid's pressure through the substeps of the fluid's step, and hands back the
    /// impulse the fluid gave it. The fluid sees its surface as a moving wall (<see cref="FluidGhostWalls"/>); the body
    /// takes the impulse in its own next step (<see cref="LinearAcceleration"/>, <see cref="ApplyAngularImpulse"/>), so the
    /// fluid and the body exchange equal and opposite momentum.
    /// </summary>
    public struct FluidBodyProxy
    {
        /// <summary>
        /// The shape in world space with its velocities (<see cref="ColliderShape.Velocity"/>, angular about its centre). The
        /// fluid's torque is taken about <see cref="ColliderShape.Center"/> and the proxy turns about it: right when that is the
        /// body's centre of mass (a sphere or <see cref="RestBox"/> of a uniform body), off by (centre − c) × impulse otherwise.
        /// </summary>
        public ColliderShape Shape;
        /// <summary>Mass (kg); 0 = kinematic: the shape keeps its velocity and the impulse is only reported.</summary>
        public float Mass;
        /// <summary>Inverse inertia tensor about the centre, world axes (1/(kg·m²)).</summary>
        public float3x3 InverseInertia;
        /// <summary>Out: impulse (N·s) the fluid gave the body over the step; gravity not included.</summary>
        public float3 Impulse;
        /// <summary>Out: angular impulse (N·m·s) about the centre the fluid gave the body over the step.</summary>
        public float3 AngularImpulse;

        /// <summary>
        /// The proxy of a particle body: <paramref name="restShape"/> (body space, relative to the rest centre of mass) placed
        /// at the body's centre of mass and best-fit rotation (<paramref name="status"/>, world), moving with the body's
        /// momentum (v = P/M, ω = I⁻¹L about the centre of mass), with its mass and inertia.
        /// </summary>
        public static FluidBodyProxy Of(in ParticleBody body, in ParticleBodyStatus status, in ColliderShape restShape)
        {
            RigidFrame frame = RigidFrame.Of(body.Positions, body.Masses);
            float3 momentum = float3.zero, angular = float3.zero;
            for (int i = 0; i < body.ParticleCount; i++)
            {
                float3 pi = body.Masses[i] * body.Velocities[i];
                momentum += pi;
                angular += math.cross(body.Positions[i] - frame.Center, pi);
            }
            float3 velocity = frame.Mass > 0f ? momentum / frame.Mass : float3.zero;
            float3 omega = math.mul(frame.InverseInertia, angular);
            ColliderShape shape = restShape.Transformed(status.Origin + frame.Center, status.Rotation, 1f);
            // The shape turns about the centre of mass (a capsule's Center is its first end: the velocity refers to it).
            float3 pivotVelocity = velocity + math.cross(omega, shape.Center - (status.Origin + frame.Center));
            return new FluidBodyProxy
            {
                Shape = shape.Moving(pivotVelocity, omega),
                Mass = frame.Mass,
                InverseInertia = frame.InverseInertia,
            };
        }

        /// <summary>
        /// The box around a body's rest particles in body space, relative to the rest centre of mass, grown by
        /// <paramref name="radius"/> (m, the particle radius) on every side: the usual proxy of a block-shaped body.
        /// </summary>
        public static ColliderShape RestBox(ReadOnlySpan<float3> restPositions, float3 restCenter, float radius)
        {
            float3 lo = new float3(float.PositiveInfinity), hi = new float3(float.NegativeInfinity);
            for (int i = 0; i < restPositions.Length; i++)
            {
                lo = math.min(lo, restPositions[i]);
                hi = math.max(hi, restPositions[i]);
            }
            if (!math.all(hi >= lo))
                return ColliderShape.Box(float3.zero, quaternion.identity, new float3(math.max(radius, 0f)));
            return ColliderShape.Box(0.5f * (lo + hi) - restCenter, quaternion.identity, 0.5f * (hi - lo) + math.max(radius, 0f));
        }

        /// <summary>The uniform acceleration (m/s²) that gives the body <see cref="Impulse"/> over its next step of <paramref name="dt"/>: add it to gravity.</summary>
        public float3 LinearAcceleration(float dt) => Mass > 0f && dt > 0f ? Impulse / (Mass * dt) : float3.zero;

        /// <summary>
        /// Gives the body's particles <see cref="AngularImpulse"/> as a rigid spin, Δvᵢ = (I⁻¹·ΔL) × (xᵢ − c) about the centre of
        /// mass c: momentum unchanged, angular momentum changed by ΔL. Call it between the fluid step and the body's step, on
        /// the positions <see cref="Of"/> read (its <see cref="InverseInertia"/> is theirs).
        /// </summary>
        public void ApplyAngularImpulse(in ParticleBody body)
        {
            if (!(Mass > 0f) || math.all(AngularImpulse == float3.zero))
                return;
            float3 dw = math.mul(InverseInertia, AngularImpulse);
            if (!math.all(math.isfinite(dw)))
                return;
            float3 center = ShapeMatching.CenterOfMass(body.Positions, body.Masses);
            for (int i = 0; i < body.ParticleCount; i++)
                body.Velocities[i] += math.cross(dw, body.Positions[i] - center);
        }

        /// <summary>
        /// One substep of <paramref name="h"/> seconds under gravity <paramref name="gravity"/> and the fluid's
        /// <paramref name="force"/> (N) and <paramref name="torque"/> (N·m, about the centre): semi-implicit Euler for the
        /// velocities, then the shape moves and turns with them; the impulses are summed. A kinematic proxy only moves.
        /// </summary>
        public void Advance(float3 force, float3 torque, float3 gravity, float h)
        {
            Impulse += h * force;
            AngularImpulse += h * torque;
            float3 v = Shape.Velocity, w = Shape.AngularVelocity;
            if (Mass > 0f)
            {
                v += h * (gravity + force / Mass);
                w += h * math.mul(InverseInertia, torque);
            }
            ColliderShape s = Shape.Translated(h * v);
            if (s.Type == ColliderShapeType.Box && math.any(w != float3.zero))
            {
                // q ← q + ½h·(ω, 0)·q, normalized.
                quaternion dq = new quaternion(new float4(0.5f * h * w, 0f));
                s.Rotation = math.normalizesafe(new quaternion(s.Rotation.value + math.mul(dq, s.Rotation).value));
            }
            Shape = s.Moving(v, w);
        }
    }
}
