using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Entities;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Bakes a <see cref="SoftBodyColliderAuthoring"/> into a <see cref="SoftBodyCollider"/> holding its
    /// world-space shape. A collider with a validation error is not baked, and the error is logged with the
    /// GameObject as context.
    /// </summary>
    public sealed class SoftBodyColliderBaker : Baker<SoftBodyColliderAuthoring>
    {
        public override void Bake(SoftBodyColliderAuthoring authoring)
        {
            // The world-space shape depends on the whole parent chain of the Transform.
            DependsOn(authoring.transform);

            List<ValidationIssue> issues = SoftBodyColliderValidation.Validate(authoring);
            if (BakeIssueLog.Report(issues, "Soft Body Collider", authoring, "The collider was not baked."))
                return;

            Entity entity = GetEntity(TransformUsageFlags.None);
            AddComponent(entity, new SoftBodyCollider { Shape = authoring.ToWorldShape() });
        }
    }
}
