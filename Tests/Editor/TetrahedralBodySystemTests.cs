using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Core;
using Unity.Entities;
using Unity.Mathematics;
using Unity.Transforms;

namespace SoftBodyDynamics.Tests.Editor
{
    /// <summary>
    /// The mass-spring and FEM systems in a test world: each runs only while its own shape component exists (a world of
    /// shape-matching bodies runs neither), places a body at its transform, steps it under gravity keeping it finite, and
    /// honours the world settings.
    /// </summary>
    public class TetrahedralBodySystemTests
    {
        const float k_Dt = 1f / 60f;

        World m_World;
        EntityManager m_Manager;
        SystemHandle m_ShapeMatching;
        SystemHandle m_MassSpring;
        SystemHandle m_Fem;
        SystemHandle m_ColliderWorld;
        readonly List<System.IDisposable> m_Blobs = new List<System.IDisposable>();
        double m_ElapsedTime;

        /// <summary>A 0.4 m cube of 2×2×2 Kuhn-split cells (27 nodes, 48 tetrahedra) centred on the origin.</summary>
        static TetrahedralMesh Cube() => BoxTetrahedra.Create(new float3(0.4f), new int3(2), float3.zero);

        [SetUp]
        public void SetUp()
        {
            m_World = new World("Tetrahedral system tests");
            m_Manager = m_World.EntityManager;
            m_ColliderWorld = m_World.CreateSystem<ColliderWorldSystem>();
            m_ShapeMatching = m_World.CreateSystem<ShapeMatchingSimulationSystem>();
            m_MassSpring = m_World.CreateSystem<MassSpringSimulationSystem>();
            m_Fem = m_World.CreateSystem<FemSimulationSystem>();
            m_ElapsedTime = 0.0;
        }

        [TearDown]
        public void TearDown()
        {
            m_Manager.CompleteAllTrackedJobs();
            m_World.Dispose();
            foreach (System.IDisposable blob in m_Blobs)
                blob.Dispose();
            m_Blobs.Clear();
        }

        bool ShouldRun(SystemHandle system) => m_World.Unmanaged.ResolveSystemStateRef(system).ShouldRunSystem();

        Entity CreateMassSpringBody(float3 position, MassSpringParameters parameters)
        {
            var issues = new List<ValidationIssue>();
            MassSpringModelData model = MassSpringModelData.FromMesh(Cube(), ElasticMaterial.Jelly, MassSpringBuildSettings.Default, issues, out _);
            Assert.That(model, Is.Not.Null, string.Join("\n", issues));
            BlobAssetReference<MassSpringShapeBlob> blob = MassSpringShapeBlobFactory.Create(model.AsModel(), Allocator.Persistent);
            m_Blobs.Add(blob);
            Entity entity = m_Manager.CreateEntity();
            m_Manager.AddComponentData(entity, LocalTransform.FromPositionRotation(position, quaternion.identity));
            SoftBodyArchetype.AddMassSpringComponents(m_Manager, entity, blob, parameters);
            return entity;
        }

        Entity CreateFemBody(float3 position, FemParameters parameters, FemElementOrder order = FemElementOrder.Linear, bool restFactor = false)
        {
            var issues = new List<ValidationIssue>();
            FemModelData model = FemModelData.Create(Cube(), ElasticMaterial.Jelly, default, issues, order);
            Assert.That(model, Is.Not.Null, string.Join("\n", issues));
            if (restFactor)
                Assert.That(model.BuildRestFactor(k_Dt / parameters.Body.Substeps, FemSolver.DampingCoefficient(model.AsModel(), parameters)), Is.True);
            BlobAssetReference<FemShapeBlob> blob = FemShapeBlobFactory.Create(model.AsModel(), Allocator.Persistent);
            m_Blobs.Add(blob);
            Entity entity = m_Manager.CreateEntity();
            m_Manager.AddComponentData(entity, LocalTransform.FromPositionRotation(position, quaternion.identity));
            SoftBodyArchetype.AddFemComponents(m_Manager, entity, blob, parameters);
            return entity;
        }

        void Update(int frames)
        {
            for (int f = 0; f < frames; f++)
            {
                m_ElapsedTime += k_Dt;
                m_World.SetTime(new TimeData(m_ElapsedTime, k_Dt));
                m_ColliderWorld.Update(m_World.Unmanaged);
                m_MassSpring.Update(m_World.Unmanaged);
                m_Fem.Update(m_World.Unmanaged);
                m_Manager.CompleteAllTrackedJobs();
            }
        }

        void AssertFiniteAndFell(Entity entity, float startY)
        {
            DynamicBuffer<SoftBodyPosition> x = m_Manager.GetBuffer<SoftBodyPosition>(entity, true);
            Assert.That(x.Length, Is.GreaterThan(0), "the buffers were sized");
            for (int i = 0; i < x.Length; i++)
                Assert.That(math.all(math.isfinite(x[i].Value)), Is.True, $"particle {i} is finite: {x[i].Value}");
            ParticleBodyState state = m_Manager.GetComponentData<ParticleBodyState>(entity);
            Assert.That(state.LastReport.Stepped, Is.True);
            Assert.That(state.Status.ResetCount, Is.EqualTo(0), "no NaN-guard reset");
            // Free fall for 0.5 s drops the centre by about ½ g t² = 1.23 m; the body's elasticity is internal, so at least 1 m.
            Assert.That(state.Status.Center.y, Is.LessThan(startY - 1f), "the body fell");
            LocalTransform transform = m_Manager.GetComponentData<LocalTransform>(entity);
            Assert.That(transform.Position.y, Is.LessThan(startY - 1f), "the entity follows the body");
        }

