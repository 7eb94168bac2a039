using SoftBodyDynamics.Solvers;
using Unity.Entities;
using Unity.Transforms;

namespace SoftBodyDynamics
{
    /// <summary>
    /// The components a simulated soft body carries, for bodies created from code: shape, settings, state, the particle
    /// (and cluster or element) buffers, an enabled <see cref="SoftBodyUninitialized"/> and a disabled
    /// <see cref="SoftBodyImpulse"/>, for each method. The shape-matching baker adds the same set with <c>IBaker</c>; the
    /// mass-spring and FEM bakers write theirs through <see cref="WriteMassSpring"/> and <see cref="WriteFem"/>.
    /// </summary>
    public static class SoftBodyArchetype
    {
        /// <summary>
        /// True when a body needs its own <see cref="ShapeMatchingQuadraticInverse"/> buffer: quadratic mode with
        /// plasticity on a blob built with the quadratic inverses.
        /// </summary>
        /// <param name="parameters">The body's parameters.</param>
        /// <param name="quadraticBlocks">Length of <see cref="ShapeMatchingShapeBlob.QuadraticInverse"/>.</param>
        public static bool NeedsQuadraticInverse(in ShapeMatchingParameters parameters, int quadraticBlocks) =>
            parameters.Mode == ShapeMatchingMode.Quadratic && parameters.Plasticity.Enabled && quadraticBlocks > 0;

        /// <summary>
        /// Makes <paramref name="entity"/> a soft body of <paramref name="shape"/>. The rest shape is placed at
        /// the entity's <see cref="LocalTransform"/> (identity is added when it has none) by the next update
        /// of <see cref="ShapeMatchingInitializationSystem"/>. Structural change: call it on the main thread.
        /// </summary>
        /// <param name="entityManager">The world's entity manager.</param>
        /// <param name="entity">A root entity (soft bodies simulate in world space).</param>
        /// <param name="shape">The blob; the caller keeps ownership of it.</param>
        /// <param name="parameters">The body's tunables.</param>
        public static void AddComponents(EntityManager entityManager, Entity entity, BlobAssetReference<ShapeMatchingShapeBlob> shape,
            in ShapeMatchingParameters parameters)
        {
            entityManager.AddComponentData(entity, new ShapeMatchingShape { Blob = shape });
            entityManager.AddComponentData(entity, new ShapeMatchingSettings { Value = parameters });
            entityManager.AddComponentData(entity, ParticleBodyState.Unstepped);
            entityManager.AddComponentData(entity, ShapeMatchingDiagnostics.Unstepped);
            entityManager.AddBuffer<SoftBodyPosition>(entity);
            entityManager.AddBuffer<SoftBodyVelocity>(entity);
            entityManager.AddBuffer<ShapeMatchingCluster>(entity);
            if (NeedsQuadraticInverse(parameters, shape.Value.QuadraticInverse.Length))
                entityManager.AddBuffer<ShapeMatchingQuadraticInverse>(entity);
            entityManager.AddComponent<SoftBodyUninitialized>(entity);
            entityManager.SetComponentEnabled<SoftBodyUninitialized>(entity, true);
            entityManager.AddComponent<SoftBodyImpulse>(entity);
            entityManager.SetComponentEnabled<SoftBodyImpulse>(entity, false);
            if (!entityManager.HasComponent<LocalTransform>(entity))
                entityManager.AddComponentData(entity, LocalTransform.Identity);
        }

        /// <summary>
        /// Makes <paramref name="entity"/> a mass-spring body of <paramref name="shape"/>, placed at its
        /// <see cref="LocalTransform"/> (identity is added when it has none) by the next update of
        /// <see cref="MassSpringSimulationSystem"/>. Structural change: call it on the main thread.
        /// </summary>
        /// <param name="entityManager">The world's entity manager.</param>
        /// <param name="entity">A root entity (bodies simulate in world space).</param>
        /// <param name="shape">The blob; the caller keeps ownership of it.</param>
        /// <param name="parameters">The body's tunables.</param>
        public static void AddMassSpringComponents(EntityManager entityManager, Entity entity, BlobAssetReference<MassSpringShapeBlob> shape,
            in MassSpringParameters parameters)
        {
            using (var writer = new EntityManagerSoftBodyWriter(entityManager, entity))
                WriteMassSpring(writer, shape, parameters);
            AddTransformIfMissing(entityManager, entity);
        }

