using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Solvers;
using Unity.Entities;
using UnityEngine;

namespace SoftBodyDynamics.Tests.Editor
{
    /// <summary>
    /// Baking mass-spring and FEM bodies from <see cref="SoftBodyAuthoring"/>: the component set and blob sizes each method
    /// gets (through <see cref="TetrahedralBodyBake.Write"/>, the baker's own code path, written to an EntityManager), that
    /// switching the method changes what is baked, and the validation of resolution, material and stable step.
    /// </summary>
    public class TetrahedralBodyBakingTests
    {
        readonly List<Object> m_Created = new List<Object>();
        World m_World;
        readonly List<EntityManagerSoftBodyWriter> m_Writers = new List<EntityManagerSoftBodyWriter>();

        [SetUp]
        public void SetUp() => m_World = new World("Tetrahedral baking tests");

        [TearDown]
        public void TearDown()
        {
            m_World.Dispose();
            foreach (EntityManagerSoftBodyWriter writer in m_Writers)
                writer.Dispose();
            m_Writers.Clear();
            foreach (Object created in m_Created)
                if (created != null)
                    Object.DestroyImmediate(created);
            m_Created.Clear();
        }

        SoftBodyAuthoring CreateBody(SoftBodyMethod method)
        {
            Mesh mesh = AuthoringTestData.CreateCubeMesh();
            m_Created.Add(mesh);
            var gameObject = new GameObject("Tetrahedral Body Under Test");
            m_Created.Add(gameObject);
            gameObject.AddComponent<MeshFilter>().sharedMesh = mesh;
            SoftBodyAuthoring body = gameObject.AddComponent<SoftBodyAuthoring>();
            body.method = method;
            body.tetResolution = 2;
            return body;
        }

        Entity Bake(SoftBodyAuthoring authoring, SoftBodyAuthoringBuild build)
        {
            EntityManager manager = m_World.EntityManager;
            Entity entity = manager.CreateEntity();
            var writer = new EntityManagerSoftBodyWriter(manager, entity);
            m_Writers.Add(writer);
            TetrahedralBodyBake.Write(authoring, build, null, writer);
            return entity;
        }

        static List<IssueCode> Codes(List<ValidationIssue> issues, IssueSeverity severity) => AuthoringTestData.Codes(issues, severity);

        [Test]
        public void Bake_MassSpring_AddsItsComponents_AndBlobsOfTheBuiltSizes()
        {
            SoftBodyAuthoring authoring = CreateBody(SoftBodyMethod.MassSpring);
            SoftBodyAuthoringBuild build = SoftBodyAuthoringValidation.ValidateAndBuild(authoring);
            Assert.That(build.Succeeded, Is.True, string.Join("\n", build.Issues));

            Entity entity = Bake(authoring, build);
            EntityManager manager = m_World.EntityManager;

            Assert.That(manager.HasComponent<MassSpringShape>(entity), Is.True);
            Assert.That(manager.HasComponent<MassSpringSettings>(entity), Is.True);
            Assert.That(manager.HasComponent<SoftBodyEmbedding>(entity), Is.True);
            Assert.That(manager.HasComponent<ParticleBodyState>(entity), Is.True);
            Assert.That(manager.HasBuffer<SoftBodyPosition>(entity) && manager.HasBuffer<SoftBodyVelocity>(entity), Is.True);
            Assert.That(manager.IsComponentEnabled<SoftBodyUninitialized>(entity), Is.True, "placed on the first step");
            Assert.That(manager.IsComponentEnabled<SoftBodyImpulse>(entity), Is.False);
            Assert.That(manager.HasComponent<FemShape>(entity) || manager.HasComponent<ShapeMatchingShape>(entity), Is.False, "no other method's shape");

            ref MassSpringShapeBlob shape = ref manager.GetComponentData<MassSpringShape>(entity).Blob.Value;
            Assert.That(shape.ParticleCount, Is.EqualTo(build.Tetrahedral.NodeCount));
            Assert.That(shape.SpringCount, Is.EqualTo(build.Tetrahedral.SpringCount));
            Assert.That(shape.IncidenceSlots.Length, Is.EqualTo(2 * shape.SpringCount), "two ends per spring");
            ref SoftBodyEmbeddingBlob embedding = ref manager.GetComponentData<SoftBodyEmbedding>(entity).Blob.Value;
            Assert.That(embedding.VertexCount, Is.EqualTo(8), "one embedded vertex per render vertex");
            Assert.That(embedding.NodeCount, Is.EqualTo(shape.ParticleCount));
        }

