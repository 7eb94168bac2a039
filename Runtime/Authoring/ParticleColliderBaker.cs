using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Entities;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Bakes a <see cref="ParticleColliderAuthoring"/> into a <see cref="ParticleCollider"/> holding its
    /// world-space shape. A collider with a validation error is not baked, and the error is logged with the
    /// GameObject as context.
    /// </summary>
    public sealed class ParticleColliderBaker : Baker<ParticleColliderAuthoring>
    {
        public override void Bake(ParticleColliderAuthoring authoring)
        {
            // The world-space shape depends on the whole parent chain of the Transform.
            DependsOn(authoring.transform);

            List<ValidationIssue> issues = ParticleColliderValidation.Validate(authoring);
            if (BakeIssueLog.Report(issues, "Particle Collider", authoring, "The collider was not baked."))
                return;

            Entity entity = GetEntity(TransformUsageFlags.None);
            AddComponent(entity, new ParticleCollider { Shape = authoring.ToWorldShape() });
        }
    }
}
