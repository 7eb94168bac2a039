using System;
using System.Collections.Generic;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Merges render vertices that share a position (split for UV seams, hard normals or poles) into
    /// particles, and records which particle each render vertex follows.
    /// </summary>
    public static class MeshWelding
    {
        /// <summary>Default weld tolerance relative to the bounds diagonal (dimensionless).</summary>
        public const float DefaultRelativeTolerance = 1e-5f;

        /// <summary>
        /// Cells of the weld grid are at least diagonal / 2²⁰, so that cell coordinates stay within the
        /// grid's 21-bit keys even for a zero tolerance.
        /// </summary>
        const float k_MinCellFractionOfDiagonal = 1f / (1 << 20);

        /// <summary>
        /// The weld distance (m): <paramref name="absolute"/> when it is &gt; 0, otherwise
        /// <paramref name="relative"/> × the diagonal of <paramref name="bounds"/>.
        /// </summary>
        public static float ResolveTolerance(in AxisAlignedBox bounds, float relative, float absolute) =>
            absolute > 0f ? absolute : relative * bounds.Diagonal;

        /// <summary>
        /// Resolves the weld distance of a build's settings (<see cref="ResolveTolerance"/>) and welds <paramref name="vertices"/>;
        /// false with a <see cref="MeshBuildIssueCode.WeldToleranceInvalid"/> error in <paramref name="issues"/> when the
        /// distance is not finite (an absurd relative tolerance on a huge mesh). The builders of every method call this.
        /// </summary>
        /// <param name="vertices">Render-vertex positions (m), finite.</param>
        /// <param name="bounds">Their bounds.</param>
        /// <param name="relative">Weld tolerance relative to the bounds diagonal (dimensionless).</param>
        /// <param name="absolute">Weld distance (m); &gt; 0 overrides <paramref name="relative"/>.</param>
        /// <param name="issues">Receives the error.</param>
        /// <param name="welded">The welded particles (default when false).</param>
        public static bool TryWeld(ReadOnlySpan<float3> vertices, in AxisAlignedBox bounds, float relative, float absolute,
            List<ValidationIssue> issues, out WeldedVertices welded)
        {
            float tolerance = ResolveTolerance(bounds, relative, absolute);
            if (!math.isfinite(tolerance))
            {
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.WeldToleranceInvalid, -1, FormattableString.Invariant(
                    $"WeldTolerance {relative} times the mesh diagonal {bounds.Diagonal} m is not a finite distance. Use a tolerance near the default {DefaultRelativeTolerance}.")));
                welded = default;
                return false;
            }
            welded = Weld(vertices, tolerance);
            return true;
        }

        /// <summary>
        /// Welds <paramref name="vertices"/> (finite) in order: each vertex joins the lowest-numbered existing
        /// particle within <paramref name="tolerance"/> (distance ≤ tolerance), or starts a new particle
        /// at its own position. A particle therefore sits exactly at its first vertex (positions are not
        /// averaged), and chains of vertices each within the tolerance of the next are not merged
        /// transitively. Deterministic: the result depends only on the input order and values.
        /// </summary>
        /// <param name="vertices">Render-vertex positions (m).</param>
        /// <param name="tolerance">Weld distance (m, ≥ 0; 0 merges only identical positions).</param>
        public static WeldedVertices Weld(ReadOnlySpan<float3> vertices, float tolerance)
        {
            if (!(tolerance >= 0f) || !math.isfinite(tolerance))
                throw new ArgumentOutOfRangeException(nameof(tolerance), tolerance, "The weld tolerance must be finite and ≥ 0.");
            AxisAlignedBox bounds = AxisAlignedBox.Of(vertices);
            float cell = math.max(tolerance, bounds.Diagonal * k_MinCellFractionOfDiagonal);
            if (!(cell > 0f) || !math.isfinite(cell))
                cell = math.max(tolerance, 1f);
            var grid = new PointGrid(bounds.Min, cell);
            var positions = new List<float3>();
            var vertexToParticle = new int[vertices.Length];
            for (int v = 0; v < vertices.Length; v++)
            {
                int particle = grid.LowestIndexWithin(vertices[v], tolerance, inclusive: true);
                if (particle < 0)
                {
                    particle = positions.Count;
                    positions.Add(vertices[v]);
                    grid.Add(vertices[v], particle);
                }
                vertexToParticle[v] = particle;
            }
            return new WeldedVertices { Positions = positions.ToArray(), VertexToParticle = vertexToParticle, Tolerance = tolerance };
        }

        /// <summary>Rewrites render-vertex triangles as particle triangles (same order, same winding).</summary>
        public static int[] RemapTriangles(ReadOnlySpan<int> triangles, int[] vertexToParticle)
        {
            var result = new int[triangles.Length];
            for (int i = 0; i < triangles.Length; i++)
                result[i] = vertexToParticle[triangles[i]];
            return result;
        }
    }
}