        [Test]
        public void EachSystem_RunsOnlyWhenItsOwnShapeExists()
        {
            Assert.That(ShouldRun(m_MassSpring) || ShouldRun(m_Fem) || ShouldRun(m_ShapeMatching), Is.False, "an empty world runs none");
            Entity collider = m_Manager.CreateEntity();
            m_Manager.AddComponentData(collider, new ParticleCollider { Shape = ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) });
            Assert.That(ShouldRun(m_ColliderWorld), Is.False, "colliders alone: nothing reads the collider world, so it is not built");

            Entity shapeMatchingOnly = m_Manager.CreateEntity();
            m_Manager.AddComponentData(shapeMatchingOnly, new ShapeMatchingShape());
            Assert.That(ShouldRun(m_ShapeMatching), Is.True);
            Assert.That(ShouldRun(m_ColliderWorld), Is.True, "a body reads the collider world");
            Assert.That(ShouldRun(m_MassSpring) || ShouldRun(m_Fem), Is.False, "shape-matching bodies run no spring or FEM system");
            m_Manager.DestroyEntity(shapeMatchingOnly);

            CreateMassSpringBody(float3.zero, MassSpringParameters.Default);
            Assert.That(ShouldRun(m_MassSpring), Is.True);
            Assert.That(ShouldRun(m_Fem) || ShouldRun(m_ShapeMatching), Is.False);

            CreateFemBody(float3.zero, FemParameters.Default);
            Assert.That(ShouldRun(m_Fem), Is.True);
            Assert.That(ShouldRun(m_ShapeMatching), Is.False);
        }

        [Test]
        public void MassSpringBody_IsPlacedAtItsTransform_FallsAndStaysFinite()
        {
            Entity body = CreateMassSpringBody(new float3(1f, 5f, 2f), MassSpringParameters.Default);

            Update(1);
            Assert.That(m_Manager.IsComponentEnabled<SoftBodyUninitialized>(body), Is.False, "initialised once");
            float3 center = m_Manager.GetComponentData<ParticleBodyState>(body).Status.Center;
            // One step of gravity moves the centre by less than 1 mm; the rest centre of the cube is its middle.
            Assert.That(math.distance(new float3(center.x, 0f, center.z), new float3(1f, 0f, 2f)), Is.LessThan(1e-4f), "placed at the transform");

            Update(29);
            AssertFiniteAndFell(body, 5f);
        }

        [Test]
        public void FemBody_IsPlacedAtItsTransform_FallsAndStaysFinite([Values] FemMaterialModel model)
        {
            FemParameters parameters = FemParameters.Default;
            parameters.Model = model;
            parameters.Integrator = model == FemMaterialModel.CoRotational ? FemIntegrator.ImplicitEuler : FemIntegrator.Xpbd;
            Entity body = CreateFemBody(new float3(-1f, 5f, 0f), parameters);

            Update(30);

            Assert.That(m_Manager.GetBuffer<FemElementRotation>(body, true).Length, Is.EqualTo(48), "one rotation per tetrahedron");
            AssertFiniteAndFell(body, 5f);
            Assert.That(m_Manager.GetComponentData<FemDiagnostics>(body).LastReport.IntegratorFallback, Is.False);
        }

        [Test]
        public void QuadraticFemBody_WithRestFactor_HasAPointRotationEach_AndFalls([Values] FemMaterialModel model)
        {
            FemParameters parameters = FemParameters.Default;
            parameters.Model = model;
            Entity body = CreateFemBody(new float3(2f, 5f, 0f), parameters, FemElementOrder.Quadratic, true);

            Update(30);

            Assert.That(m_Manager.GetBuffer<FemElementRotation>(body, true).Length, Is.EqualTo(4 * 48), "one rotation per integration point");
            Assert.That(m_Manager.GetBuffer<FemWarmStart>(body, true).Length, Is.EqualTo(m_Manager.GetBuffer<SoftBodyPosition>(body, true).Length));
            AssertFiniteAndFell(body, 5f);
            FemStepReport report = m_Manager.GetComponentData<FemDiagnostics>(body).LastReport;
            Assert.That(report.CgConverged, Is.True);
            // The rest factor's preconditioning: a handful of iterations per substep at most.
            Assert.That(report.MaxCgIterations, Is.LessThan(20));
        }

        [Test]
        public void WorldSettings_ReplaceTheGravityOfSpringAndFemBodies()
        {
            Entity spring = CreateMassSpringBody(new float3(0f, 5f, 0f), MassSpringParameters.Default);
            Entity fem = CreateFemBody(new float3(3f, 5f, 0f), FemParameters.Default);
            Entity world = m_Manager.CreateEntity();
            m_Manager.AddComponentData(world, new ParticleWorldSettings { Gravity = float3.zero, MinSubsteps = 1 });

            Update(30);

            // Without gravity and at rest, the bodies stay where they were placed (round-off only).
            Assert.That(m_Manager.GetComponentData<ParticleBodyState>(spring).Status.Center.y, Is.EqualTo(5f).Within(1e-3f));
            Assert.That(m_Manager.GetComponentData<ParticleBodyState>(fem).Status.Center.y, Is.EqualTo(5f).Within(1e-3f));
        }
    }
}
