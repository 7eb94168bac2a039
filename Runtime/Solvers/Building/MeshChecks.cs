using System;
using System.Collections.Generic;
using Unity.Mathematics;
using static System.FormattableString;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Checks of a raw triangle mesh that must pass before it can be welded.</summary>
    public static class MeshChecks
    {
        /// <summary>
        /// Appends an error for an empty mesh, the first non-finite vertex, an index count that is not a
        /// multiple of 3, the first triangle with an out-of-range index, and zero-size bounds.
        /// Returns true when none of these was found.
        /// </summary>
        /// <param name="vertices">Render-vertex positions (m).</param>
        /// <param name="triangles">Vertex indices, three per triangle.</param>
        public static bool CheckInput(ReadOnlySpan<float3> vertices, ReadOnlySpan<int> triangles, List<ValidationIssue> issues)
        {
            if (vertices.Length == 0 || triangles.Length == 0)
            {
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.EmptyMesh, -1, vertices.Length == 0
                    ? "The mesh has no vertices. Assign a mesh that has geometry."
                    : Invariant($"The mesh has {vertices.Length} vertices but no triangles. Soft bodies are built from triangle meshes; check that the mesh's submeshes use triangle topology.")));
                return false;
            }

            bool ok = CheckVertices(vertices, issues);
            ok &= CheckTriangles(triangles, vertices.Length, issues);
            if (ok && AxisAlignedBox.Of(vertices).Diagonal == 0f)
            {
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.ZeroSize, -1, Invariant(
                    $"All {vertices.Length} vertices are at the same position (bounds of zero size), so there is no shape to keep. Check the mesh and its import scale.")));
                ok = false;
            }
            return ok;
        }

        static bool CheckVertices(ReadOnlySpan<float3> vertices, List<ValidationIssue> issues)
        {
            int first = -1, count = 0;
            for (int v = 0; v < vertices.Length; v++)
            {
                if (math.all(math.isfinite(vertices[v])))
                    continue;
                if (first < 0)
                    first = v;
                count++;
            }
            if (first < 0)
                return true;
            string kind = math.any(math.isnan(vertices[first])) ? "NaN" : "infinity";
            string others = count > 1 ? Invariant($" {count} vertices in all are affected.") : "";
            issues.Add(ValidationIssue.Error(MeshBuildIssueCode.NonFiniteVertex, first, Invariant(
                $"Vertex {first} has a non-finite position ({kind}).{others} Fix the mesh or its import settings.")));
            return false;
        }

        static bool CheckTriangles(ReadOnlySpan<int> triangles, int vertexCount, List<ValidationIssue> issues)
        {
            bool ok = true;
            if (triangles.Length % 3 != 0)
            {
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.TriangleCountNotMultipleOfThree, -1, Invariant(
                    $"The index buffer has {triangles.Length} indices, which is not a multiple of 3, so it is not a list of triangles. Re-export the mesh with triangle topology.")));
                ok = false;
            }

            int firstTriangle = -1, badIndex = 0, count = 0;
            for (int t = 0; t < triangles.Length / 3; t++)
            {
                for (int k = 0; k < 3; k++)
                {
                    int index = triangles[3 * t + k];
                    if ((uint)index < (uint)vertexCount)
                        continue;
                    if (firstTriangle < 0)
                    {
                        firstTriangle = t;
                        badIndex = index;
                    }
                    count++;
                    break;
                }
            }
            if (firstTriangle >= 0)
            {
                string others = count > 1 ? Invariant($" {count} triangles in all are affected.") : "";
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.TriangleIndexOutOfRange, firstTriangle, Invariant(
                    $"Triangle {firstTriangle} refers to vertex {badIndex}, but the mesh has {vertexCount} vertices (valid indices 0 to {vertexCount - 1}).{others} The index buffer is corrupt; re-import or re-export the mesh.")));
                ok = false;
            }
            return ok;
        }
    }
}
