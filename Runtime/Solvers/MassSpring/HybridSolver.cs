using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// A hybrid body: shape matching and a spring network on the same particles, one
    /// <see cref="CompositeSolveStage{TFirst,TSecond}"/> of <see cref="ShapeMatchingSolveStage"/> then
    /// <see cref="MassSpringSolveStage"/>. The substeps, the shape-matching pull and its damping of the non-rigid
    /// velocity come from the shape-matching parameters (<see cref="ShapeMatchingSolver.Constants"/>); the springs add
    /// their forces with <see cref="MassSpringParameters.Integrator"/> (its substep count is not used). Both models
    /// must describe the same particles with the same masses.
    /// </summary>
    public static class HybridSolver
    {
        /// <summary>Advances the body by <paramref name="dt"/> seconds.</summary>
        /// <param name="shapeState">Positions, velocities, clusters and the shape-matching scratch.</param>
        /// <param name="springState">Only its scratch is used (<see cref="MassSpringState.Scratch"/>, <see cref="MassSpringState.SpringScratch"/>).</param>
        public static unsafe ParticleStepReport Step(in ShapeMatchingModel shapeModel, in ShapeMatchingParameters shapeParameters,
            in ShapeMatchingState shapeState, in MassSpringModel springModel, in MassSpringParameters springParameters,
            in MassSpringState springState, ReadOnlySpan<ColliderShape> colliders, float dt, ref ParticleBodyStatus status)
        {
            if (!(dt > 0f) || !math.isfinite(dt) || shapeModel.ParticleCount == 0 || springModel.ParticleCount != shapeModel.ParticleCount)
                return new ParticleStepReport { BadParticle = -1 };
            ShapeMatchingParameters sp = shapeParameters.Sanitized();
            MassSpringParameters mp = springParameters.Sanitized();
            ParticleStepConstants constants = ShapeMatchingSolver.Constants(sp, dt);
            var body = new ParticleBody(shapeModel.RestPositions, shapeModel.BodyRest.RestCenter, shapeModel.Masses,
                springModel.InverseMasses, shapeState.Positions, shapeState.Velocities, shapeState.Predicted, shapeState.Goals,
                shapeState.ContactNormals);
            fixed (float3* rest = shapeModel.RestPositions)
            fixed (float* masses = shapeModel.Masses)
            fixed (float* inverseCounts = shapeModel.InverseClusterCounts)
            fixed (int* offsets = shapeModel.ClusterOffsets)
            fixed (int* members = shapeModel.ClusterParticles)
            fixed (float* weights = shapeModel.ClusterWeights)
            fixed (ClusterRestData* clusterRest = shapeModel.ClusterRest)
            fixed (float3x3* modelQuadratic = shapeModel.QuadraticInverse)
            fixed (ClusterState* clusters = shapeState.Clusters)
            fixed (float3x3* stateQuadratic = shapeState.QuadraticInverse)
            fixed (float3* springRest = springModel.RestPositions)
            fixed (float* springMasses = springModel.Masses)
            fixed (float* inverseMasses = springModel.InverseMasses)
            fixed (Spring* springs = springModel.Springs)
            fixed (int* incidenceOffsets = springModel.IncidenceOffsets)
            fixed (int* slots = springModel.IncidenceSlots)
            fixed (int* colorOffsets = springModel.ColorOffsets)
            fixed (int* colorSprings = springModel.ColorSprings)
            fixed (float3* scratch = springState.Scratch)
            fixed (float3* springScratch = springState.SpringScratch)
            {
                var stage = new CompositeSolveStage<ShapeMatchingSolveStage, MassSpringSolveStage>(
                    new ShapeMatchingSolveStage(rest, masses, inverseCounts, offsets, members, weights, clusterRest, modelQuadratic,
                        clusters, stateQuadratic, shapeModel, shapeState, sp),
                    new MassSpringSolveStage(springRest, springMasses, inverseMasses, springs, incidenceOffsets, slots, colorOffsets,
                        colorSprings, scratch, springScratch, springModel.ParticleCount, springModel.SpringCount, springModel.ColorCount, mp));
                ParticleStepReport report = ParticleBodyStep.Step(ref stage, body, constants, colliders, ref status);
                report.ParametersReplaced = SanitizedParameters.Differ(shapeParameters, sp) || SanitizedParameters.Differ(springParameters, mp);
                return report;
            }
        }
    }
}