        /// <summary>
        /// Makes <paramref name="entity"/> a finite-element body of <paramref name="shape"/>, placed at its
        /// <see cref="LocalTransform"/> (identity is added when it has none) by the next update of
        /// <see cref="FemSimulationSystem"/>. Structural change: call it on the main thread.
        /// </summary>
        /// <param name="entityManager">The world's entity manager.</param>
        /// <param name="entity">A root entity (bodies simulate in world space).</param>
        /// <param name="shape">The blob; the caller keeps ownership of it.</param>
        /// <param name="parameters">The body's tunables.</param>
        public static void AddFemComponents(EntityManager entityManager, Entity entity, BlobAssetReference<FemShapeBlob> shape,
            in FemParameters parameters)
        {
            using (var writer = new EntityManagerSoftBodyWriter(entityManager, entity))
                WriteFem(writer, shape, parameters);
            AddTransformIfMissing(entityManager, entity);
        }

        /// <summary>
        /// The simulation components of a mass-spring body (the one definition the baker and
        /// <see cref="AddMassSpringComponents"/> share): <see cref="MassSpringShape"/>, <see cref="MassSpringSettings"/>,
        /// <see cref="ParticleBodyState"/>, the particle buffers, <see cref="SoftBodyUninitialized"/> enabled and
        /// <see cref="SoftBodyImpulse"/> disabled. The blob is not handed to the writer (the caller owns it); no transform
        /// or render components.
        /// </summary>
        public static void WriteMassSpring(ISoftBodyEntityWriter writer, BlobAssetReference<MassSpringShapeBlob> shape,
            in MassSpringParameters parameters)
        {
            writer.AddComponent(new MassSpringShape { Blob = shape });
            writer.AddComponent(new MassSpringSettings { Value = parameters });
            WriteParticleBody(writer);
        }

        /// <summary>
        /// The simulation components of a finite-element body (shared as <see cref="WriteMassSpring"/> is):
        /// <see cref="FemShape"/>, <see cref="FemSettings"/>, <see cref="FemDiagnostics"/>, the
        /// <see cref="FemElementRotation"/> and <see cref="FemWarmStart"/> buffers and the particle-body components.
        /// </summary>
        public static void WriteFem(ISoftBodyEntityWriter writer, BlobAssetReference<FemShapeBlob> shape, in FemParameters parameters)
        {
            writer.AddComponent(new FemShape { Blob = shape });
            writer.AddComponent(new FemSettings { Value = parameters });
            writer.AddComponent(new FemDiagnostics());
            writer.AddBuffer<FemElementRotation>();
            writer.AddBuffer<FemWarmStart>();
            WriteParticleBody(writer);
        }

        /// <summary>What mass-spring and FEM bodies share: state, particle buffers, an enabled uninitialized tag, a disabled impulse.</summary>
        static void WriteParticleBody(ISoftBodyEntityWriter writer)
        {
            writer.AddComponent(ParticleBodyState.Unstepped);
            writer.AddBuffer<SoftBodyPosition>();
            writer.AddBuffer<SoftBodyVelocity>();
            writer.AddComponent(new SoftBodyUninitialized(), true);
            writer.AddComponent(new SoftBodyImpulse(), false);
        }

        static void AddTransformIfMissing(EntityManager entityManager, Entity entity)
        {
            if (!entityManager.HasComponent<LocalTransform>(entity))
                entityManager.AddComponentData(entity, LocalTransform.Identity);
        }
    }
}
