using System.Collections.Generic;
using Unity.Mathematics;
using static System.FormattableString;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Checks <see cref="SoftBodyBuildSettings"/> on its own (no mesh needed), for the builder and the inspector.</summary>
    public static class SoftBodyBuildSettingsValidation
    {
        /// <summary>Appends an error for every invalid field; returns true when there was none.</summary>
        public static bool Validate(in SoftBodyBuildSettings settings, List<ValidationIssue> issues)
        {
            int before = issues.Count;
            if (!IsFiniteNonNegative(settings.WeldTolerance))
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.WeldToleranceInvalid, -1, Invariant(
                    $"WeldTolerance is {settings.WeldTolerance}; it must be a finite fraction of the mesh diagonal, at least 0 (default {MeshWelding.DefaultRelativeTolerance}).")));
            if (!IsFiniteNonNegative(settings.WeldDistance))
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.WeldToleranceInvalid, -1, Invariant(
                    $"WeldDistance is {settings.WeldDistance} m; it must be a finite distance of at least 0 m (0 uses WeldTolerance).")));
            if (!(settings.TotalMass > 0f) || !math.isfinite(settings.TotalMass))
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.TotalMassNotPositive, -1, Invariant(
                    $"TotalMass is {settings.TotalMass} kg; it must be a finite mass above 0 kg (for example 1 kg).")));
            if (!IsFiniteNonNegative(settings.ClusterSize))
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.ClusterSizeInvalid, -1, Invariant(
                    $"ClusterSize is {settings.ClusterSize} m; it must be a finite size of at least 0 m (0 makes one cluster of the whole body).")));
            if (!IsFiniteNonNegative(settings.InteriorSpacing))
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.InteriorSpacingInvalid, -1, Invariant(
                    $"InteriorSpacing is {settings.InteriorSpacing} m; it must be a finite distance of at least 0 m (0 chooses one eighth of the mesh's longest side).")));
            if (settings.MaxParticles <= 0)
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.MaxParticlesInvalid, -1, Invariant(
                    $"MaxParticles is {settings.MaxParticles}; it must be at least 1 (default {SoftBodyBuildSettings.DefaultMaxParticles}).")));
            return issues.Count == before;
        }

        static bool IsFiniteNonNegative(float x) => x >= 0f && math.isfinite(x);
    }
}
