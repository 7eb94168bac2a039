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
            var issues = new List<ValidationIssue>();
            FluidValidation.Validate(parameters, authoring.particleBudget, issues);
            if (authoring.storage == FluidStorage.Entities && authoring.particlePrefab == null)
                issues.Add(ValidationIssue.Error(FluidIssueCode.PrefabMissing, -1,
                    "Entities storage needs a particle prefab with a Metaball Particle component; assign one or use Packed storage."));
            if (authoring.backend != FluidBackend.Cpu && authoring.computeShader == null)
                issues.Add(ValidationIssue.Warning(FluidIssueCode.ComputeShaderMissing, -1,
                    "The fluid asks for the GPU but has no compute shader: assign Shaders/FluidSolver.compute, or it runs on the CPU."));
            if (authoring.backend != FluidBackend.Cpu && authoring.storage == FluidStorage.Entities)
                issues.Add(ValidationIssue.Warning(FluidIssueCode.GpuNeedsPackedStorage, -1,
                    "Entities storage (one entity per particle) runs on the CPU; use Packed storage to run the fluid on the GPU."));
            if (authoring.backend != FluidBackend.Cpu && authoring.readback == FluidReadback.EveryNFrames && authoring.readbackInterval < 1)
                issues.Add(ValidationIssue.Error(FluidIssueCode.ReadbackIntervalInvalid, -1,
                    $"The read-back interval is {authoring.readbackInterval} frames; it must be at least 1."));
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
                Backend = authoring.backend,
                Readback = authoring.readback,
                ReadbackInterval = authoring.readbackInterval,
            });
            if (authoring.backend != FluidBackend.Cpu && authoring.computeShader != null)
                AddComponent(entity, new FluidComputeShader { Shader = authoring.computeShader });
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
