using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;
using Unity.Transforms;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Bakes a <see cref="SoftBodyAuthoring"/>: validates it (<see cref="SoftBodyAuthoringValidation"/>), builds the
    /// shape blob and adds the soft-body components with <see cref="SoftBodyUninitialized"/> enabled, so the
    /// runtime places the body at the baked pose on its first step. On any validation error the error is logged
    /// with the GameObject as context and no simulation component is added (the mesh still renders, static).
    /// <para>
    /// Transform: the body is a root entity in world space at scale 1 (<see cref="TransformUsageFlags.ManualOverride"/>
    /// with a <see cref="LocalTransform"/> of the world position and rotation); the Transform's scale is baked into
    /// the rest shape. This keeps non-uniform scale and parent GameObjects from adding a PostTransformMatrix or a
    /// Parent that the world-space simulation would fight.
    /// </para>
    /// </summary>
    public sealed class SoftBodyBaker : Baker<SoftBodyAuthoring>
    {
        public override void Bake(SoftBodyAuthoring authoring)
        {
            // Rebake when the MeshFilter, its mesh or the Transform (pose and scale are baked) change.
            MeshFilter meshFilter = GetComponent<MeshFilter>();
            Mesh mesh = meshFilter != null ? meshFilter.sharedMesh : null;
            if (mesh != null)
                DependsOn(mesh);
            Transform transform = authoring.transform;
            DependsOn(transform);

            SoftBodyAuthoringBuild build = SoftBodyAuthoringValidation.ValidateAndBuild(authoring);
            Log(authoring, build.Issues);
            if (!build.Succeeded)
                return;

            Entity entity = GetEntity(TransformUsageFlags.ManualOverride);
            AddComponent(entity, LocalTransform.FromPositionRotation(UnityMathConversions.ToFloat3(transform.position),
                UnityMathConversions.ToQuaternion(transform.rotation)));
            AddComponent<LocalToWorld>(entity); // written by the transform systems from LocalTransform

            SoftBodyBuildResult result = build.Result;
            BlobAssetReference<SoftBodyShapeBlob> blob = SoftBodyShapeBlobFactory.Create(result.Model, result.VertexToParticle,
                build.Mesh.Triangles, Allocator.Persistent);
            AddBlobAsset(ref blob, out _);

            ShapeMatchingParameters parameters = authoring.Parameters;
            AddComponent(entity, new SoftBodyShape { Blob = blob });
            AddComponent(entity, new SoftBodySettings { Value = parameters });
            AddComponent(entity, new SoftBodyState { LastReport = new ShapeMatchingStepReport { BadParticle = -1 } });
            AddBuffer<SoftBodyPosition>(entity);
            AddBuffer<SoftBodyVelocity>(entity);
            AddBuffer<SoftBodyCluster>(entity);
            if (SoftBodyArchetype.NeedsQuadraticInverse(parameters, result.Model.QuadraticInverse.Length))
                AddBuffer<SoftBodyQuadraticInverse>(entity);
            AddComponent<SoftBodyUninitialized>(entity);
            SetComponentEnabled<SoftBodyUninitialized>(entity, true);
            AddComponent(entity, new SoftBodyImpulse());
            SetComponentEnabled<SoftBodyImpulse>(entity, false);
            AddComponent(entity, new SoftBodyRenderMesh { Mesh = mesh });
        }

        static void Log(SoftBodyAuthoring authoring, List<SoftBodyIssue> issues)
        {
            foreach (SoftBodyIssue issue in issues)
            {
                if (issue.Severity == SoftBodyIssueSeverity.Error)
                    Debug.LogError($"Soft Body on '{authoring.name}' was not baked ({issue.Code}): {issue.Message}", authoring);
                else
                    Debug.LogWarning($"Soft Body on '{authoring.name}' ({issue.Code}): {issue.Message}", authoring);
            }
        }
    }
}
