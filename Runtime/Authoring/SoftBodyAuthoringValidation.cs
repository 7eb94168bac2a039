using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEngine;
using static System.FormattableString;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Every check on a <see cref="SoftBodyAuthoring"/>, in one place, used by the baker and the inspector:
    /// 1. a MeshFilter with a mesh (<see cref="MeshBuildIssueCode.NoMesh"/>);
    /// 2. the mesh is readable on the CPU (<see cref="MeshBuildIssueCode.MeshNotReadable"/>);
    /// 3. the builder's checks of the mesh and build settings (<see cref="SoftBodyBuilder"/>); without a readable
    ///    mesh, the build settings alone (<see cref="SoftBodyBuildSettingsValidation"/>);
    /// 4. the solver parameters (<see cref="ShapeMatchingParameterValidation"/>).
    /// For the mass-spring and FEM methods, steps 3 and 4 are instead: the physical material (<see cref="ElasticMaterial.IsValid"/>),
    /// the method's parameters (<see cref="MassSpringParameterValidation"/>, <see cref="FemParameterValidation"/>), the tetrahedralisation settings
    /// (<see cref="TetrahedralizationSettings.Validate"/>), the tetrahedraliser's and the
    /// model builder's checks (<see cref="TetrahedralBodyBuilder"/>), and a warning when an explicit integrator's substep at
    /// <see cref="AssumedFixedTimeStep"/> exceeds the model's stable step.
    /// </summary>
    public static class SoftBodyAuthoringValidation
    {
        /// <summary>Reads <paramref name="mesh"/> at <paramref name="scale"/> and builds the body from it; the inspector passes a cached version of <see cref="Build"/>.</summary>
        public delegate (SoftBodyMeshData Mesh, SoftBodyBuildResult Result) BuildFunction(Mesh mesh, float3 scale, in SoftBodyBuildSettings settings);

        /// <summary>Reads <paramref name="mesh"/> at <paramref name="scale"/> and builds a mass-spring or FEM body; the inspector passes a cached version of <see cref="BuildTetrahedral"/>.</summary>
        public delegate (SoftBodyMeshData Mesh, TetrahedralBodyBuild Build) TetrahedralBuildFunction(Mesh mesh, float3 scale,
            SoftBodyMethod method, in TetrahedralizationSettings tetrahedralization, in ElasticMaterial material,
            in MassSpringBuildSettings springs, in FemBuildSettings fem);

        /// <summary>
        /// The fixed step (s) the stability warning assumes: the default timestep of Entities' FixedStepSimulationSystemGroup.
        /// A project with another fixed rate should read the warning's stable step against its own substep.
        /// </summary>
        public const float AssumedFixedTimeStep = 1f / 60f;

        /// <summary>The issues of <paramref name="authoring"/> (building the body to find them).</summary>
        public static List<ValidationIssue> Validate(SoftBodyAuthoring authoring) => ValidateAndBuild(authoring).Issues;

        /// <summary>Validates <paramref name="authoring"/> and returns the build the baker needs.</summary>
        public static SoftBodyAuthoringBuild ValidateAndBuild(SoftBodyAuthoring authoring) => ValidateAndBuild(authoring, Build);

        /// <summary>Validates <paramref name="authoring"/>, building a shape-matching body with <paramref name="build"/>.</summary>
        public static SoftBodyAuthoringBuild ValidateAndBuild(SoftBodyAuthoring authoring, BuildFunction build) =>
            ValidateAndBuild(authoring, build, BuildTetrahedral);

        /// <summary>Validates <paramref name="authoring"/>, building the body of its method with <paramref name="build"/> or <paramref name="buildTetrahedral"/>.</summary>
        public static SoftBodyAuthoringBuild ValidateAndBuild(SoftBodyAuthoring authoring, BuildFunction build, TetrahedralBuildFunction buildTetrahedral)
        {
            if (authoring == null)
                throw new ArgumentNullException(nameof(authoring));
            var report = new SoftBodyAuthoringBuild { Method = authoring.method };
            Mesh mesh = FindReadableMesh(authoring, report.Issues);
            if (authoring.method == SoftBodyMethod.MassSpring || authoring.method == SoftBodyMethod.Fem)
            {
                ValidateTetrahedral(authoring, mesh, buildTetrahedral, report);
                return report;
            }
            if (authoring.method != SoftBodyMethod.ShapeMatching)
            {
                report.Issues.Add(ValidationIssue.Error(SoftBodyAuthoringIssueCode.MethodInvalid, -1,
                    $"Method {(int)authoring.method} on '{authoring.name}' is not a soft-body method. Pick Shape Matching, Mass Spring or FEM."));
                return report;
            }
            if (mesh != null)
            {
                (report.Mesh, report.Result) = build(mesh, authoring.BakedScale, authoring.BuildSettings);
                report.Issues.AddRange(report.Result.Issues);
            }
            else
                SoftBodyBuildSettingsValidation.Validate(authoring.BuildSettings, report.Issues);
            ShapeMatchingParameterValidation.Validate(authoring.Parameters, report.Issues);
            return report;
        }

        static void ValidateTetrahedral(SoftBodyAuthoring authoring, Mesh mesh, TetrahedralBuildFunction buildTetrahedral,
            SoftBodyAuthoringBuild report)
        {
            bool massSpring = authoring.method == SoftBodyMethod.MassSpring;
            ElasticMaterial material = authoring.Material;
            TetrahedralizationSettings tetrahedralization = authoring.TetrahedralizationSettings;
            bool materialValid = material.IsValid;
            if (!materialValid)
                report.Issues.Add(ValidationIssue.Error(massSpring ? MassSpringIssueCode.MaterialInvalid : FemIssueCode.MaterialInvalid, -1,
                    Invariant($"The material of '{authoring.name}' is invalid (Young's modulus {material.YoungsModulus} Pa, Poisson ratio {material.PoissonRatio}, ")
                    + Invariant($"density {material.Density} kg/m³, damping ratio {material.DampingRatio}). Use a Young's modulus above 0, a Poisson ratio from 0 ")
                    + "to below 0.5, a density above 0 and a damping ratio of at least 0, or pick a preset."));
            if (massSpring)
                MassSpringParameterValidation.Validate(authoring.MassSpringParameters, report.Issues);
            else
            {
                FemParameterValidation.Validate(authoring.FemParameters, report.Issues);
                FemParameterValidation.Validate(authoring.FemBuildSettings, report.Issues);
            }
            if (mesh == null || !materialValid)
            {
                TetrahedralizationSettings.Validate(tetrahedralization, report.Issues);
                return;
            }
            (report.Mesh, report.Tetrahedral) = buildTetrahedral(mesh, authoring.BakedScale, authoring.method, tetrahedralization, material,
                authoring.MassSpringBuildSettings, authoring.FemBuildSettings);
            report.Issues.AddRange(report.Tetrahedral.Issues);
            if (report.Tetrahedral.Succeeded)
                CheckStableStep(authoring, report.Tetrahedral.MaxStableStep, report.Issues);
        }

        /// <summary>
        /// Warns when the body's explicit integrator would take substeps longer than the model's stable step at
        /// <see cref="AssumedFixedTimeStep"/>: the body would blow up and the NaN guard would keep resetting it.
        /// </summary>
        public static void CheckStableStep(SoftBodyAuthoring authoring, double maxStableStep, List<ValidationIssue> issues)
        {
            int substeps = Math.Max(1, authoring.substeps);
            double h = AssumedFixedTimeStep / substeps;
            if (authoring.method == SoftBodyMethod.MassSpring)
            {
                ValidationIssue? issue = MassSpringStability.CheckStep(authoring.massSpringIntegrator, h, maxStableStep);
                if (issue.HasValue)
                    issues.Add(issue.Value);
                return;
            }
            if (!FemRunsExplicit(authoring.femModel, authoring.femIntegrator) || !(h > maxStableStep))
                return;
            int needed = (int)Math.Ceiling(AssumedFixedTimeStep / maxStableStep);
            issues.Add(ValidationIssue.Warning(FemIssueCode.StepAboveStableLimit, -1, Invariant(
                $"'{authoring.name}' is too stiff for its substep: at a fixed step of {AssumedFixedTimeStep * 1000f:0.##} ms and {substeps} substeps, ")
                + Invariant($"each substep is {h * 1000.0:0.###} ms, but the explicit integrator is stable only below {maxStableStep * 1000.0:0.####} ms ")
                + Invariant($"for this material and resolution. Use at least {needed} substeps, a softer material, a lower Resolution, or the ")
                + "Implicit Euler or XPBD (Neo-Hookean) integrator."));
        }

        /// <summary>True when <paramref name="integrator"/> runs explicitly for <paramref name="model"/> (symplectic Euler, or an unsupported pair that falls back to it).</summary>
        public static bool FemRunsExplicit(FemMaterialModel model, FemIntegrator integrator) =>
            integrator == FemIntegrator.SymplecticEuler
            || (integrator == FemIntegrator.Xpbd && model != FemMaterialModel.NeoHookean);

        /// <summary>The uncached mass-spring or FEM build: reads the mesh at <paramref name="scale"/> and runs <see cref="TetrahedralBodyBuilder.Build"/>.</summary>
        public static (SoftBodyMeshData Mesh, TetrahedralBodyBuild Build) BuildTetrahedral(Mesh mesh, float3 scale, SoftBodyMethod method,
            in TetrahedralizationSettings tetrahedralization, in ElasticMaterial material, in MassSpringBuildSettings springs,
            in FemBuildSettings fem)
        {
            SoftBodyMeshData data = SoftBodyMeshData.Read(mesh, scale);
            return (data, TetrahedralBodyBuilder.Build(data, method, tetrahedralization, material, springs, fem));
        }

        /// <summary>The uncached build: reads the mesh at <paramref name="scale"/> and runs <see cref="SoftBodyBuilder.Build"/>.</summary>
        public static (SoftBodyMeshData Mesh, SoftBodyBuildResult Result) Build(Mesh mesh, float3 scale, in SoftBodyBuildSettings settings)
        {
            SoftBodyMeshData data = SoftBodyMeshData.Read(mesh, scale);
            return (data, SoftBodyBuilder.Build(data.Vertices, data.Triangles, settings));
        }

        /// <summary>
        /// The MeshFilter's mesh when it exists and is readable; otherwise null, with the issue appended to
        /// <paramref name="issues"/> unless that is null (the gizmo only needs the mesh).
        /// </summary>
        public static Mesh FindReadableMesh(SoftBodyAuthoring authoring, List<ValidationIssue> issues)
        {
            MeshFilter meshFilter = authoring.GetComponent<MeshFilter>();
            if (meshFilter == null)
            {
                issues?.Add(ValidationIssue.Error(MeshBuildIssueCode.NoMesh, -1,
                    $"'{authoring.name}' has no MeshFilter. Add a MeshFilter with the mesh to simulate (the soft body deforms that mesh)."));
                return null;
            }
            Mesh mesh = meshFilter.sharedMesh;
            if (mesh == null)
            {
                issues?.Add(ValidationIssue.Error(MeshBuildIssueCode.NoMesh, -1,
                    $"The MeshFilter on '{authoring.name}' has no mesh. Assign the mesh to simulate in its Mesh field."));
                return null;
            }
            if (!mesh.isReadable)
            {
                issues?.Add(ValidationIssue.Error(MeshBuildIssueCode.MeshNotReadable, -1,
                    $"Mesh '{mesh.name}' on '{authoring.name}' is not readable: every soft body draws its own copy of the mesh, made at "
                    + "run time from the CPU copy. Select the model asset and enable Read/Write in its Model import settings."));
                return null;
            }
            return mesh;
        }
    }
}
