using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The step every particle body shares, generic over what holds it together (<see cref="IParticleSolveStage"/>).
    /// A step of dt is <see cref="ParticleStepConstants.Substeps"/> substeps of h, each:
    /// <list type="number">
    /// <item>predict (velocities): the non-rigid velocity decays, vᵢ ← uᵢ + D (vᵢ − uᵢ) with uᵢ the body's rigid
    /// velocity (<see cref="RigidMotionDamping"/>), and gravity acts, vᵢ += h·g;</item>
    /// <item>solve: the stage adds its internal forces from the positions xᵢ (symplectic Euler: forces of xₙ, then
    /// positions from the new velocities);</item>
    /// <item>predict (positions): x*ᵢ = xᵢ + h·vᵢ;</item>
    /// <item>collide: x* pushed out of colliders with friction and restitution, the push added to v
    /// (<see cref="ContactProjection"/>); the contact normals are the next substep's input to a stage that holds contacts
    /// in its solve (<see cref="ContactProjection.Settings.KeepTouching"/>; the step's first come from the positions);</item>
    /// <item>update: xᵢ = x*ᵢ.</item>
    /// </list>
    /// Around the substeps: a sleeping body is woken by a change of gravity, a velocity written from outside or a
    /// collider overlapping it; a guard resets a body with a non-finite or absurd state (speed above
    /// <see cref="ParticleStepConstants.MaxSpeed"/>, position beyond <see cref="PositionLimit"/>) to its rest shape at
    /// its last good placement and reports it; the placement (centre of mass, best-fit rotation) is updated and the
    /// origin the positions are relative to follows the body in whole metres beyond <see cref="RebaseDistance"/>, so a
    /// body 10 km from the world origin has the float32 resolution of one near it; a slow body falls asleep.
    /// Pinned particles (<see cref="ParticleBody.InverseMasses"/> = 0) keep zero velocity through every substep: before
    /// the solve, before the positions are predicted, and after the collide.
    /// The same function runs in the Burst jobs and in the .NET tests; it touches nothing but its arguments.
    /// </summary>
    public static class ParticleBodyStep
    {
        /// <summary>Largest accepted distance of a particle from the body's origin, and of the origin from the world origin (m).</summary>
        public const float PositionLimit = 1e6f;

        /// <summary>
        /// Distance (m, per axis) the body's centre may move from <see cref="ParticleBodyStatus.Origin"/> before the origin
        /// moves to it. Within it float32 positions resolve 4 µm; bodies that stay within it of the world origin keep
        /// the origin at zero, so their positions are world positions.
        /// </summary>
        public const float RebaseDistance = 64f;

        /// <summary>Advances the body by one step. See the class comment.</summary>
        /// <param name="colliders">Static colliders in world space.</param>
        public static ParticleStepReport Step<TStage>(ref TStage stage, in ParticleBody body, in ParticleStepConstants constants,
            ReadOnlySpan<ColliderShape> colliders, ref ParticleBodyStatus status) where TStage : struct, IParticleSolveStage
        {
            var report = new ParticleStepReport { BadParticle = -1 };
            if (!(constants.Dt > 0f) || !math.isfinite(constants.Dt) || body.ParticleCount == 0 || constants.Substeps < 1)
                return report;
            ContactProjection.Settings contact = constants.Contact;
            contact.Origin = status.Origin;
            contact.WholeBody = true;
            if (status.Asleep)
            {
                if (!ShouldWake(body, constants, contact, colliders, status))
                    return report;
                Wake(ref status);
                report.WokeUp = true;
            }
            // Bad input (written from outside since the last step) is caught before it spreads, with its index.
            int badInput = FindBadParticle(body.Positions, body.Velocities, constants.MaxSpeed);
            if (badInput >= 0 || !(math.cmax(math.abs(status.Origin)) <= PositionLimit))
            {
                ResetToLastGoodPlacement(ref stage, body, math.max(badInput, 0), ref status, ref report);
                return report;
            }
            report.Stepped = true;
            report.Substeps = constants.Substeps;
            status.LastAcceleration = constants.Gravity;

            float h = constants.H;
            float velocityLoss = 1f - constants.VelocityRetention;
            var x = body.Positions;
            var v = body.Velocities;
            var predicted = body.Predicted;
            // A stage that holds contacts in its solve reads each substep's contacts from the previous one; the first from the positions.
            if (contact.KeepTouching)
            {
                if (colliders.Length > 0)
                    ContactProjection.StartContacts(x, body.ContactNormals, colliders, contact);
                else
                    body.ContactNormals.Clear();
            }
            for (int s = 0; s < constants.Substeps; s++)
            {
                // Predict (velocities). The positions' rigid frame serves the damping and the solve alike.
                RigidFrame frame = RigidFrame.Of(x, body.Masses);
                if (velocityLoss > 0f)
                    RigidMotionDamping.Apply(x, v, body.Masses, velocityLoss, body.Scratch, frame);
                float3 dv = h * constants.Gravity;
                for (int i = 0; i < x.Length; i++)
                    v[i] += dv;
                // The stage sees pinned particles at rest.
                if (body.HasPins)
                    HoldPinned(body.InverseMasses, v);
                // Solve.
                stage.Solve(body, constants, frame, s == constants.Substeps - 1);
                if (body.HasPins)
                    HoldPinned(body.InverseMasses, v);
                // Predict (positions).
                for (int i = 0; i < x.Length; i++)
                    predicted[i] = x[i] + h * v[i];
                // Collide, then update.
                report.Contacts = colliders.Length > 0
                    ? ContactProjection.Project(x, predicted, v, body.ContactNormals, colliders, contact, h)
                    : ClearContacts(body.ContactNormals);
                if (body.HasPins && colliders.Length > 0)
                    HoldPinned(body.InverseMasses, x, predicted, v);
                predicted.CopyTo(x);
            }

            int bad = FindBadParticle(x, v, constants.MaxSpeed);
            if (bad >= 0)
            {
                ResetToLastGoodPlacement(ref stage, body, bad, ref status, ref report);
                return report;
            }

            UpdatePlacement(body, ref status);
            if (constants.SleepSpeed > 0f && MeanSquareSpeed(v, body.Masses) < constants.SleepSpeed * constants.SleepSpeed)
            {
                status.StillTime += constants.Dt;
                if (status.StillTime >= constants.SleepDelay)
                {
                    status.Asleep = true;
                    report.FellAsleep = true;
                    v.Clear();
                }
            }
            else
            {
                status.StillTime = 0f;
            }
            status.StepCount++;
            return report;
        }

        /// <summary>Wakes a sleeping body (call after writing velocities or applying an impulse).</summary>
        public static void Wake(ref ParticleBodyStatus status)
        {
            status.Asleep = false;
            status.StillTime = 0f;
        }

        /// <summary>The origin for a body whose centre is at <paramref name="center"/> (world): zero near the world origin, else the centre rounded to whole metres.</summary>
        public static float3 OriginFor(float3 center) =>
            math.cmax(math.abs(center)) > RebaseDistance && math.all(math.isfinite(center)) ? math.round(center) : float3.zero;

        /// <summary>
        /// Places the rest shape with its centre of mass at <paramref name="position"/> (world), rotated and moving
        /// uniformly, and starts the status there (origin, centre, rotation).
        /// </summary>
        public static void Place(in ParticleBody body, float3 position, quaternion rotation, float3 velocity, out ParticleBodyStatus status)
        {
            status = new ParticleBodyStatus { Center = position, Rotation = math.normalizesafe(rotation) };
            status.Origin = OriginFor(position);
            status.LocalCenter = position - status.Origin;
            PlaceParticles(body, status.LocalCenter, status.Rotation, velocity);
        }

        /// <summary>Rest shape with its centre of mass at <paramref name="center"/> (relative to the origin), rotated, moving uniformly.</summary>
        public static void PlaceParticles(in ParticleBody body, float3 center, quaternion rotation, float3 velocity)
        {
            float3x3 r = new float3x3(rotation);
            for (int i = 0; i < body.ParticleCount; i++)
            {
                body.Positions[i] = center + math.mul(r, body.RestPositions[i] - body.RestCenter);
                body.Velocities[i] = velocity;
            }
        }

        /// <summary>The guard's answer: rest shape at the last good centre and rotation, at rest, reported; the stage resets what it must.</summary>
        static void ResetToLastGoodPlacement<TStage>(ref TStage stage, in ParticleBody body, int badParticle,
            ref ParticleBodyStatus status, ref ParticleStepReport report) where TStage : struct, IParticleSolveStage
        {
            report.Reset = true;
            report.BadParticle = badParticle;
            status.ResetCount++;
            if (!math.all(math.isfinite(status.Center)) || !(math.cmax(math.abs(status.Center)) <= PositionLimit)
                || !Finite.All(status.Rotation.value))
            {
                status.Center = float3.zero;
                status.Rotation = quaternion.identity;
            }
            status.Rotation = math.normalizesafe(status.Rotation);
            status.Origin = OriginFor(status.Center);
            status.LocalCenter = status.Center - status.Origin;
            PlaceParticles(body, status.LocalCenter, status.Rotation, float3.zero);
            stage.OnReset(status.Rotation);
            status.StillTime = 0f;
            status.Asleep = false;
            status.StepCount++;
        }

        /// <summary>
        /// Centre of mass and best-fit rotation of the whole body (warm-started), the placement the guard resets to;
        /// moves the origin (and the positions with it, by whole metres: exact in float32) once the centre is more than
        /// <see cref="RebaseDistance"/> from it.
        /// </summary>
        static void UpdatePlacement(in ParticleBody body, ref ParticleBodyStatus status)
        {
            var x = body.Positions;
            float3 center = ShapeMatching.CenterOfMass(x, body.Masses);
            float3x3 apq = ShapeMatching.Apq(x, body.Masses, center, body.RestPositions, body.RestCenter);
            RotationExtraction.Extract(apq, ref status.Rotation);
            if (math.cmax(math.abs(center)) > RebaseDistance)
            {
                float3 shift = math.round(center);
                for (int i = 0; i < x.Length; i++)
                    x[i] -= shift;
                center -= shift;
                status.Origin += shift;
            }
            status.LocalCenter = center;
            status.Center = status.Origin + center;
        }

        /// <summary>First particle with a non-finite or absurd position or velocity, or −1.</summary>
        static int FindBadParticle(ReadOnlySpan<float3> x, ReadOnlySpan<float3> v, float maxSpeed)
        {
            float speedLimitSq = maxSpeed * maxSpeed;
            const float positionLimitSq = PositionLimit * PositionLimit;
            for (int i = 0; i < x.Length; i++)
            {
                float s2 = math.lengthsq(v[i]);
                // Written so that NaN fails every comparison and is caught.
                if (!(s2 <= speedLimitSq) || !(math.lengthsq(x[i]) <= positionLimitSq))
                    return i;
            }
            return -1;
        }

        /// <summary>Σ mᵢ|vᵢ|² / Σ mᵢ: the body sleeps on its RMS speed, so a few grazing surface particles do not keep it awake.</summary>
        static float MeanSquareSpeed(ReadOnlySpan<float3> v, ReadOnlySpan<float> mass)
        {
            float sum = 0f, m = 0f;
            for (int i = 0; i < v.Length; i++)
            {
                sum += mass[i] * math.lengthsq(v[i]);
                m += mass[i];
            }
            return m > 0f ? sum / m : 0f;
        }

        static bool ShouldWake(in ParticleBody body, in ParticleStepConstants constants, in ContactProjection.Settings contact,
            ReadOnlySpan<ColliderShape> colliders, in ParticleBodyStatus status)
        {
            if (math.any(constants.Gravity != status.LastAcceleration))
                return true;
            // A collider that moved into the body: deeper than a sliver of the particle radius.
            float tolerance = 0.01f * contact.Radius + 1e-6f;
            for (int i = 0; i < body.ParticleCount; i++)
            {
                if (math.any(body.Velocities[i] != float3.zero) || !math.all(math.isfinite(body.Positions[i])))
                    return true;
                for (int c = 0; c < colliders.Length; c++)
                    if (ParticleCollision.Penetration(colliders[c].Translated(-contact.Origin), body.Positions[i], contact.Radius,
                            out _, out float depth) && depth > tolerance)
                        return true;
            }
            return false;
        }

        /// <summary>Pinned particles (wᵢ = 0) do not move: their velocity is zero whatever gravity and the stage added.</summary>
        static void HoldPinned(ReadOnlySpan<float> inverseMass, Span<float3> v)
        {
            for (int i = 0; i < v.Length; i++)
                if (inverseMass[i] == 0f)
                    v[i] = float3.zero;
        }

        /// <summary>A collider does not push a pinned particle either.</summary>
        static void HoldPinned(ReadOnlySpan<float> inverseMass, ReadOnlySpan<float3> x, Span<float3> predicted, Span<float3> v)
        {
            for (int i = 0; i < v.Length; i++)
                if (inverseMass[i] == 0f)
                {
                    predicted[i] = x[i];
                    v[i] = float3.zero;
                }
        }

        static int ClearContacts(Span<float3> normals)
        {
            normals.Clear();
            return 0;
        }
    }
}
