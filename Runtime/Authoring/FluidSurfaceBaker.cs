using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Bakes a <see cref="FluidSurfaceAuthoring"/> into <see cref="FluidSurface"/> on the fluid's entity: the look
    /// (sanitized, each replaced value reported) and the sphere radius in metres. A surface without a fluid or with an
    /// unusable radius is not baked.
    /// </summary>
    public sealed class FluidSurfaceBaker : Baker<FluidSurfaceAuthoring>
    {
        public override void Bake(FluidSurfaceAuthoring authoring)
        {
            var fluid = GetComponent<FluidAuthoring>();
            DependsOn(fluid);
            var issues = new List<ValidationIssue>();
            float scale = authoring.radiusInSpacings;
            if (fluid == null)
                issues.Add(ValidationIssue.Error(FluidSurfaceIssueCode.SettingsInvalid, -1, "The fluid surface needs a Fluid component on the same GameObject."));
            if (!(scale > 0f) || !math.isfinite(scale))
                issues.Add(ValidationIssue.Error(FluidSurfaceIssueCode.SettingsInvalid, -1, $"The sphere radius is {scale} particle spacings; it must be positive and finite."));
            else if (scale < 0.5f || scale > 2f)
                issues.Add(ValidationIssue.Warning(FluidSurfaceIssueCode.RadiusUnusual, -1,
                    $"The sphere radius is {scale} particle spacings: below 0.5 neighbours do not touch (gaps), above 2 the surface blurs."));
            FluidLook look = authoring.Look.Sanitized(out string problems);
            if (problems.Length > 0)
                issues.Add(ValidationIssue.Warning(FluidSurfaceIssueCode.LookReplaced, -1, "Look: " + problems));
            if (BakeIssueLog.Report(issues, "Fluid surface", authoring, "The fluid surface was not baked."))
                return;
            AddComponent(GetEntity(TransformUsageFlags.None), new FluidSurface
            {
                Look = look,
                ParticleRadius = scale * fluid.particleSpacing,
            });
        }
    }
}
