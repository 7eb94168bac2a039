using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One step of a shape-matching body (Müller, Heidelberger, Teschner &amp; Gross 2005, §3.3 and §4) as
    /// the time discretisation of one continuous model,
    /// <code>
    ///   ẍᵢ = a + ω² (gᵢ(x) − xᵢ) − 2ζω (ẋᵢ − uᵢ)
    /// </code>
    /// with gᵢ the goals of the clusters fitted to the positions x, uᵢ = v_cm + Ω × (xᵢ − x_cm) the body's
    /// rigid velocity, ω = 2πf and ζ the material's frequency and damping ratio. A step of dt is split into
    /// n substeps of h = dt / n, with n at least <see cref="ShapeMatchingParameters.Substeps"/> and enough
    /// that ωh ≤ <see cref="ShapeMatchingParameters.MaxSubstepPhase"/>; each substep:
    /// <list type="number">
    /// <item>predict: the non-rigid velocity decays, vᵢ ← uᵢ + D (vᵢ − uᵢ) (<see cref="RigidMotionDamping"/>),
    /// and the external acceleration is added, vᵢ += h·a;</item>
    /// <item>solve: goals gᵢ of the positions xᵢ (<see cref="ClusterGoals"/>), Δᵢ = α (gᵢ − xᵢ) (eq. 3),
    /// vᵢ += Δᵢ / h (see <c>PullTowardGoals</c>), then x*ᵢ = xᵢ + h·vᵢ;</item>
    /// <item>collide: x* pushed out of colliders with friction, the push added to v (Δv = Δx/h),
    /// restitution on the normal velocity, pre-existing overlap left at most
    /// <see cref="ShapeMatchingParameters.MaxDepenetrationSpeed"/> (<see cref="ContactProjection"/>);</item>
    /// <item>update: xᵢ = x*ᵢ.</item>
    /// </list>
    /// α and D come from the exact rule of <see cref="OscillatorDiscretization"/>: a deformation the goals
    /// resist fully oscillates at exactly ω and decays at exactly ζω for any h, and the substep is stable at
    /// any step size. After the substeps a guard checks every particle: a non-finite value, a speed above
    /// <see cref="ShapeMatchingParameters.MaxSpeed"/> or a position beyond <see cref="PositionLimit"/>
    /// resets the body to its rest shape at its last good placement (keeping its plastic rest shape) and is
    /// reported. A body whose particles stay slow (mass-weighted RMS speed) sleeps until a force change, a
    /// velocity written from outside or an overlapping collider wakes it.
    /// Positions are simulated relative to <see cref="SoftBodyStatus.Origin"/>, which follows the body in
    /// whole metres once it is more than <see cref="RebaseDistance"/> from it, so a body 10 km from the world
    /// origin has the float32 resolution of one near it.
    /// The same function runs in the Burst jobs and in the .NET tests; it touches nothing but its arguments.
    /// </summary>
    public static class ShapeMatchingSolver
    {
        /// <summary>Largest accepted distance of a particle from the body's origin, and of the origin from the world origin (m).</summary>
        public const float PositionLimit = 1e6f;

        /// <summary>
        /// Distance (m, per axis) the body's centre may move from <see cref="SoftBodyStatus.Origin"/> before the origin
        /// moves to it. Within it float32 positions resolve 4 µm; bodies that stay within it of the world origin keep
        /// the origin at zero, so their positions are world positions.
        /// </summary>
        public const float RebaseDistance = 64f;

        /// <summary>Places the rest shape with its centre of mass at <paramref name="position"/> (world), rotated and moving uniformly.</summary>
        public static void Initialize(in ShapeMatchingModel model, in ShapeMatchingState state, float3 position,
            quaternion rotation, float3 velocity, out SoftBodyStatus status)
        {
            status = new SoftBodyStatus { Center = position, Rotation = math.normalizesafe(rotation) };
            status.Origin = OriginFor(position);
            status.LocalCenter = position - status.Origin;
            PlaceRestShape(model, state, status.LocalCenter, status.Rotation, velocity);
        }

        /// <summary>Wakes a sleeping body (call after writing velocities or applying an impulse).</summary>
        public static void Wake(ref SoftBodyStatus status)
        {
            status.Asleep = false;
            status.StillTime = 0f;
        }

        /// <summary>
        /// Substeps a step of <paramref name="dt"/> takes with <paramref name="parameters"/>: at least
        /// <see cref="ShapeMatchingParameters.Substeps"/>, and enough that ω·h ≤ <see cref="ShapeMatchingParameters.MaxSubstepPhase"/>
        /// (at most <see cref="ShapeMatchingParameters.MaxSubsteps"/>).
        /// </summary>
        public static int SubstepCount(in ShapeMatchingParameters parameters, float dt)
        {
            ShapeMatchingParameters p = parameters.Sanitized();
            return OscillatorDiscretization.SubstepsFor(p.AngularFrequency, dt, p.Substeps, p.MaxSubstepPhase,
                ShapeMatchingParameters.MaxSubsteps);
        }

        /// <summary>Advances the body by <paramref name="dt"/> seconds. See the class comment for the algorithm.</summary>
        /// <param name="colliders">Static colliders in world space.</param>
        public static ShapeMatchingStepReport Step(in ShapeMatchingModel model, in ShapeMatchingParameters parameters,
            ReadOnlySpan<ColliderShape> colliders, float dt, in ShapeMatchingState state, ref SoftBodyStatus status)
        {
            var report = new ShapeMatchingStepReport { BadParticle = -1 };
            if (!(dt > 0f) || !math.isfinite(dt) || model.ParticleCount == 0)
                return report;
            ShapeMatchingParameters p = parameters.Sanitized();
            float3 origin = status.Origin;
            if (status.Asleep)
            {
                if (!ShouldWake(model, p, colliders, origin, state, status))
                    return report;
                Wake(ref status);
                report.WokeUp = true;
            }
            // Bad input (written from outside since the last step) is caught before it spreads, with its index.
            int badInput = FindBadParticle(state.Positions, state.Velocities, p.MaxSpeed);
            if (badInput >= 0 || !(math.cmax(math.abs(origin)) <= PositionLimit))
            {
                ResetToLastGoodPlacement(model, state, math.max(badInput, 0), ref status, ref report);
                return report;
            }
            report.Stepped = true;
            status.LastAcceleration = p.Acceleration;

            float omega = p.AngularFrequency;
            int substeps = OscillatorDiscretization.SubstepsFor(omega, dt, p.Substeps, p.MaxSubstepPhase,
                ShapeMatchingParameters.MaxSubsteps);
            float h = dt / substeps;
            OscillatorDiscretization.Coefficients k = OscillatorDiscretization.Compute(omega, p.DampingRatio, h);
            report.Substeps = substeps;
            float velocityLoss = 1f - k.VelocityRetention;
            // Resting contacts must not bounce: ignore approach speeds one substep of acceleration can produce.
            float bounceThreshold = 2f * math.length(p.Acceleration) * h;
            var contact = new ContactProjection.Settings
            {
                Radius = p.ParticleRadius, Friction = p.Friction, Restitution = p.Restitution,
                BounceThreshold = bounceThreshold, MaxDepenetration = p.MaxDepenetrationSpeed * h, Origin = origin,
            };
            var x = state.Positions;
            var v = state.Velocities;
            var predicted = state.Predicted;

            for (int s = 0; s < substeps; s++)
            {
                // Predict (velocities): the non-rigid velocity decays, v ← u + D (v − u); the external acceleration acts.
                if (velocityLoss > 0f)
                    RigidMotionDamping.Apply(x, v, model.Masses, velocityLoss, state.Goals);
                for (int i = 0; i < x.Length; i++)
                    v[i] += h * p.Acceleration;
                // Solve: goals of the positions xᵢ; plastic flow once per step, on its last substep.
                var counters = ClusterGoals.Compute(model, p, state, x, s == substeps - 1 ? dt : 0f);
                PullTowardGoals(model, state, k.Pull, h);
                report.MaxRotationIterations = math.max(report.MaxRotationIterations, counters.MaxIterations);
                report.PlasticUpdates += counters.PlasticUpdates;
                report.Fallbacks = counters.Fallbacks;
                report.PlasticityUnavailable |= counters.PlasticityUnavailable;
                // Predict (positions): x* = x + h v.
                for (int i = 0; i < x.Length; i++)
                    predicted[i] = x[i] + h * v[i];
                // Collide (positions and velocities), then update: xᵢ = x*ᵢ.
                report.Contacts = colliders.Length > 0
                    ? ContactProjection.Project(x, predicted, v, state.ContactNormals, colliders, contact, h)
                    : ClearContacts(state.ContactNormals);
                predicted.CopyTo(x);
            }

            int bad = FindBadParticle(x, v, p.MaxSpeed);
            if (bad >= 0)
            {
                ResetToLastGoodPlacement(model, state, bad, ref status, ref report);
                return report;
            }

            UpdatePlacement(model, state, ref status);
            if (p.SleepSpeed > 0f && MeanSquareSpeed(v, model.Masses) < p.SleepSpeed * p.SleepSpeed)
            {
                status.StillTime += dt;
                if (status.StillTime >= p.SleepDelay)
                {
                    status.Asleep = true;
                    report.FellAsleep = true;
                    for (int i = 0; i < v.Length; i++)
                        v[i] = float3.zero;
                }
            }
            else
            {
                status.StillTime = 0f;
            }
            status.StepCount++;
            return report;
        }

        /// <summary>The origin for a body whose centre is at <paramref name="center"/> (world): zero near the world origin, else the centre rounded to whole metres.</summary>
        public static float3 OriginFor(float3 center) =>
            math.cmax(math.abs(center)) > RebaseDistance && math.all(math.isfinite(center)) ? math.round(center) : float3.zero;

        /// <summary>
        /// Eq. 3 as a velocity change: Δᵢ = α (gᵢ − xᵢ), vᵢ += Δᵢ / h, so the position the substep then
        /// predicts, xᵢ + h vᵢ, has moved by Δᵢ toward the goal. Shape matching is an internal force, so the pull
        /// must change neither momentum nor angular momentum; two projections make that hold to round-off:
        /// <list type="bullet">
        /// <item>Σ mᵢ Δᵢ = 0 in exact arithmetic, but the float32 rest offsets do not sum to exactly zero
        /// and that residual is the same every substep: the mass-weighted mean of Δ is removed.</item>
        /// <item>The pull is torque-free about x_cm in exact arithmetic (Σ mᵢ gᵢ pᵢᵀ is symmetric for the
        /// polar rotation and for A = A_pq A_qq⁻¹), but not to the rotation's stopping tolerance and float32
        /// round-off. The rigid rotation δθ × (xᵢ − x_cm) with I δθ = Σ mᵢ (xᵢ − x_cm) × Δᵢ is removed.</item>
        /// </list>
        /// </summary>
        static void PullTowardGoals(in ShapeMatchingModel model, in ShapeMatchingState state, float alpha, float h)
        {
            var x = state.Positions;
            var v = state.Velocities;
            var delta = state.Goals;
            float3 drift = float3.zero;
            float mass = 0f;
            for (int i = 0; i < x.Length; i++)
            {
                if (!(model.InverseClusterCounts[i] > 0f))
                    continue;
                delta[i] -= x[i];
                drift += model.Masses[i] * delta[i];
                mass += model.Masses[i];
            }
            if (!(mass > 0f) || !(alpha > 0f))
                return;
            drift /= mass;
            float3 xcm = ShapeMatching.CenterOfMass(x, model.Masses);
            float3 torque = float3.zero;
            for (int i = 0; i < x.Length; i++)
            {
                delta[i] = model.InverseClusterCounts[i] > 0f ? alpha * (delta[i] - drift) : float3.zero;
                torque += model.Masses[i] * math.cross(x[i] - xcm, delta[i]);
            }
            float3 spin = math.mul(RigidMotionDamping.InverseInertia(x, model.Masses, xcm), torque);
            if (!math.all(math.isfinite(spin)))
                spin = float3.zero;
            float invH = 1f / h;
            for (int i = 0; i < x.Length; i++)
                v[i] += (delta[i] - math.cross(spin, x[i] - xcm)) * invH;
        }

        /// <summary>
        /// The NaN guard's answer: rest shape at the last good centre and rotation, at rest, reported. Each
        /// cluster keeps its plastic rest shape (Sₚ, A_qq⁻¹, quadratic inverse) when it is finite: the guard undoes
        /// a broken state, not the body's history.
        /// </summary>
        static void ResetToLastGoodPlacement(in ShapeMatchingModel model, in ShapeMatchingState state, int badParticle,
            ref SoftBodyStatus status, ref ShapeMatchingStepReport report)
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
            PlaceParticles(model, state, status.LocalCenter, status.Rotation, float3.zero);
            bool quadraticFinite = Finite.All(state.QuadraticInverse);
            for (int c = 0; c < model.ClusterCount; c++)
            {
                ref ClusterState cluster = ref state.Clusters[c];
                bool plasticFinite = Finite.All(cluster.PlasticDeformation) && Finite.All(cluster.Rest.AqqInverse)
                                     && math.determinant(cluster.PlasticDeformation) > 0f;
                if (plasticFinite)
                    cluster.Rotation = status.Rotation;
                else
                    cluster = new ClusterState { Rotation = status.Rotation, PlasticDeformation = float3x3.identity, Rest = model.ClusterRest[c] };
            }
            if (!quadraticFinite && state.QuadraticInverse.Length == model.QuadraticInverse.Length)
                model.QuadraticInverse.CopyTo(state.QuadraticInverse);
            status.StillTime = 0f;
            status.Asleep = false;
            status.StepCount++;
        }

        /// <summary>
        /// Rest shape placed with its centre of mass at <paramref name="center"/> (relative to the body's
        /// <see cref="SoftBodyStatus.Origin"/>) and rotation, uniform velocity; clusters back to rest (Sₚ = I,
        /// rotation = <paramref name="rotation"/>, the model's rest data and quadratic inverses).
        /// </summary>
        public static void PlaceRestShape(in ShapeMatchingModel model, in ShapeMatchingState state, float3 center,
            quaternion rotation, float3 velocity)
        {
            PlaceParticles(model, state, center, rotation, velocity);
            for (int c = 0; c < model.ClusterCount; c++)
                state.Clusters[c] = new ClusterState
                    { Rotation = rotation, PlasticDeformation = float3x3.identity, Rest = model.ClusterRest[c] };
            if (state.QuadraticInverse.Length == model.QuadraticInverse.Length)
                model.QuadraticInverse.CopyTo(state.QuadraticInverse);
        }

        static void PlaceParticles(in ShapeMatchingModel model, in ShapeMatchingState state, float3 center,
            quaternion rotation, float3 velocity)
        {
            float3x3 r = new float3x3(rotation);
            for (int i = 0; i < model.ParticleCount; i++)
            {
                state.Positions[i] = center + math.mul(r, model.RestPositions[i] - model.BodyRest.RestCenter);
                state.Velocities[i] = velocity;
            }
        }

        /// <summary>
        /// Centre of mass and best-fit rotation of the whole body (warm-started), the placement the guard resets to;
        /// moves the origin (and the positions with it, by whole metres: exact in float32) once the centre is more than
        /// <see cref="RebaseDistance"/> from it.
        /// </summary>
        static void UpdatePlacement(in ShapeMatchingModel model, in ShapeMatchingState state, ref SoftBodyStatus status)
        {
            var x = state.Positions;
            float3 center = ShapeMatching.CenterOfMass(x, model.Masses);
            float3x3 apq = ShapeMatching.Apq(x, model.Masses, center, model.RestPositions, model.BodyRest.RestCenter);
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

        static bool ShouldWake(in ShapeMatchingModel model, in ShapeMatchingParameters p, ReadOnlySpan<ColliderShape> colliders,
            float3 origin, in ShapeMatchingState state, in SoftBodyStatus status)
        {
            if (math.any(p.Acceleration != status.LastAcceleration))
                return true;
            // A collider that moved into the body: deeper than a sliver of the particle radius.
            float tolerance = 0.01f * p.ParticleRadius + 1e-6f;
            for (int i = 0; i < state.Positions.Length; i++)
            {
                if (math.any(state.Velocities[i] != float3.zero) || !math.all(math.isfinite(state.Positions[i])))
                    return true;
                for (int c = 0; c < colliders.Length; c++)
                    if (ParticleCollision.Penetration(colliders[c].Translated(-origin), state.Positions[i], p.ParticleRadius, out _, out float depth)
                        && depth > tolerance)
                        return true;
            }
            return false;
        }

        static int ClearContacts(Span<float3> normals)
        {
            normals.Clear();
            return 0;
        }
    }
}
