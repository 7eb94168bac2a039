using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Entities;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Bakes a <see cref="FluidTapAuthoring"/> into a <see cref="FluidTap"/> (world-space settings, at most four bursts,
    /// the fluid entity). A tap with a validation error (including a steady-state alive count above the fluid's budget)
    /// is not baked; every issue is logged with the GameObject as context.
    /// </summary>
    public sealed class FluidTapBaker : Baker<FluidTapAuthoring>
    {
        public override void Bake(FluidTapAuthoring authoring)
        {
            DependsOn(authoring.transform);
            var issues = new List<ValidationIssue>();
            FluidTapBurst[] bursts = authoring.bursts ?? new FluidTapBurst[0];
            if (authoring.fluid == null)
                issues.Add(ValidationIssue.Error(FluidEmissionIssueCode.TapShapeInvalid, -1, "The tap has no fluid: assign a Fluid to pour into."));
            else
            {
                DependsOn(authoring.fluid);
                FluidValidation.ValidateTap(authoring.ToSettings(), bursts, authoring.fluid.particleSpacing, authoring.fluid.particleBudget, issues);
            }
            if (bursts.Length > FluidTap.MaxBursts)
                issues.Add(ValidationIssue.Warning(FluidEmissionIssueCode.TapBurstInvalid, FluidTap.MaxBursts,
                    $"A tap keeps at most {FluidTap.MaxBursts} bursts; bursts {FluidTap.MaxBursts} and later are ignored."));
            if (BakeIssueLog.Report(issues, "Fluid Tap", authoring, "The tap was not baked."))
                return;

            var tap = new FluidTap
            {
                Settings = authoring.ToSettings(),
                Fluid = GetEntity(authoring.fluid, TransformUsageFlags.None),
                BurstCount = System.Math.Min(bursts.Length, FluidTap.MaxBursts),
            };
            for (int b = 0; b < tap.BurstCount; b++)
                tap.SetBurst(b, bursts[b]);
            AddComponent(GetEntity(TransformUsageFlags.None), tap);
        }
    }
}
