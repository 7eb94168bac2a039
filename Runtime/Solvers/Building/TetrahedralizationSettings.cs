using System.Collections.Generic;
using Unity.Mathematics;
using static System.FormattableString;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// How <see cref="LatticeTetrahedralizer"/> turns a closed triangle mesh into a tetrahedral volume mesh. Each
    /// field's summary doubles as its inspector tooltip; units are in brackets.
    /// </summary>
    public struct TetrahedralizationSettings
    {
        /// <summary>Default cells along the mesh's longest side.</summary>
        public const int DefaultResolution = 8;
        /// <summary>Smallest resolution: one cell along the longest side.</summary>
        public const int MinResolution = 1;
        /// <summary>Largest resolution: 128 cells along the longest side (at most 128³ cells, 6 tetrahedra each).</summary>
        public const int MaxResolution = 128;
        /// <summary>Default node limit per body.</summary>
        public const int DefaultMaxNodes = 65536;

        /// <summary>
        /// Lattice cells along the mesh's longest side [count, 1..128; default 8]. The cells are cubes of side
        /// longest side / Resolution; each kept cell becomes 6 tetrahedra. Cost grows with the cube of it: a
        /// compact body keeps about half of the R³ cells (R = 8: ~300 cells, ~1 800 tetrahedra, ~500 nodes;
        /// R = 16: 8× that), and the solver's time per step grows in proportion. The bake's inside test costs
        /// about R² × triangles winding-number terms. The volume exceeds the mesh's by about surface area ×
        /// cell size / 2, because cells the surface passes through are kept; that excess falls as 1/R.
        /// </summary>
        public int Resolution;

        /// <summary>
        /// Most nodes the volume mesh may have [count, &gt; 0; default 65536]. Building fails above it: lower
        /// Resolution or raise the limit.
        /// </summary>
        public int MaxNodes;

        /// <summary>
        /// Render vertices closer than this fraction of the mesh's bounds diagonal are merged before the
        /// closedness check and the inside test [dimensionless, ≥ 0; default 1e-5], so meshes split at UV seams
        /// and hard edges still count as closed. Ignored when WeldDistance is above 0. Every render vertex is
        /// still embedded at its own position.
        /// </summary>
        public float WeldTolerance;

        /// <summary>Absolute weld distance [m, ≥ 0]: when above 0 it replaces WeldTolerance.</summary>
        public float WeldDistance;

        /// <summary>Resolution 8, at most 65536 nodes, weld tolerance 1e-5 of the diagonal.</summary>
        public static TetrahedralizationSettings Default => new TetrahedralizationSettings
        {
            Resolution = DefaultResolution,
            MaxNodes = DefaultMaxNodes,
            WeldTolerance = MeshWelding.DefaultRelativeTolerance,
            WeldDistance = 0f,
        };

        /// <summary>
        /// A copy with every field in range: Resolution clamped to 1..128, MaxNodes at least 1 (default when not
        /// positive), weld tolerances that are negative or not finite replaced by their defaults.
        /// </summary>
        public TetrahedralizationSettings Sanitized() => new TetrahedralizationSettings
        {
            Resolution = math.clamp(Resolution, MinResolution, MaxResolution),
            MaxNodes = MaxNodes > 0 ? MaxNodes : DefaultMaxNodes,
            WeldTolerance = IsFiniteNonNegative(WeldTolerance) ? WeldTolerance : MeshWelding.DefaultRelativeTolerance,
            WeldDistance = IsFiniteNonNegative(WeldDistance) ? WeldDistance : 0f,
        };

        /// <summary>Appends an error for every invalid field; returns true when there was none.</summary>
        public static bool Validate(in TetrahedralizationSettings settings, List<ValidationIssue> issues)
        {
            int before = issues.Count;
            if (settings.Resolution < MinResolution || settings.Resolution > MaxResolution)
                issues.Add(ValidationIssue.Error(TetrahedralMeshIssueCode.TetResolutionOutOfRange, -1, Invariant(
                    $"Resolution is {settings.Resolution}; it must be between {MinResolution} and {MaxResolution} cells along the mesh's longest side (default {DefaultResolution}).")));
            if (settings.MaxNodes <= 0)
                issues.Add(ValidationIssue.Error(TetrahedralMeshIssueCode.MaxNodesInvalid, -1, Invariant(
                    $"MaxNodes is {settings.MaxNodes}; it must be at least 1 (default {DefaultMaxNodes}).")));
            if (!IsFiniteNonNegative(settings.WeldTolerance))
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.WeldToleranceInvalid, -1, Invariant(
                    $"WeldTolerance is {settings.WeldTolerance}; it must be a finite fraction of the mesh diagonal, at least 0 (default {MeshWelding.DefaultRelativeTolerance}).")));
            if (!IsFiniteNonNegative(settings.WeldDistance))
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.WeldToleranceInvalid, -1, Invariant(
                    $"WeldDistance is {settings.WeldDistance} m; it must be a finite distance of at least 0 m (0 uses WeldTolerance).")));
            return issues.Count == before;
        }

        static bool IsFiniteNonNegative(float x) => x >= 0f && math.isfinite(x);
    }
}
