using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Tests.Editor
{
    /// <summary>
    /// Validation of soft-body and collider authoring (the checks the bakers and inspectors share), the preset
    /// values and the world-space collider conversion.
    /// </summary>
    public class SoftBodyAuthoringTests
    {
        readonly List<Object> m_Created = new List<Object>();

        [TearDown]
        public void TearDown()
        {
            foreach (Object created in m_Created)
                if (created != null)
                    Object.DestroyImmediate(created);
            m_Created.Clear();
        }

        Mesh CreateCubeMesh()
        {
            Mesh mesh = AuthoringTestData.CreateCubeMesh();
            m_Created.Add(mesh);
            return mesh;
        }

        SoftBodyAuthoring CreateBody(Mesh mesh, bool addMeshFilter = true)
        {
            var gameObject = new GameObject("Soft Body Under Test");
            m_Created.Add(gameObject);
            if (addMeshFilter)
                gameObject.AddComponent<MeshFilter>().sharedMesh = mesh;
            SoftBodyAuthoring body = gameObject.AddComponent<SoftBodyAuthoring>();
            body.addInteriorParticles = false;
            body.clusterSize = 0f;
            return body;
        }

        ParticleColliderAuthoring CreateCollider(ColliderShapeType shape)
        {
            var gameObject = new GameObject("Collider Under Test");
            m_Created.Add(gameObject);
            ParticleColliderAuthoring collider = gameObject.AddComponent<ParticleColliderAuthoring>();
            collider.shape = shape;
            return collider;
        }

        static List<IssueCode> Errors(List<ValidationIssue> issues) => AuthoringTestData.Codes(issues, IssueSeverity.Error);

        static List<IssueCode> Codes(List<ValidationIssue> issues, IssueSeverity severity) => AuthoringTestData.Codes(issues, severity);

        // ---------------------------------------------------------------- soft body validation

        [Test]
        public void Validate_ValidCube_HasNoErrorAndBuilds()
        {
            SoftBodyAuthoring body = CreateBody(CreateCubeMesh());

            SoftBodyAuthoringBuild build = SoftBodyAuthoringValidation.ValidateAndBuild(body);

            Assert.That(Errors(build.Issues), Is.Empty, string.Join("\n", build.Issues));
            Assert.That(build.Succeeded, Is.True);
            Assert.That(build.Result.ParticleCount, Is.EqualTo(8));
            Assert.That(build.Mesh.Triangles, Is.EqualTo(AuthoringTestData.CubeTriangles));
        }

        [Test]
        public void Validate_NoMeshFilter_ReportsNoMesh()
        {
            SoftBodyAuthoring body = CreateBody(null, addMeshFilter: false);

            List<ValidationIssue> issues = SoftBodyAuthoringValidation.Validate(body);

            Assert.That(Errors(issues), Does.Contain((IssueCode)MeshBuildIssueCode.NoMesh));
            Assert.That(issues.Find(i => i.Code == MeshBuildIssueCode.NoMesh).Message, Does.Contain("MeshFilter"));
        }

        [Test]
        public void Validate_MeshFilterWithoutMesh_ReportsNoMesh()
        {
            SoftBodyAuthoring body = CreateBody(null);

            Assert.That(Errors(SoftBodyAuthoringValidation.Validate(body)), Does.Contain((IssueCode)MeshBuildIssueCode.NoMesh));
        }

        [Test]
        public void Validate_UnreadableMesh_ReportsMeshNotReadable()
        {
            Mesh mesh = CreateCubeMesh();
            mesh.UploadMeshData(true); // frees the CPU copy: isReadable becomes false
            SoftBodyAuthoring body = CreateBody(mesh);

            SoftBodyAuthoringBuild build = SoftBodyAuthoringValidation.ValidateAndBuild(body);

            Assert.That(Errors(build.Issues), Does.Contain((IssueCode)MeshBuildIssueCode.MeshNotReadable));
            Assert.That(build.Succeeded, Is.False);
        }

        [Test]
        public void Validate_NaNVertex_ReportsNonFiniteVertex()
        {
            Mesh mesh = CreateCubeMesh();
            Vector3[] vertices = mesh.vertices;
            vertices[5] = new Vector3(float.NaN, 0f, 0f);
            mesh.vertices = vertices;
            SoftBodyAuthoring body = CreateBody(mesh);

            List<ValidationIssue> issues = SoftBodyAuthoringValidation.Validate(body);

            Assert.That(Errors(issues), Does.Contain((IssueCode)MeshBuildIssueCode.NonFiniteVertex));
            Assert.That(issues.Find(i => i.Code == MeshBuildIssueCode.NonFiniteVertex).Index, Is.EqualTo(5));
        }

        [Test]
        public void Validate_NegativeMass_ReportsTotalMassNotPositive()
        {
            SoftBodyAuthoring body = CreateBody(CreateCubeMesh());
            body.totalMass = -1f;

            Assert.That(Errors(SoftBodyAuthoringValidation.Validate(body)), Does.Contain((IssueCode)MeshBuildIssueCode.TotalMassNotPositive));
        }

        [Test]
        public void Validate_MoreParticlesThanTheLimit_ReportsTooManyParticles()
        {
            SoftBodyAuthoring body = CreateBody(CreateCubeMesh());
            body.maxParticles = 4; // the cube welds into 8 particles

            SoftBodyAuthoringBuild build = SoftBodyAuthoringValidation.ValidateAndBuild(body);

            Assert.That(Errors(build.Issues), Does.Contain((IssueCode)MeshBuildIssueCode.TooManyParticles));
            Assert.That(build.Succeeded, Is.False);
        }

        [Test]
        public void Validate_NegativeFrequency_ReportsFrequencyOutOfRange()
        {
            SoftBodyAuthoring body = CreateBody(CreateCubeMesh());
            body.frequency = -2f;

            Assert.That(Errors(SoftBodyAuthoringValidation.Validate(body)), Does.Contain((IssueCode)ShapeMatchingIssueCode.FrequencyOutOfRange));
        }

        [Test]
        public void MigrateLegacyStiffness_CustomBody_KeepsItsFrequencyAt60Hz()
        {
            SoftBodyAuthoring body = CreateBody(CreateCubeMesh());
            body.ApplyPreset(SoftBodyPreset.Custom);
            body.substeps = 4;
            body.legacyStiffness = 0.15f;
            body.legacyDamping = 3f;

            SoftBodyPresets.MigrateLegacyStiffness(body);

            Assert.That(LegacyStiffness.ToFrequency(0.15f, 3f, 4, SoftBodyPresets.LegacyTimeStep, out float f, out float zeta), Is.True);
            Assert.That(body.frequency, Is.EqualTo(f));
            Assert.That(body.dampingRatio, Is.EqualTo(zeta));
            Assert.That(body.legacyStiffness, Is.EqualTo(-1f), "migrates once");
        }

        [Test]
        public void MigrateLegacyStiffness_PresetBody_TakesThePresetsNewValues()
        {
            SoftBodyAuthoring body = CreateBody(CreateCubeMesh());
            body.ApplyPreset(SoftBodyPreset.Rubber);
            body.legacyStiffness = 0.6f;
            body.legacyDamping = 4f;

            SoftBodyPresets.MigrateLegacyStiffness(body);

            Assert.That(SoftBodyPresets.Matches(body, SoftBodyPreset.Rubber), Is.True);
        }

        [Test]
        public void Validate_MissingMeshAndBadParameter_ReportsBoth()
        {
            SoftBodyAuthoring body = CreateBody(null);
            body.restitution = 3f;

            List<IssueCode> errors = Errors(SoftBodyAuthoringValidation.Validate(body));

            Assert.That(errors, Does.Contain((IssueCode)MeshBuildIssueCode.NoMesh));
            Assert.That(errors, Does.Contain((IssueCode)ParticleBodyIssueCode.RestitutionOutOfRange));
        }

        [TestCase(true)]
        [TestCase(false)]
        public void Validate_BadBuildSetting_IsReportedOnceWithOrWithoutAMesh(bool hasMesh)
        {
            SoftBodyAuthoring body = CreateBody(hasMesh ? CreateCubeMesh() : null);
            body.totalMass = 0f;

            List<IssueCode> errors = Errors(SoftBodyAuthoringValidation.Validate(body));

            Assert.That(errors.FindAll(code => code == MeshBuildIssueCode.TotalMassNotPositive), Has.Count.EqualTo(1));
            Assert.That(errors.Contains(MeshBuildIssueCode.NoMesh), Is.EqualTo(!hasMesh));
        }

        // ---------------------------------------------------------------- presets

        [Test]
        public void ApplyPreset_Jelly_SetsDocumentedValues()
        {
            SoftBodyAuthoring body = CreateBody(CreateCubeMesh());
            body.ApplyPreset(SoftBodyPreset.Jelly);

            AssertMaterial(body, ShapeMatchingMode.Linear, 7.7f, 0.13f, 0.6f, 0f, 0f, 0f, 0.4f, 0.2f);
            Assert.That(body.preset, Is.EqualTo(SoftBodyPreset.Jelly));
        }

        [Test]
        public void ApplyPreset_Rubber_SetsDocumentedValues()
        {
            SoftBodyAuthoring body = CreateBody(CreateCubeMesh());
            body.ApplyPreset(SoftBodyPreset.Rubber);

            AssertMaterial(body, ShapeMatchingMode.Linear, 18.5f, 0.25f, 0.3f, 0f, 0f, 0f, 1f, 0.7f);
            Assert.That(body.preset, Is.EqualTo(SoftBodyPreset.Rubber));
        }

        [Test]
        public void ApplyPreset_Clay_SetsDocumentedValues()
        {
            SoftBodyAuthoring body = CreateBody(CreateCubeMesh());
            body.ApplyPreset(SoftBodyPreset.Clay);

            AssertMaterial(body, ShapeMatchingMode.Linear, 13.8f, 0.22f, 0.8f, 0.05f, 10f, 0.6f, 0.9f, 0f);
            Assert.That(body.Parameters.Plasticity.Enabled, Is.True);
        }

        [Test]
        public void NewComponent_HoldsTheJellyPreset()
        {
            SoftBodyAuthoring body = CreateBody(CreateCubeMesh());

            Assert.That(body.preset, Is.EqualTo(SoftBodyPreset.Jelly));
            Assert.That(SoftBodyPresets.Matches(body, SoftBodyPreset.Jelly), Is.True);
        }

        [Test]
        public void Synchronize_AfterAHandEdit_SwitchesToCustomAndKeepsTheValue()
        {
            SoftBodyAuthoring body = CreateBody(CreateCubeMesh());
            body.ApplyPreset(SoftBodyPreset.Rubber);
            body.frequency = 3.3f;

            SoftBodyPresets.Synchronize(body);

            Assert.That(body.preset, Is.EqualTo(SoftBodyPreset.Custom));
            Assert.That(body.frequency, Is.EqualTo(3.3f));
        }

        [Test]
        public void Synchronize_AfterPickingAPreset_WritesItsValues()
        {
            SoftBodyAuthoring body = CreateBody(CreateCubeMesh());
            body.preset = SoftBodyPreset.Clay; // as the inspector's dropdown does

            SoftBodyPresets.Synchronize(body);

            Assert.That(body.preset, Is.EqualTo(SoftBodyPreset.Clay));
            Assert.That(SoftBodyPresets.Matches(body, SoftBodyPreset.Clay), Is.True);
        }

        [Test]
        public void EveryPreset_PassesParameterValidation()
        {
            foreach (SoftBodyPreset preset in new[] { SoftBodyPreset.Jelly, SoftBodyPreset.Rubber, SoftBodyPreset.Clay })
            {
                SoftBodyAuthoring body = CreateBody(CreateCubeMesh());
                body.ApplyPreset(preset);
                var issues = new List<ValidationIssue>();
                ShapeMatchingParameterValidation.Validate(body.Parameters, issues);
                Assert.That(Errors(issues), Is.Empty, $"{preset}: {string.Join("\n", issues)}");
            }
        }

        static void AssertMaterial(SoftBodyAuthoring body, ShapeMatchingMode mode, float frequency, float dampingRatio, float beta,
            float yield, float creep, float maxDeformation, float friction, float restitution)
        {
            Assert.That(body.mode, Is.EqualTo(mode), "mode");
            Assert.That(body.frequency, Is.EqualTo(frequency), "frequency");
            Assert.That(body.dampingRatio, Is.EqualTo(dampingRatio), "damping ratio");
            Assert.That(body.beta, Is.EqualTo(beta), "beta");
            Assert.That(body.plasticYield, Is.EqualTo(yield), "yield");
            Assert.That(body.plasticCreep, Is.EqualTo(creep), "creep");
            Assert.That(body.plasticMaxDeformation, Is.EqualTo(maxDeformation), "max deformation");
            Assert.That(body.friction, Is.EqualTo(friction), "friction");
            Assert.That(body.restitution, Is.EqualTo(restitution), "restitution");
        }

        // ---------------------------------------------------------------- colliders

        [Test]
        public void ColliderValidation_DefaultBox_HasNoIssue()
        {
            ParticleColliderAuthoring collider = CreateCollider(ColliderShapeType.Box);

            Assert.That(ParticleColliderValidation.Validate(collider), Is.Empty);
        }

        [Test]
        public void ColliderValidation_BoxWithZeroEdge_ReportsSizeNotPositive()
        {
            ParticleColliderAuthoring collider = CreateCollider(ColliderShapeType.Box);
            collider.size = new Vector3(1f, 0f, 1f);

            Assert.That(Codes(ParticleColliderValidation.Validate(collider), IssueSeverity.Error),
                Does.Contain((IssueCode)ColliderIssueCode.SizeNotPositive));
        }

        [Test]
        public void ColliderValidation_NegativeRadius_ReportsSizeNotPositive()
        {
            ParticleColliderAuthoring collider = CreateCollider(ColliderShapeType.Capsule);
            collider.radius = -0.1f;

            Assert.That(Codes(ParticleColliderValidation.Validate(collider), IssueSeverity.Error),
                Does.Contain((IssueCode)ColliderIssueCode.SizeNotPositive));
        }

        [Test]
        public void ColliderValidation_NaNRadius_ReportsSizeNotFinite()
        {
            ParticleColliderAuthoring collider = CreateCollider(ColliderShapeType.Sphere);
            collider.radius = float.NaN;

            Assert.That(Codes(ParticleColliderValidation.Validate(collider), IssueSeverity.Error),
                Does.Contain((IssueCode)ColliderIssueCode.SizeNotFinite));
        }

        [Test]
        public void ColliderValidation_NonUniformlyScaledSphere_Warns()
        {
            ParticleColliderAuthoring collider = CreateCollider(ColliderShapeType.Sphere);
            collider.transform.localScale = new Vector3(1f, 2f, 1f);

            List<ValidationIssue> issues = ParticleColliderValidation.Validate(collider);

            Assert.That(Codes(issues, IssueSeverity.Warning), Does.Contain((IssueCode)ColliderIssueCode.NonUniformScale));
            Assert.That(ValidationIssue.AnyError(issues), Is.False);
        }

        [Test]
        public void ColliderValidation_CapsuleStretchedAlongItsAxis_DoesNotWarn()
        {
            ParticleColliderAuthoring collider = CreateCollider(ColliderShapeType.Capsule);
            collider.transform.localScale = new Vector3(1f, 3f, 1f);

            Assert.That(ParticleColliderValidation.Validate(collider), Is.Empty);
        }

        [Test]
        public void ColliderValidation_ZeroScaledBox_ReportsScaleZero()
        {
            ParticleColliderAuthoring collider = CreateCollider(ColliderShapeType.Box);
            collider.transform.localScale = new Vector3(1f, 0f, 1f);

            Assert.That(Codes(ParticleColliderValidation.Validate(collider), IssueSeverity.Error),
                Does.Contain((IssueCode)ColliderIssueCode.ScaleZero));
        }

        /// <summary>A rotation by +90° about the unit <paramref name="axis"/>.</summary>
        static quaternion QuarterTurn(float3 axis)
        {
            float s = math.sin(math.PI / 4f), c = math.cos(math.PI / 4f);
            return new quaternion(axis.x * s, axis.y * s, axis.z * s, c);
        }

        [Test]
        public void WorldShape_ScaledRotatedBox_HasWorldCentreAndHalfExtents()
        {
            var box = new ParticleColliderDefinition
            {
                Shape = ColliderShapeType.Box, Center = new float3(1f, 0f, 0f), Size = new float3(2f, 4f, 6f),
            };
            quaternion quarterTurnY = QuarterTurn(new float3(0f, 1f, 0f));

            ColliderShape shape = ParticleColliderWorldShape.Compute(box, new float3(0f, 1f, 0f), quarterTurnY, new float3(2f, 1f, 1f));

            Assert.That(shape.Type, Is.EqualTo(ColliderShapeType.Box));
            Assert.That(math.distance(shape.Center, new float3(0f, 1f, -2f)), Is.LessThan(1e-5f));
            Assert.That(math.distance(shape.HalfExtents, new float3(2f, 2f, 3f)), Is.LessThan(1e-6f));
        }

        [Test]
        public void WorldShape_CapsuleAlongY_EndsAtTheCapCentres()
        {
            var capsule = new ParticleColliderDefinition
            {
                Shape = ColliderShapeType.Capsule, Radius = 0.5f, Height = 3f, Direction = ColliderCapsuleAxis.Y,
            };

            ColliderShape shape = ParticleColliderWorldShape.Compute(capsule, float3.zero, quaternion.identity, new float3(1f, 2f, 1f));

            Assert.That(shape.Radius, Is.EqualTo(0.5f));
            // Height 3 m scaled by 2 is 6 m tip to tip; the segment stops one radius short of each tip.
            Assert.That(math.distance(shape.Center, new float3(0f, -2.5f, 0f)), Is.LessThan(1e-5f));
            Assert.That(math.distance(shape.Axis, new float3(0f, 2.5f, 0f)), Is.LessThan(1e-5f));
        }

        [Test]
        public void WorldShape_Plane_UsesTheUpAxisAsNormal()
        {
            var plane = new ParticleColliderDefinition { Shape = ColliderShapeType.Plane };
            quaternion tiltX = QuarterTurn(new float3(1f, 0f, 0f));

            ColliderShape shape = ParticleColliderWorldShape.Compute(plane, new float3(0f, 2f, 0f), tiltX, new float3(5f, 5f, 5f));

            Assert.That(math.distance(shape.Center, new float3(0f, 2f, 0f)), Is.LessThan(1e-6f));
            Assert.That(math.distance(shape.Axis, math.mul(tiltX, new float3(0f, 1f, 0f))), Is.LessThan(1e-6f));
        }
    }
}