        [Test]
        public void Bake_Fem_AddsItsComponents_AndBlobsOfTheBuiltSizes()
        {
            SoftBodyAuthoring authoring = CreateBody(SoftBodyMethod.Fem);
            SoftBodyAuthoringBuild build = SoftBodyAuthoringValidation.ValidateAndBuild(authoring);
            Assert.That(build.Succeeded, Is.True, string.Join("\n", build.Issues));

            Entity entity = Bake(authoring, build);
            EntityManager manager = m_World.EntityManager;

            Assert.That(manager.HasComponent<FemShape>(entity), Is.True);
            Assert.That(manager.HasComponent<FemSettings>(entity), Is.True);
            Assert.That(manager.HasComponent<FemDiagnostics>(entity), Is.True);
            Assert.That(manager.HasBuffer<FemElementRotation>(entity), Is.True);
            Assert.That(manager.HasComponent<SoftBodyEmbedding>(entity), Is.True);
            Assert.That(manager.HasComponent<MassSpringShape>(entity) || manager.HasComponent<ShapeMatchingShape>(entity), Is.False, "no other method's shape");

            ref FemShapeBlob shape = ref manager.GetComponentData<FemShape>(entity).Blob.Value;
            Assert.That(shape.ParticleCount, Is.EqualTo(build.Tetrahedral.NodeCount));
            Assert.That(shape.ElementCount, Is.EqualTo(build.Tetrahedral.TetrahedronCount));
            Assert.That(shape.IncidenceSlots.Length, Is.EqualTo(4 * shape.ElementCount), "four corners per tetrahedron");
            Assert.That(manager.GetComponentData<FemSettings>(entity).Value.Model, Is.EqualTo(authoring.femModel));
        }

        [Test]
        public void SwitchingTheMethod_ChangesWhatIsBuilt()
        {
            SoftBodyAuthoring authoring = CreateBody(SoftBodyMethod.ShapeMatching);
            SoftBodyAuthoringBuild shapeMatching = SoftBodyAuthoringValidation.ValidateAndBuild(authoring);
            authoring.method = SoftBodyMethod.MassSpring;
            SoftBodyAuthoringBuild massSpring = SoftBodyAuthoringValidation.ValidateAndBuild(authoring);
            authoring.method = SoftBodyMethod.Fem;
            SoftBodyAuthoringBuild fem = SoftBodyAuthoringValidation.ValidateAndBuild(authoring);

            Assert.That(shapeMatching.Succeeded && shapeMatching.Result != null && shapeMatching.Tetrahedral == null, Is.True);
            Assert.That(massSpring.Succeeded && massSpring.Result == null && massSpring.Tetrahedral.MassSpring != null, Is.True);
            Assert.That(fem.Succeeded && fem.Result == null && fem.Tetrahedral.Fem != null && fem.Tetrahedral.MassSpring == null, Is.True);

            Entity springEntity = Bake(SetMethod(authoring, SoftBodyMethod.MassSpring), massSpring);
            Entity femEntity = Bake(SetMethod(authoring, SoftBodyMethod.Fem), fem);
            Assert.That(m_World.EntityManager.HasComponent<MassSpringShape>(springEntity), Is.True);
            Assert.That(m_World.EntityManager.HasComponent<FemShape>(femEntity), Is.True);
        }

        static SoftBodyAuthoring SetMethod(SoftBodyAuthoring authoring, SoftBodyMethod method)
        {
            authoring.method = method;
            return authoring;
        }

