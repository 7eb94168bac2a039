using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One step of a mass-spring body (Teschner et al. 2003): the shared particle step (<see cref="ParticleBodyStep"/>:
    /// guard, wake and sleep, substeps of predict / solve / collide / update, placement, origin) with the springs as
    /// its solve stage (<see cref="MassSpringSolveStage"/>). The shared step's own velocity damping is off
    /// (retention 1): the dashpots of the springs are the only damping. A step of dt is
    /// <see cref="ParticleBodySettings.Substeps"/> substeps of h = dt / substeps.
    /// </summary>
    public static class MassSpringSolver
    {
        /// <summary>Places the rest shape with its centre of mass at <paramref name="position"/> (world), rotated and moving uniformly.</summary>
        public static void Initialize(in MassSpringModel model, in MassSpringState state, float3 position, quaternion rotation,
            float3 velocity, out ParticleBodyStatus status) =>
            ParticleBodyStep.Place(Body(model, state), position, rotation, velocity, out status);

        /// <summary>Wakes a sleeping body (call after writing velocities or applying an impulse).</summary>
        public static void Wake(ref ParticleBodyStatus status) => ParticleBodyStep.Wake(ref status);

        /// <summary>The per-step constants for (sanitized) parameters <paramref name="p"/> and step <paramref name="dt"/>: no pull, retention 1.</summary>
        public static ParticleStepConstants Constants(in MassSpringParameters p, float dt)
        {
            int substeps = math.clamp(p.Body.Substeps, 1, MassSpringParameters.MaxSubsteps);
            return ParticleStepConstants.Undamped(dt, substeps, p.Body.Acceleration, p.Body.ParticleRadius, p.Body.Friction, p.Body.Restitution,
                p.Body.MaxDepenetrationSpeed, p.Body.MaxSpeed, p.Body.SleepSpeed, p.Body.SleepDelay);
        }

        /// <summary>Advances the body by <paramref name="dt"/> seconds (see the class comment).</summary>
        /// <param name="colliders">Static colliders in world space.</param>
        public static ParticleStepReport Step(in MassSpringModel model, in MassSpringParameters parameters,
            ReadOnlySpan<ColliderShape> colliders, float dt, in MassSpringState state, ref ParticleBodyStatus status) =>
            Step(model, parameters, colliders, dt, state, ref status, 0);

        /// <summary>
        /// As <see cref="Step(in MassSpringModel, in MassSpringParameters, ReadOnlySpan{ColliderShape}, float, in MassSpringState, ref ParticleBodyStatus)"/>,
        /// with the per-spring and per-particle passes run in batches of <paramref name="batch"/> (0 = one batch): the
        /// split a job system would make. The result has the same bits for every batch size.
        /// </summary>
        public static unsafe ParticleStepReport Step(in MassSpringModel model, in MassSpringParameters parameters,
            ReadOnlySpan<ColliderShape> colliders, float dt, in MassSpringState state, ref ParticleBodyStatus status, int batch)
        {
            if (!(dt > 0f) || !math.isfinite(dt) || model.ParticleCount == 0)
                return new ParticleStepReport { BadParticle = -1 };
            MassSpringParameters p = parameters.Sanitized();
            ParticleStepConstants constants = Constants(p, dt);
            ParticleBody body = Body(model, state);
            fixed (float3* rest = model.RestPositions)
            fixed (float* masses = model.Masses)
            fixed (float* inverseMasses = model.InverseMasses)
            fixed (Spring* springs = model.Springs)
            fixed (int* offsets = model.IncidenceOffsets)
            fixed (int* slots = model.IncidenceSlots)
            fixed (int* colorOffsets = model.ColorOffsets)
            fixed (int* colorSprings = model.ColorSprings)
            fixed (float3* scratch = state.Scratch)
            fixed (float3* springScratch = state.SpringScratch)
            {
                var stage = new MassSpringSolveStage(rest, masses, inverseMasses, springs, offsets, slots, colorOffsets, colorSprings,
                    scratch, springScratch, model.ParticleCount, model.SpringCount, model.ColorCount, p) { Batch = batch };
                ParticleStepReport report = ParticleBodyStep.Step(ref stage, body, constants, colliders, ref status);
                report.ParametersReplaced = SanitizedParameters.Differ(parameters, p);
                return report;
            }
        }

        /// <summary>The particle arrays of a mass-spring body as the shared step sees them (with the pins' inverse masses).</summary>
        public static ParticleBody Body(in MassSpringModel model, in MassSpringState state)
        {
            int n = state.Positions.Length;
            bool scratch = state.Scratch.Length >= MassSpringState.ScratchPerParticle * n;
            return new ParticleBody(model.RestPositions, model.RestCenter, model.Masses, model.InverseMasses, state.Positions,
                state.Velocities, scratch ? state.Predicted : default, scratch ? state.Block(2) : default,
                scratch ? state.ContactNormals : default);
        }
    }
}
