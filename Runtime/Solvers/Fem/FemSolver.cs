using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One step of a finite-element body: linear or quadratic tetrahedra with a co-rotational or stable Neo-Hookean material
    /// (<see cref="FemMaterialModel"/>), advanced by symplectic Euler, implicit Euler or XPBD (<see cref="FemIntegrator"/>)
    /// as the solve stage (<see cref="FemSolveStage"/>) of the shared particle step (<see cref="ParticleBodyStep"/>:
    /// guard, wake and sleep, substeps of predict / solve / collide / update, placement, origin). Damping is the
    /// stiffness-proportional Rayleigh term C = β K, β = 2ζ/ω_ref (<see cref="DampingCoefficient"/>); the shared step's
    /// own velocity damping is off.
    /// </summary>
    public static class FemSolver
    {
        /// <summary>Places the rest shape with its centre of mass at <paramref name="position"/> (world), rotated and moving uniformly; element rotations at the body's.</summary>
        public static void Initialize(in FemModel model, in FemState state, float3 position, quaternion rotation, float3 velocity,
            out ParticleBodyStatus status)
        {
            ParticleBodyStep.Place(Body(model, state), position, rotation, velocity, out status);
            state.Rotations.Fill(status.Rotation);
            state.WarmStart.Clear();
        }

        /// <summary>Wakes a sleeping body (call after writing velocities or applying an impulse).</summary>
        public static void Wake(ref ParticleBodyStatus status) => ParticleBodyStep.Wake(ref status);

        /// <summary>
        /// The integrator that runs for <paramref name="p"/>: XPBD needs the Neo-Hookean model; the co-rotational model with
        /// XPBD runs symplectic Euler and sets <paramref name="fallback"/>. Symplectic and implicit Euler run with both models.
        /// </summary>
        public static FemIntegrator EffectiveIntegrator(in FemParameters p, out bool fallback)
        {
            fallback = p.Integrator == FemIntegrator.Xpbd && p.Model != FemMaterialModel.NeoHookean;
            return fallback ? FemIntegrator.SymplecticEuler : p.Integrator;
        }

        /// <summary>
        /// <see cref="EffectiveIntegrator(in FemParameters, out bool)"/> for <paramref name="model"/>: XPBD's constraints are per
        /// linear tetrahedron, so quadratic elements run implicit Euler instead and set <paramref name="fallback"/>.
        /// </summary>
        public static FemIntegrator EffectiveIntegrator(in FemModel model, in FemParameters p, out bool fallback)
        {
            if (model.IsQuadratic && p.Integrator == FemIntegrator.Xpbd)
            {
                fallback = true;
                return FemIntegrator.ImplicitEuler;
            }
            return EffectiveIntegrator(p, out fallback);
        }

        /// <summary>Reference frequency ω_ref (rad/s): <see cref="FemParameters.DampingFrequency"/>, or the model's estimate when 0.</summary>
        public static float ReferenceFrequency(in FemModel model, in FemParameters p) =>
            p.DampingFrequency > 0f ? p.DampingFrequency : model.DefaultDampingFrequency;

        /// <summary>Rayleigh stiffness coefficient β = 2ζ/ω_ref (s): the mode at ω_ref has damping ratio ζ, a mode at ω has ζω/ω_ref.</summary>
        public static float DampingCoefficient(in FemModel model, in FemParameters p)
        {
            float omega = ReferenceFrequency(model, p);
            return omega > 0f && model.DampingRatio > 0f ? 2f * model.DampingRatio / omega : 0f;
        }

        /// <summary>
        /// The per-step constants of (sanitized) parameters <paramref name="p"/> and step <paramref name="dt"/> for
        /// <paramref name="integrator"/> (the effective one): fixed substeps, no shared velocity damping; for implicit Euler
        /// without friction, contacts kept while touching, which its solve holds on the surface (<see cref="FemImplicitEuler"/>).
        /// </summary>
        public static ParticleStepConstants Constants(in FemParameters p, FemIntegrator integrator, float dt)
        {
            int substeps = math.clamp(p.Body.Substeps, 1, FemParameters.MaxSubsteps);
            ParticleStepConstants constants = ParticleStepConstants.Undamped(dt, substeps, p.Body.Acceleration, p.Body.ParticleRadius, p.Body.Friction,
                p.Body.Restitution, p.Body.MaxDepenetrationSpeed, p.Body.MaxSpeed, p.Body.SleepSpeed, p.Body.SleepDelay);
            constants.Contact.KeepTouching = integrator == FemIntegrator.ImplicitEuler && p.Body.Friction == 0f;
            return constants;
        }

        /// <summary>Advances the body by <paramref name="dt"/> seconds. See the class comment.</summary>
        /// <param name="colliders">Static colliders in world space.</param>
        public static unsafe FemStepReport Step(in FemModel model, in FemParameters parameters, ReadOnlySpan<ColliderShape> colliders,
            float dt, in FemState state, ref ParticleBodyStatus status)
        {
            FemParameters p = parameters.Sanitized();
            FemIntegrator integrator = EffectiveIntegrator(model, p, out bool fallback);
            var report = new FemStepReport { Step = new ParticleStepReport { BadParticle = -1 }, Integrator = integrator,
                IntegratorFallback = fallback, CgConverged = true };
            if (!(dt > 0f) || !math.isfinite(dt) || model.ParticleCount == 0)
                return report;
            ParticleStepConstants constants = Constants(p, integrator, dt);
            ParticleBody body = Body(model, state);
            float beta = DampingCoefficient(model, p);
            fixed (float3* rest = model.RestPositions)
            fixed (float* masses = model.Masses)
            fixed (float* inverseMasses = model.InverseMasses)
            fixed (TetElement* elements = model.Elements)
            fixed (int* incidenceOffsets = model.IncidenceOffsets)
            fixed (int* incidenceSlots = model.IncidenceSlots)
            fixed (int* colorOffsets = model.ColorOffsets)
            fixed (int* colorElements = model.ColorElements)
            fixed (float* stiffness = model.StiffnessDiagonal)
            fixed (quaternion* rotations = state.Rotations)
            fixed (float3* work = state.Work)
            fixed (float3* slots = state.Slots)
            fixed (float3* multipliers = state.Multipliers)
            fixed (float3* tangents = state.Tangents)
            fixed (float3* warmStart = state.WarmStart)
            fixed (int* elementNodes = model.ElementNodes)
            fixed (float3* pointGradients = model.PointGradients)
            fixed (float* pointVolumes = model.PointVolumes)
            fixed (int* factorNodes = model.FactorNodes)
            fixed (int* factorRowStarts = model.FactorRowStarts)
            fixed (float* factorValues = model.FactorValues)
            {
                var stage = new FemSolveStage(rest, masses, inverseMasses, elements, incidenceOffsets, incidenceSlots, colorOffsets,
                    colorElements, stiffness, rotations, work, slots, multipliers, tangents, warmStart, elementNodes, pointGradients,
                    pointVolumes, factorNodes, factorRowStarts, factorValues, model, state, p, integrator, beta);
                report.Step = ParticleBodyStep.Step(ref stage, body, constants, colliders, ref status);
                report.Step.ParametersReplaced = SanitizedParameters.Differ(parameters, p);
                report.MaxCgIterations = stage.MaxCgIterations;
                report.TotalCgIterations = stage.TotalCgIterations;
                report.CgConverged = stage.CgConverged;
                report.MaxCgResidual = stage.MaxCgResidual;
                report.InvertedElements = stage.InvertedElements;
            }
            return report;
        }

        /// <summary>The node arrays of a finite-element body as the shared step sees them.</summary>
        public static ParticleBody Body(in FemModel model, in FemState state) =>
            new ParticleBody(model.RestPositions, model.RestCenter, model.Masses, model.InverseMasses, state.Positions, state.Velocities,
                state.Predicted, state.Forces, state.ContactNormals);
    }
}
