using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One step of a shape-matching body (Müller, Heidelberger, Teschner &amp; Gross 2005, §3.3 and §4) as the
    /// time discretisation of one continuous model,
    /// <code>
    ///   ẍᵢ = a + ω² (gᵢ(x) − xᵢ) − 2ζω (ẋᵢ − uᵢ)
    /// </code>
    /// with gᵢ the goals of the clusters fitted to the positions x, uᵢ = v_cm + Ω × (xᵢ − x_cm) the body's rigid
    /// velocity, ω = 2πf and ζ the material's frequency and damping ratio. The step is the shared particle-body step
    /// (<see cref="ParticleBodyStep"/>: guard, wake and sleep, substeps of predict / solve / collide / update,
    /// placement, origin) with shape matching as its solve stage (<see cref="ShapeMatchingSolveStage"/>). A step of dt
    /// takes at least <see cref="ParticleBodySettings.Substeps"/> substeps, and enough that
    /// ωh ≤ <see cref="ShapeMatchingParameters.MaxSubstepPhase"/>; the pull α and the velocity retention D of a
    /// substep come from the exact rule of <see cref="OscillatorDiscretization"/>, so a deformation the goals resist
    /// fully oscillates at exactly ω and decays at exactly ζω for any h, and the substep is stable at any step size.
    /// </summary>
    public static class ShapeMatchingSolver
    {
        /// <summary>Largest accepted distance of a particle from the body's origin, and of the origin from the world origin (m).</summary>
        public const float PositionLimit = ParticleBodyStep.PositionLimit;

        /// <summary>See <see cref="ParticleBodyStep.RebaseDistance"/>.</summary>
        public const float RebaseDistance = ParticleBodyStep.RebaseDistance;

        /// <summary>Places the rest shape with its centre of mass at <paramref name="position"/> (world), rotated and moving uniformly; clusters at rest.</summary>
        public static void Initialize(in ShapeMatchingModel model, in ShapeMatchingState state, float3 position,
            quaternion rotation, float3 velocity, out ParticleBodyStatus status)
        {
            ParticleBodyStep.Place(Body(model, state), position, rotation, velocity, out status);
            ResetClusters(model, state, status.Rotation);
        }

        /// <summary>Wakes a sleeping body (call after writing velocities or applying an impulse).</summary>
        public static void Wake(ref ParticleBodyStatus status) => ParticleBodyStep.Wake(ref status);

        /// <summary>
        /// Substeps a step of <paramref name="dt"/> takes with <paramref name="parameters"/>: at least
        /// <see cref="ParticleBodySettings.Substeps"/>, and enough that ω·h ≤ <see cref="ShapeMatchingParameters.MaxSubstepPhase"/>
        /// (at most <see cref="ShapeMatchingParameters.MaxSubsteps"/>).
        /// </summary>
        public static int SubstepCount(in ShapeMatchingParameters parameters, float dt) => Constants(parameters.Sanitized(), dt).Substeps;

        /// <summary>The per-step constants of a body with (sanitized) parameters <paramref name="p"/> and step <paramref name="dt"/>.</summary>
        public static ParticleStepConstants Constants(in ShapeMatchingParameters p, float dt)
        {
            ParticleStepConstants k = ParticleStepConstants.For(dt, p.AngularFrequency, p.DampingRatio, p.Body.Substeps,
                p.MaxSubstepPhase, ShapeMatchingParameters.MaxSubsteps, p.Body.Acceleration);
            k.Contact.Radius = p.Body.ParticleRadius;
            k.Contact.Friction = p.Body.Friction;
            k.Contact.Restitution = p.Body.Restitution;
            k.Contact.MaxDepenetration = p.Body.MaxDepenetrationSpeed * k.H;
            k.MaxSpeed = p.Body.MaxSpeed;
            k.SleepSpeed = p.Body.SleepSpeed;
            k.SleepDelay = p.Body.SleepDelay;
            return k;
        }

        /// <summary>Advances the body by <paramref name="dt"/> seconds. See the class comment for the algorithm.</summary>
        /// <param name="colliders">Static colliders in world space.</param>
        public static unsafe ShapeMatchingStepReport Step(in ShapeMatchingModel model, in ShapeMatchingParameters parameters,
            ReadOnlySpan<ColliderShape> colliders, float dt, in ShapeMatchingState state, ref ParticleBodyStatus status)
        {
            if (!(dt > 0f) || !math.isfinite(dt) || model.ParticleCount == 0)
                return new ShapeMatchingStepReport { BadParticle = -1 };
            ShapeMatchingParameters p = parameters.Sanitized();
            ParticleStepConstants constants = Constants(p, dt);
            ParticleBody body = Body(model, state);
            fixed (float3* rest = model.RestPositions)
            fixed (float* masses = model.Masses)
            fixed (float* inverseCounts = model.InverseClusterCounts)
            fixed (int* offsets = model.ClusterOffsets)
            fixed (int* members = model.ClusterParticles)
            fixed (float* weights = model.ClusterWeights)
            fixed (ClusterRestData* clusterRest = model.ClusterRest)
            fixed (float3x3* modelQuadratic = model.QuadraticInverse)
            fixed (ClusterState* clusters = state.Clusters)
            fixed (float3x3* stateQuadratic = state.QuadraticInverse)
            {
                var stage = new ShapeMatchingSolveStage(rest, masses, inverseCounts, offsets, members, weights, clusterRest,
                    modelQuadratic, clusters, stateQuadratic, model, state, p);
                ParticleStepReport r = ParticleBodyStep.Step(ref stage, body, constants, colliders, ref status);
                return new ShapeMatchingStepReport
                {
                    Stepped = r.Stepped, WokeUp = r.WokeUp, FellAsleep = r.FellAsleep, Reset = r.Reset, BadParticle = r.BadParticle,
                    Contacts = r.Contacts, Substeps = r.Substeps, Fallbacks = stage.Fallbacks,
                    MaxRotationIterations = stage.MaxRotationIterations, PlasticUpdates = stage.PlasticUpdates,
                    PlasticityUnavailable = stage.PlasticityUnavailable,
                    ParametersReplaced = SanitizedParameters.Differ(parameters, p),
                };
            }
        }

        /// <summary>
        /// Rest shape placed with its centre of mass at <paramref name="center"/> (relative to the body's
        /// <see cref="ParticleBodyStatus.Origin"/>) and rotation, uniform velocity; clusters back to rest (Sₚ = I,
        /// rotation = <paramref name="rotation"/>, the model's rest data and quadratic inverses).
        /// </summary>
        public static void PlaceRestShape(in ShapeMatchingModel model, in ShapeMatchingState state, float3 center,
            quaternion rotation, float3 velocity)
        {
            ParticleBodyStep.PlaceParticles(Body(model, state), center, rotation, velocity);
            ResetClusters(model, state, rotation);
        }

        /// <summary>The particle arrays of a shape-matching body as the shared step sees them.</summary>
        public static ParticleBody Body(in ShapeMatchingModel model, in ShapeMatchingState state) =>
            new ParticleBody(model.RestPositions, model.BodyRest.RestCenter, model.Masses, model.InverseMasses, state.Positions,
                state.Velocities, state.Predicted, state.Goals, state.ContactNormals);

        static void ResetClusters(in ShapeMatchingModel model, in ShapeMatchingState state, quaternion rotation)
        {
            for (int c = 0; c < model.ClusterCount; c++)
                state.Clusters[c] = new ClusterState
                    { Rotation = rotation, PlasticDeformation = float3x3.identity, Rest = model.ClusterRest[c] };
            if (state.QuadraticInverse.Length == model.QuadraticInverse.Length)
                model.QuadraticInverse.CopyTo(state.QuadraticInverse);
        }
    }
}
