using System;
using System.Collections.Generic;
using Unity.Mathematics;
using static System.FormattableString;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Checks any tetrahedral mesh (built or supplied by the user) before a solver uses it: indices in range,
    /// finite nodes, positive volumes, shape quality and unused nodes. Self-contained; a bake-time tool.
    /// <para>
    /// Quality measure: q = 6√2·V / ℓ³_rms (V: signed volume, ℓ_rms: root mean square of the 6 edge lengths), in
    /// double. q = 1 for the regular tetrahedron, ≈ 0.657 for a Kuhn-split cube, 0 for a flat one, negative for an
    /// inverted one; it scales as the smallest height over the longest edge, so it falls for slivers, needles and caps
    /// alike, whose stiffness matrices are ill-conditioned.
    /// </para>
    /// </summary>
    public static class TetrahedralMeshChecks
    {
        /// <summary>
        /// |q| at or below this is zero volume (error): float32 nodes carry about 1.2e-7 relative round-off per
        /// coordinate, so a volume this small relative to ℓ³ cannot be told from a flat tetrahedron.
        /// </summary>
        public const double DegenerateQuality = 1e-6;

        /// <summary>Quality below this (a tenth of the regular tetrahedron's) draws a sliver warning.</summary>
        public const double SliverQuality = 0.1;

        /// <summary>q = 6√2·V / ℓ³_rms of the tetrahedron (a, b, c, d), in double (see the class summary); 0 when all nodes coincide.</summary>
        public static double Quality(float3 a, float3 b, float3 c, float3 d)
        {
            double ax = a.x, ay = a.y, az = a.z;
            double bx = b.x - ax, by = b.y - ay, bz = b.z - az;
            double cx = c.x - ax, cy = c.y - ay, cz = c.z - az;
            double dx = d.x - ax, dy = d.y - ay, dz = d.z - az;
            double sixV = bx * (cy * dz - cz * dy) + by * (cz * dx - cx * dz) + bz * (cx * dy - cy * dx);
            double sum = bx * bx + by * by + bz * bz + cx * cx + cy * cy + cz * cz + dx * dx + dy * dy + dz * dz
                         + Sq(c.x - (double)b.x, c.y - (double)b.y, c.z - (double)b.z)
                         + Sq(d.x - (double)b.x, d.y - (double)b.y, d.z - (double)b.z)
                         + Sq(d.x - (double)c.x, d.y - (double)c.y, d.z - (double)c.z);
            double rms = Math.Sqrt(sum / 6.0);
            return rms > 0.0 ? Math.Sqrt(2.0) * sixV / (rms * rms * rms) : 0.0;
        }

        static double Sq(double x, double y, double z) => x * x + y * y + z * z;

        /// <summary>Σ signed volumes of the tetrahedra (m³, in double).</summary>
        public static double TotalVolume(TetrahedralMesh mesh)
        {
            double sum = 0.0;
            foreach (int4 t in mesh.Tetrahedra)
                sum += SignedVolume(mesh.Positions[t.x], mesh.Positions[t.y], mesh.Positions[t.z], mesh.Positions[t.w]);
            return sum;
        }

        /// <summary>(b − a)·((c − a) × (d − a)) / 6 in double (m³).</summary>
        public static double SignedVolume(float3 a, float3 b, float3 c, float3 d)
        {
            double bx = b.x - (double)a.x, by = b.y - (double)a.y, bz = b.z - (double)a.z;
            double cx = c.x - (double)a.x, cy = c.y - (double)a.y, cz = c.z - (double)a.z;
            double dx = d.x - (double)a.x, dy = d.y - (double)a.y, dz = d.z - (double)a.z;
            return (bx * (cy * dz - cz * dy) + by * (cz * dx - cx * dz) + bz * (cx * dy - cy * dx)) / 6.0;
        }

        /// <summary>
        /// Appends errors for an empty mesh, non-finite nodes, out-of-range indices, zero-volume and inverted
        /// tetrahedra (each naming the first, with a count), and warnings for slivers (naming the worst) and unused
        /// nodes. Returns true when there was no error.
        /// </summary>
        public static bool Check(TetrahedralMesh mesh, List<ValidationIssue> issues)
        {
            int nodes = mesh?.Positions?.Length ?? 0, tets = mesh?.Tetrahedra?.Length ?? 0;
            if (nodes == 0 || tets == 0)
            {
                issues.Add(ValidationIssue.Error(TetrahedralMeshIssueCode.EmptyTetrahedralMesh, -1, Invariant(
                    $"The tetrahedral mesh has {nodes} nodes and {tets} tetrahedra; it needs at least 4 nodes and 1 tetrahedron.")));
                return false;
            }
            int before = issues.Count;
            var finite = new bool[nodes];
            int firstNonFinite = -1, nonFinite = 0;
            for (int n = 0; n < nodes; n++)
            {
                finite[n] = math.all(math.isfinite(mesh.Positions[n]));
                if (finite[n])
                    continue;
                nonFinite++;
                if (firstNonFinite < 0)
                    firstNonFinite = n;
            }
            if (nonFinite > 0)
                issues.Add(ValidationIssue.Error(TetrahedralMeshIssueCode.NonFiniteNode, firstNonFinite, Invariant(
                    $"Node {firstNonFinite} has a non-finite position (NaN or infinity); {nonFinite} nodes in all. Fix the volume mesh.")));

            var used = new bool[nodes];
            int firstOut = -1, outCount = 0, firstFlat = -1, flatCount = 0, firstInverted = -1, invertedCount = 0, worst = -1, slivers = 0;
            double worstQuality = double.PositiveInfinity, invertedVolume = 0.0;
            for (int t = 0; t < tets; t++)
            {
                int4 q = mesh.Tetrahedra[t];
                if ((uint)q.x >= (uint)nodes || (uint)q.y >= (uint)nodes || (uint)q.z >= (uint)nodes || (uint)q.w >= (uint)nodes)
                {
                    outCount++;
                    if (firstOut < 0)
                        firstOut = t;
                    continue;
                }
                used[q.x] = used[q.y] = used[q.z] = used[q.w] = true;
                if (!finite[q.x] || !finite[q.y] || !finite[q.z] || !finite[q.w])
                    continue;
                float3 a = mesh.Positions[q.x], b = mesh.Positions[q.y], c = mesh.Positions[q.z], d = mesh.Positions[q.w];
                double quality = Quality(a, b, c, d);
                bool repeated = q.x == q.y || q.x == q.z || q.x == q.w || q.y == q.z || q.y == q.w || q.z == q.w;
                if (repeated || Math.Abs(quality) <= DegenerateQuality)
                {
                    flatCount++;
                    if (firstFlat < 0)
                        firstFlat = t;
                }
                else if (quality < 0.0)
                {
                    invertedCount++;
                    if (firstInverted < 0)
                    {
                        firstInverted = t;
                        invertedVolume = SignedVolume(a, b, c, d);
                    }
                }
                else if (quality < SliverQuality)
                {
                    slivers++;
                    if (quality < worstQuality)
                    {
                        worstQuality = quality;
                        worst = t;
                    }
                }
            }
            if (outCount > 0)
            {
                int4 q = mesh.Tetrahedra[firstOut];
                issues.Add(ValidationIssue.Error(TetrahedralMeshIssueCode.TetrahedronIndexOutOfRange, firstOut, Invariant(
                    $"Tetrahedron {firstOut} has nodes ({q.x}, {q.y}, {q.z}, {q.w}), but the mesh has {nodes} nodes (valid indices 0 to {nodes - 1}); {outCount} tetrahedra in all. The volume mesh is corrupt; rebuild it.")));
            }
            if (flatCount > 0)
                issues.Add(ValidationIssue.Error(TetrahedralMeshIssueCode.TetrahedronDegenerate, firstFlat, Invariant(
                    $"Tetrahedron {firstFlat} has zero volume (a repeated node, or its nodes lie in a plane to float precision: quality at most {DegenerateQuality}); {flatCount} tetrahedra in all. Remove them from the volume mesh.")));
            if (invertedCount > 0)
                issues.Add(ValidationIssue.Error(TetrahedralMeshIssueCode.TetrahedronInverted, firstInverted, Invariant(
                    $"Tetrahedron {firstInverted} has negative volume {invertedVolume:G4} m³: its nodes (a, b, c, d) are not ordered so that (b − a)·((c − a) × (d − a)) > 0; {invertedCount} tetrahedra in all. Swap two nodes of each, or export the mesh with consistent orientation.")));
            if (slivers > 0)
                issues.Add(ValidationIssue.Warning(TetrahedralMeshIssueCode.TetrahedronSliver, worst, Invariant(
                    $"{slivers} of {tets} tetrahedra are badly shaped (quality 6√2·V/ℓ³_rms below {SliverQuality}; 1 is regular); the worst is tetrahedron {worst} at {worstQuality:G3}. They make the body stiff along their thin direction and need smaller steps; remesh with better-shaped elements.")));
            if (outCount == 0)
            {
                int firstUnused = -1, unused = 0;
                for (int n = 0; n < nodes; n++)
                {
                    if (used[n])
                        continue;
                    unused++;
                    if (firstUnused < 0)
                        firstUnused = n;
                }
                if (unused > 0)
                    issues.Add(ValidationIssue.Warning(TetrahedralMeshIssueCode.UnusedNodes, firstUnused, Invariant(
                        $"{unused} of {nodes} nodes belong to no tetrahedron (the first is node {firstUnused}): they get no mass and no forces. Remove them from the volume mesh.")));
            }
            return !ValidationIssue.AnyError(issues, before);
        }
    }
}
