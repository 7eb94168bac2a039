using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Every check on a <see cref="SoftBodyAuthoring"/>, in one place, used by the baker and the inspector:
    /// 1. a MeshFilter with a mesh (<see cref="SoftBodyIssueCode.NoMesh"/>);
    /// 2. the mesh is readable on the CPU (<see cref="SoftBodyIssueCode.MeshNotReadable"/>);
    /// 3. the builder's checks of the mesh and build settings (<see cref="SoftBodyBuilder"/>); without a readable
    ///    mesh, the build settings alone (<see cref="SoftBodyBuildSettingsValidation"/>);
    /// 4. the solver parameters (<see cref="ShapeMatchingParameterValidation"/>).
    /// </summary>
    public static class SoftBodyAuthoringValidation
    {
        /// <summary>Reads <paramref name="mesh"/> at <paramref name="scale"/> and builds the body from it; the inspector passes a cached version of <see cref="Build"/>.</summary>
        public delegate (SoftBodyMeshData Mesh, SoftBodyBuildResult Result) BuildFunction(Mesh mesh, float3 scale, in SoftBodyBuildSettings settings);

        /// <summary>The issues of <paramref name="authoring"/> (building the body to find them).</summary>
        public static List<SoftBodyIssue> Validate(SoftBodyAuthoring authoring) => ValidateAndBuild(authoring).Issues;

        /// <summary>Validates <paramref name="authoring"/> and returns the build the baker needs.</summary>
        public static SoftBodyAuthoringBuild ValidateAndBuild(SoftBodyAuthoring authoring) => ValidateAndBuild(authoring, Build);

        /// <summary>Validates <paramref name="authoring"/>, building the body with <paramref name="build"/>.</summary>
        public static SoftBodyAuthoringBuild ValidateAndBuild(SoftBodyAuthoring authoring, BuildFunction build)
        {
            if (authoring == null)
                throw new ArgumentNullException(nameof(authoring));
            var report = new SoftBodyAuthoringBuild();
            Mesh mesh = FindReadableMesh(authoring, report.Issues);
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
        public static Mesh FindReadableMesh(SoftBodyAuthoring authoring, List<SoftBodyIssue> issues)
        {
            MeshFilter meshFilter = authoring.GetComponent<MeshFilter>();
            if (meshFilter == null)
            {
                issues?.Add(SoftBodyIssue.Error(SoftBodyIssueCode.NoMesh, -1,
                    $"'{authoring.name}' has no MeshFilter. Add a MeshFilter with the mesh to simulate (the soft body deforms that mesh)."));
                return null;
            }
            Mesh mesh = meshFilter.sharedMesh;
            if (mesh == null)
            {
                issues?.Add(SoftBodyIssue.Error(SoftBodyIssueCode.NoMesh, -1,
                    $"The MeshFilter on '{authoring.name}' has no mesh. Assign the mesh to simulate in its Mesh field."));
                return null;
            }
            if (!mesh.isReadable)
            {
                issues?.Add(SoftBodyIssue.Error(SoftBodyIssueCode.MeshNotReadable, -1,
                    $"Mesh '{mesh.name}' on '{authoring.name}' is not readable: every soft body draws its own copy of the mesh, made at "
                    + "run time from the CPU copy. Select the model asset and enable Read/Write in its Model import settings."));
                return null;
            }
            return mesh;
        }
    }
}