        [Test]
        public void Validate_ResolutionOutOfRange_IsAnError([Values(SoftBodyMethod.MassSpring, SoftBodyMethod.Fem)] SoftBodyMethod method,
            [Values(0, 129)] int resolution)
        {
            SoftBodyAuthoring authoring = CreateBody(method);
            authoring.tetResolution = resolution;

            SoftBodyAuthoringBuild build = SoftBodyAuthoringValidation.ValidateAndBuild(authoring);

            Assert.That(Codes(build.Issues, IssueSeverity.Error), Does.Contain((IssueCode)TetrahedralMeshIssueCode.TetResolutionOutOfRange));
            Assert.That(build.Succeeded, Is.False);
        }

        [Test]
        public void Validate_InvalidMaterial_IsAnErrorOfTheMethod([Values(SoftBodyMethod.MassSpring, SoftBodyMethod.Fem)] SoftBodyMethod method)
        {
            SoftBodyAuthoring authoring = CreateBody(method);
            authoring.youngsModulus = -1f;

            SoftBodyAuthoringBuild build = SoftBodyAuthoringValidation.ValidateAndBuild(authoring);

            IssueCode expected = method == SoftBodyMethod.MassSpring ? MassSpringIssueCode.MaterialInvalid : FemIssueCode.MaterialInvalid;
            Assert.That(Codes(build.Issues, IssueSeverity.Error), Does.Contain(expected));
            Assert.That(build.Issues.Find(i => i.Code == expected).Message, Does.Contain("Young's modulus"));
            Assert.That(build.Succeeded, Is.False);
        }

        [Test]
        public void Validate_StiffMaterialWithExplicitIntegrator_WarnsWithTheStableStep([Values(SoftBodyMethod.MassSpring, SoftBodyMethod.Fem)] SoftBodyMethod method)
        {
            // E = 1 GPa, ρ = 1000 kg/m³: waves at about √(E/ρ) = 1000 m/s cross a 0.5 m cell in 0.5 ms, far below one
            // substep of 1/60 s: every explicit integrator is unstable there.
            SoftBodyAuthoring authoring = CreateBody(method);
            authoring.youngsModulus = 1e9f;
            authoring.substeps = 1;
            authoring.massSpringIntegrator = MassSpringIntegrator.SymplecticEuler;
            authoring.femModel = FemMaterialModel.CoRotational;
            authoring.femIntegrator = FemIntegrator.SymplecticEuler;

            SoftBodyAuthoringBuild build = SoftBodyAuthoringValidation.ValidateAndBuild(authoring);

            IssueCode expected = method == SoftBodyMethod.MassSpring ? MassSpringIssueCode.StepAboveStableLimit : FemIssueCode.StepAboveStableLimit;
            Assert.That(Codes(build.Issues, IssueSeverity.Warning), Does.Contain(expected), string.Join("\n", build.Issues));
            Assert.That(build.Tetrahedral.MaxStableStep, Is.LessThan(SoftBodyAuthoringValidation.AssumedFixedTimeStep));
            Assert.That(build.Succeeded, Is.True, "a warning does not stop the bake");

            authoring.massSpringIntegrator = MassSpringIntegrator.ImplicitEuler;
            authoring.femIntegrator = FemIntegrator.ImplicitEuler;
            Assert.That(Codes(SoftBodyAuthoringValidation.Validate(authoring), IssueSeverity.Warning), Does.Not.Contain(expected),
                "an implicit integrator is stable at any step");
        }

        [Test]
        public void Presets_SetThePhysicalMaterial_TheSameForEveryMethod()
        {
            SoftBodyAuthoring authoring = CreateBody(SoftBodyMethod.Fem);
            authoring.ApplyPreset(SoftBodyPreset.Rubber);
            Assert.That(authoring.Material.YoungsModulus, Is.EqualTo(ElasticMaterial.Rubber.YoungsModulus));
            Assert.That(authoring.Material.Density, Is.EqualTo(ElasticMaterial.Rubber.Density));
            authoring.method = SoftBodyMethod.MassSpring;
            Assert.That(authoring.Material.PoissonRatio, Is.EqualTo(ElasticMaterial.Rubber.PoissonRatio), "the method does not change the material");

            authoring.youngsModulus *= 2f;
            SoftBodyPresets.Synchronize(authoring);
            Assert.That(authoring.preset, Is.EqualTo(SoftBodyPreset.Custom), "a hand-edited material is Custom");
        }
    }
}
