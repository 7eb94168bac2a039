using SoftBodyDynamics.Solvers;
using Unity.Entities;
using Unity.Transforms;

namespace SoftBodyDynamics
{
    /// <summary>
    /// The components a simulated soft body carries, for bodies created from code (bakers add the same
    /// set with <c>IBaker</c>): shape, settings, state, the particle (and cluster or element) buffers, an enabled
    /// <see cref="SoftBodyUninitialized"/> and a disabled <see cref="SoftBodyImpulse"/>, for each method.
    /// </summary>
    public static class SoftBodyArchetype
    {
        /// <summary>
        /// True when a body needs its own <see cref="SoftBodyQuadraticInverse"/> buffer: quadratic mode with
        /// plasticity on a blob built with the quadratic inverses.
        /// </summary>
        /// <param name="parameters">The body's parameters.</param>
        /// <param name="quadraticBlocks">Length of <see cref="SoftBodyShapeBlob.QuadraticInverse"/>.</param>
        public static bool NeedsQuadraticInverse(in ShapeMatchingParameters parameters, int quadraticBlocks) =>
            parameters.Mode == ShapeMatchingMode.Quadratic && parameters.Plasticity.Enabled && quadraticBlocks > 0;

        /// <summary>
        /// Makes <paramref name="entity"/> a soft body of <paramref name="shape"/>. The rest shape is placed at
        /// the entity's <see cref="LocalTransform"/> (identity is added when it has none) by the next update
        /// of <see cref="SoftBodyInitializationSystem"/>. Structural change: call it on the main thread.
        /// </summary>
        /// <param name="entityManager">The world's entity manager.</param>
        /// <param name="entity">A root entity (soft bodies simulate in world space).</param>
        /// <param name="shape">The blob; the caller keeps ownership of it.</param>
        /// <param name="parameters">The body's tunables.</param>
        public static void AddComponents(EntityManager entityManager, Entity entity, BlobAssetReference<SoftBodyShapeBlob> shape,
            in ShapeMatchingParameters parameters)
        {
            entityManager.AddComponentData(entity, new SoftBodyShape { Blob = shape });
            entityManager.AddComponentData(entity, new SoftBodySettings { Value = parameters });
            entityManager.AddComponentData(entity, new SoftBodyState { LastReport = new ShapeMatchingStepReport { BadParticle = -1 } });
            entityManager.AddBuffer<SoftBodyPosition>(entity);
            entityManager.AddBuffer<SoftBodyVelocity>(entity);
            entityManager.AddBuffer<SoftBodyCluster>(entity);
            if (NeedsQuadraticInverse(parameters, shape.Value.QuadraticInverse.Length))
                entityManager.AddBuffer<SoftBodyQuadraticInverse>(entity);
            entityManager.AddComponent<SoftBodyUninitialized>(entity);
            entityManager.SetComponentEnabled<SoftBodyUninitialized>(entity, true);
            entityManager.AddComponent<SoftBodyImpulse>(entity);
            entityManager.SetComponentEnabled<SoftBodyImpulse>(entity, false);
            if (!entityManager.HasComponent<LocalTransform>(entity))
                entityManager.AddComponentData(entity, LocalTransform.Identity);
        }

        /// <summary>
        /// Makes <paramref name="entity"/> a mass-spring body of <paramref name="shape"/>, placed at its
        /// <see cref="LocalTransform"/> by the next update of <see cref="MassSpringSimulationSystem"/>. Structural change:
        /// call it on the main thread.
        /// </summary>
        /// <param name="entityManager">The world's entity manager.</param>
        /// <param name="entity">A root entity (bodies simulate in world space).</param>
        /// <param name="shape">The blob; the caller keeps ownership of it.</param>
        /// <param name="parameters">The body's tunables.</param>
        public static void AddMassSpringComponents(EntityManager entityManager, Entity entity, BlobAssetReference<MassSpringShapeBlob> shape,
            in MassSpringParameters parameters)
        {
            entityManager.AddComponentData(entity, new MassSpringShape { Blob = shape });
            entityManager.AddComponentData(entity, new MassSpringSettings { Value = parameters });
            AddParticleBodyComponents(entityManager, entity);
        }

        /// <summary>
        /// Makes <paramref name="entity"/> a finite-element body of <paramref name="shape"/>, placed at its
        /// <see cref="LocalTransform"/> by the next update of <see cref="FemSimulationSystem"/>. Structural change: call it
        /// on the main thread.
        /// </summary>
        /// <param name="entityManager">The world's entity manager.</param>
        /// <param name="entity">A root entity (bodies simulate in world space).</param>
        /// <param name="shape">The blob; the caller keeps ownership of it.</param>
        /// <param name="parameters">The body's tunables.</param>
        public static void AddFemComponents(EntityManager entityManager, Entity entity, BlobAssetReference<FemShapeBlob> shape,
            in FemParameters parameters)
        {
            entityManager.AddComponentData(entity, new FemShape { Blob = shape });
            entityManager.AddComponentData(entity, new FemSettings { Value = parameters });
            entityManager.AddComponentData(entity, new FemDiagnostics());
            entityManager.AddBuffer<FemElementRotation>(entity);
            AddParticleBodyComponents(entityManager, entity);
        }

        /// <summary>What mass-spring and FEM bodies share: state, particle buffers, an enabled uninitialized tag, a disabled impulse.</summary>
        static void AddParticleBodyComponents(EntityManager entityManager, Entity entity)
        {
            entityManager.AddComponentData(entity, ParticleBodyState.Unstepped);
            entityManager.AddBuffer<SoftBodyPosition>(entity);
            entityManager.AddBuffer<SoftBodyVelocity>(entity);
            entityManager.AddComponent<SoftBodyUninitialized>(entity);
            entityManager.SetComponentEnabled<SoftBodyUninitialized>(entity, true);
            entityManager.AddComponent<SoftBodyImpulse>(entity);
            entityManager.SetComponentEnabled<SoftBodyImpulse>(entity, false);
            if (!entityManager.HasComponent<LocalTransform>(entity))
                entityManager.AddComponentData(entity, LocalTransform.Identity);
        }
    }
}
