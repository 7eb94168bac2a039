using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One step of a shape-matching body (Müller, Heidelberger, Teschner &amp; Gross 2005, §3.3 and §4),
    /// split into substeps of h = dt / substeps, each:
    /// <list type="number">
    /// <item>predict: vᵢ += h·a, x*ᵢ = xᵢ + h·vᵢ;</item>
    /// <item>solve: goals gᵢ of the predicted positions from the clusters (<see cref="ClusterGoals"/>),
    /// Δᵢ = α_sub (gᵢ − x*ᵢ) (eq. 3), x*ᵢ += Δᵢ, vᵢ += Δᵢ/h (see <c>PullTowardGoals</c>);</item>
    /// <item>collide: x* pushed out of colliders with friction, the push added to v (Δv = Δx/h),
    /// restitution on the normal velocity (<see cref="ContactProjection"/>);</item>
    /// <item>update: xᵢ = x*ᵢ, then damping of the velocity that differs from the body's rigid motion (<see cref="RigidMotionDamping"/>).</item>
    /// </list>
    /// Because goals are reached by a fraction α ≤ 1 of the way, there is no overshoot and the step is
    /// unconditionally stable (§3.3). After the substeps a guard checks every particle: a non-finite
    /// value, a speed above <see cref="ShapeMatchingParameters.MaxSpeed"/> or a position beyond
    /// <see cref="PositionLimit"/> resets the body to its rest shape at its last good placement and is
    /// reported. A body whose particles stay slow (mass-weighted RMS speed) sleeps until a force change, a velocity written
    /// from outside or an overlapping collider wakes it.
    /// The same function runs in the Burst jobs and in the .NET tests; it touches nothing but its arguments.
    /// </summary>
    public static class ShapeMatchingSolver
    {
        /// <summary>Largest accepted distance of a particle from the world origin (m).</summary>
        public const float PositionLimit = 1e6f;

        /// <summary>Places the rest shape with its centre of mass at <paramref name="position"/>, rotated and moving uniformly.</summary>
        public static void Initialize(in ShapeMatchingModel model, in ShapeMatchingState state, float3 position,
            quaternion rotation, float3 velocity, out SoftBodyStatus status)
        {
            status = new SoftBodyStatus { Center = position, Rotation = math.normalizesafe(rotation) };
            PlaceRestShape(model, state, status.Center, status.Rotation, velocity);
        }

        /// <summary>Wakes a sleeping body (call after writing velocities or applying an impulse).</summary>
        public static void Wake(ref SoftBodyStatus status)
        {
            status.Asleep = false;
            status.StillTime = 0f;
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
            if (status.Asleep)
            {
                if (!ShouldWake(model, p, colliders, state, status))
                    return report;
                Wake(ref status);
                report.WokeUp = true;
            }
            // Bad input (written from outside since the last step) is caught before it spreads, with its index.
            int badInput = FindBadParticle(state.Positions, state.Velocities, p.MaxSpeed);
            if (badInput >= 0)
            {
                ResetToLastGoodPlacement(model, state, badInput, ref status, ref report);
                return report;
            }
            report.Stepped = true;
            status.LastAcceleration = p.Acceleration;

            int substeps = p.Substeps;
            float h = dt / substeps;
            // α per substep so that (1 − α_sub)^substeps = 1 − α: the same stiffness for any substep count.
            float alpha = p.Stiffness >= 1f ? 1f : 1f - math.pow(1f - p.Stiffness, 1f / substeps);
            float damping = p.Damping > 0f ? 1f - math.exp(-p.Damping * h) : 0f;
            // Resting contacts must not bounce: ignore approach speeds one substep of acceleration can produce.
            float bounceThreshold = 2f * math.length(p.Acceleration) * h;
            var x = state.Positions;
            var v = state.Velocities;
            var predicted = state.Predicted;

            for (int s = 0; s < substeps; s++)
            {
                // Predict.
                for (int i = 0; i < x.Length; i++)
                {
                    v[i] += h * p.Acceleration;
                    predicted[i] = x[i] + h * v[i];
                }
                // Solve: goals of the predicted positions; plastic flow once per step, on its last substep.
                var counters = ClusterGoals.Compute(model, p, state, predicted, s == substeps - 1 ? dt : 0f);
                PullTowardGoals(model, state, alpha, h);
                report.MaxRotationIterations = math.max(report.MaxRotationIterations, counters.MaxIterations);
                report.PlasticUpdates += counters.PlasticUpdates;
                report.Fallbacks = counters.Fallbacks;
                // Collide (positions and velocities), then update: xᵢ = x*ᵢ.
                report.Contacts = colliders.Length > 0
                    ? ContactProjection.Project(x, predicted, v, state.ContactNormals, colliders, p.ParticleRadius, p.Friction,
                        h, p.Restitution, bounceThreshold)
                    : ClearContacts(state.ContactNormals);
                predicted.CopyTo(x);
                if (damping > 0f)
                    RigidMotionDamping.Apply(x, v, model.Masses, damping, state.Goals);
            }

            int bad = FindBadParticle(x, v, p.MaxSpeed);
            if (bad >= 0)
            {
                ResetToLastGoodPlacement(model, state, bad, ref status, ref report);
                return report;
            }

            UpdatePlacement(model, x, ref status);
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

        /// <summary>
        /// Eq. 3: Δᵢ = α (gᵢ − x*ᵢ), x*ᵢ += Δᵢ, vᵢ += Δᵢ/h. Velocities change only by these small
        /// increments (never as a difference of two positions), so float32 round-off of momentum stays
        /// at the level of the increments. Shape matching is an internal force, so the pull must change
        /// neither momentum nor angular momentum; two projections make that hold exactly:
        /// <list type="bullet">
        /// <item>Σ mᵢ Δᵢ = 0 in exact arithmetic, but the float32 rest offsets do not sum to exactly zero
        /// and that residual is the same every substep: the mass-weighted mean of Δ is removed.</item>
        /// <item>The pull is torque-free about the predicted positions only for rigid goals and an exact
        /// rotation, while angular momentum is carried by xᵢ × vᵢ at the substep's start, which the pull
        /// changes by Σ mᵢ (xᵢ − x_cm) × Δᵢ / h (for a tumbling body −Σ mᵢ vᵢ × Δᵢ, O((hω)²) of the spin
        /// per substep, plus the rotation's stopping tolerance over h). The rigid rotation δθ × (xᵢ − x_cm)
        /// with I δθ = Σ mᵢ (xᵢ − x_cm) × Δᵢ is removed from Δ, positions and velocities alike, so the
        /// pull carries no torque and no velocity is left that the positions do not follow.</item>
        /// </list>
        /// </summary>
        static void PullTowardGoals(in ShapeMatchingModel model, in ShapeMatchingState state, float alpha, float h)
        {
            var x = state.Positions;
            var v = state.Velocities;
            var delta = state.Goals;
            var predicted = state.Predicted;
            float3 drift = float3.zero;
            float mass = 0f;
            for (int i = 0; i < x.Length; i++)
            {
                if (!(model.InverseClusterCounts[i] > 0f))
                    continue;
                delta[i] -= predicted[i];
                drift += model.Masses[i] * delta[i];
                mass += model.Masses[i];
            }
            if (!(mass > 0f))
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
            {
                float3 d = delta[i] - math.cross(spin, x[i] - xcm);
                predicted[i] += d;
                v[i] += d * invH;
            }
        }

        /// <summary>The NaN guard's answer: rest shape at the last good centre and rotation, at rest, reported.</summary>
        static void ResetToLastGoodPlacement(in ShapeMatchingModel model, in ShapeMatchingState state, int badParticle,
            ref SoftBodyStatus status, ref ShapeMatchingStepReport report)
        {
            report.Reset = true;
            report.BadParticle = badParticle;
            status.ResetCount++;
            if (!math.all(math.isfinite(status.Center)) || !(math.lengthsq(status.Center) <= PositionLimit * PositionLimit)
                || !Finite.All(status.Rotation.value))
            {
                status.Center = float3.zero;
                status.Rotation = quaternion.identity;
            }
            status.Rotation = math.normalizesafe(status.Rotation);
            PlaceRestShape(model, state, status.Center, status.Rotation, float3.zero);
            status.StillTime = 0f;
            status.Asleep = false;
            status.StepCount++;
        }

        /// <summary>
        /// Rest shape placed at a centre and rotation, uniform velocity; clusters back to rest (Sₚ = I,
        /// rotation = <paramref name="rotation"/>, the model's rest data and quadratic inverses).
        /// </summary>
        public static void PlaceRestShape(in ShapeMatchingModel model, in ShapeMatchingState state, float3 center,
            quaternion rotation, float3 velocity)
        {
            float3x3 r = new float3x3(rotation);
            for (int i = 0; i < model.ParticleCount; i++)
            {
                state.Positions[i] = center + math.mul(r, model.RestPositions[i] - model.BodyRest.RestCenter);
                state.Velocities[i] = velocity;
            }
            for (int c = 0; c < model.ClusterCount; c++)
                state.Clusters[c] = new ClusterState
                    { Rotation = rotation, PlasticDeformation = float3x3.identity, Rest = model.ClusterRest[c] };
            if (state.QuadraticInverse.Length == model.QuadraticInverse.Length)
                model.QuadraticInverse.CopyTo(state.QuadraticInverse);
        }

        /// <summary>Centre of mass and best-fit rotation of the whole body (warm-started), the placement the guard resets to.</summary>
        static void UpdatePlacement(in ShapeMatchingModel model, ReadOnlySpan<float3> x, ref SoftBodyStatus status)
        {
            float3 center = ShapeMatching.CenterOfMass(x, model.Masses);
            float3x3 apq = ShapeMatching.Apq(x, model.Masses, center, model.RestPositions, model.BodyRest.RestCenter);
            RotationExtraction.Extract(apq, ref status.Rotation);
            status.Center = center;
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
            in ShapeMatchingState state, in SoftBodyStatus status)
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
                    if (ParticleCollision.Penetration(colliders[c], state.Positions[i], p.ParticleRadius, out _, out float depth)
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
