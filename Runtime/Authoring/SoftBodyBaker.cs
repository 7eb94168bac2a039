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
    /// blobs of its method (shape matching here; mass-spring and FEM through <see cref="TetrahedralBodyBake"/>) and adds
    /// the soft-body components with <see cref="SoftBodyUninitialized"/> enabled, so the
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

            if (build.Method != SoftBodyMethod.ShapeMatching)
            {
                TetrahedralBodyBake.Write(authoring, build, mesh, new Writer(this, entity));
                return;
            }

            SoftBodyBuildResult result = build.Result;
            BlobAssetReference<ShapeMatchingShapeBlob> blob = ShapeMatchingShapeBlobFactory.Create(result.Model, result.VertexToParticle,
                build.Mesh.Triangles, Allocator.Persistent);
            AddBlobAsset(ref blob, out _);

            ShapeMatchingParameters parameters = authoring.Parameters;
            AddComponent(entity, new ShapeMatchingShape { Blob = blob });
            AddComponent(entity, new ShapeMatchingSettings { Value = parameters });
            AddComponent(entity, ParticleBodyState.Unstepped);
            AddComponent(entity, ShapeMatchingDiagnostics.Unstepped);
            AddBuffer<SoftBodyPosition>(entity);
            AddBuffer<SoftBodyVelocity>(entity);
            AddBuffer<ShapeMatchingCluster>(entity);
            if (SoftBodyArchetype.NeedsQuadraticInverse(parameters, result.Model.QuadraticInverse.Length))
                AddBuffer<ShapeMatchingQuadraticInverse>(entity);
            AddComponent<SoftBodyUninitialized>(entity);
            SetComponentEnabled<SoftBodyUninitialized>(entity, true);
            AddComponent(entity, new SoftBodyImpulse());
            SetComponentEnabled<SoftBodyImpulse>(entity, false);
            AddComponent(entity, new SoftBodyRenderMesh { Mesh = mesh });
        }

        /// <summary>The baker as an <see cref="ISoftBodyEntityWriter"/> for one entity.</summary>
        sealed class Writer : ISoftBodyEntityWriter
        {
            readonly IBaker m_Baker;
            readonly Entity m_Entity;

            public Writer(IBaker baker, Entity entity)
            {
                m_Baker = baker;
                m_Entity = entity;
            }

            public void AddComponent<T>(in T component) where T : unmanaged, IComponentData => m_Baker.AddComponent(m_Entity, component);

            public void AddComponent<T>(in T component, bool enabled) where T : unmanaged, IComponentData, IEnableableComponent
            {
                m_Baker.AddComponent(m_Entity, component);
                m_Baker.SetComponentEnabled<T>(m_Entity, enabled);
            }

            public void AddBuffer<T>() where T : unmanaged, IBufferElementData => m_Baker.AddBuffer<T>(m_Entity);

            public void AddBlob<T>(ref BlobAssetReference<T> blob) where T : unmanaged => m_Baker.AddBlobAsset(ref blob, out _);
        }

        static void Log(SoftBodyAuthoring authoring, List<ValidationIssue> issues)
        {
            foreach (ValidationIssue issue in issues)
            {
                if (issue.Severity == IssueSeverity.Error)
                    Debug.LogError($"Soft Body on '{authoring.name}' was not baked ({issue.Code}): {issue.Message}", authoring);
                else
                    Debug.LogWarning($"Soft Body on '{authoring.name}' ({issue.Code}): {issue.Message}", authoring);
            }
        }
    }
}
