using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Entities;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>Bakes a <see cref="FluidDrainAuthoring"/> into a <see cref="FluidDrainVolume"/>; an invalid drain is not baked and the error is logged.</summary>
    public sealed class FluidDrainBaker : Baker<FluidDrainAuthoring>
    {
        public override void Bake(FluidDrainAuthoring authoring)
        {
            DependsOn(authoring.transform);
            var issues = new List<ValidationIssue>();
            FluidDrain drain = authoring.ToDrain();
            FluidValidation.ValidateDrain(drain, 0, issues);
            if (authoring.fluid == null)
                issues.Add(ValidationIssue.Error(FluidEmissionIssueCode.DrainInvalid, -1, "The drain has no fluid: assign the Fluid it drains."));
            if (BakeIssueLog.Report(issues, "Fluid Drain", authoring, "The drain was not baked."))
                return;
            AddComponent(GetEntity(TransformUsageFlags.None), new FluidDrainVolume { Drain = drain, Fluid = GetEntity(authoring.fluid, TransformUsageFlags.None) });
        }
    }
}
