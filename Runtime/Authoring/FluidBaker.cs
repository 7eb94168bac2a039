using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Entities;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Bakes a <see cref="FluidAuthoring"/> into <see cref="FluidSettings"/>, <see cref="FluidRuntime"/> and the empty
    /// particle buffers (sized to the budget by the simulation system). A fluid with a validation error is not baked;
    /// every issue is logged with the GameObject as context.
    /// </summary>
    public sealed class FluidBaker : Baker<FluidAuthoring>
    {
        public override void Bake(FluidAuthoring authoring)
        {
            DependsOn(authoring.transform);
            FluidParameters parameters = authoring.ToParameters();
            var issues = new List<SoftBodyIssue>();
            FluidValidation.Validate(parameters, authoring.particleBudget, issues);
            if (authoring.storage == FluidStorage.Entities && authoring.particlePrefab == null)
                issues.Add(SoftBodyIssue.Error(SoftBodyIssueCode.FluidPrefabMissing, -1,
                    "Entities storage needs a particle prefab with a Metaball Particle component; assign one or use Packed storage."));
            if (BakeIssueLog.Report(issues, "Fluid", authoring, "The fluid was not baked."))
                return;

            Entity entity = GetEntity(TransformUsageFlags.None);
            AddComponent(entity, new FluidSettings
            {
                Parameters = parameters,
                Budget = authoring.particleBudget,
                Color = authoring.PresetColor,
                Storage = authoring.storage,
                ParticlePrefab = authoring.storage == FluidStorage.Entities ? GetEntity(authoring.particlePrefab, TransformUsageFlags.Dynamic) : Entity.Null,
            });
            AddComponent(entity, new FluidRuntime());
            AddBuffer<FluidPosition>(entity);
            AddBuffer<FluidVelocity>(entity);
            AddBuffer<FluidAge>(entity);
            AddBuffer<FluidLifetime>(entity);
            AddBuffer<FluidAttribute>(entity);
            AddBuffer<FluidId>(entity);
            AddBuffer<FluidScratchInt>(entity);
            AddBuffer<FluidScratchFloat>(entity);
            AddBuffer<FluidScratchVector>(entity);
            AddBuffer<FluidTapRuntime>(entity);
        }
    }
}
