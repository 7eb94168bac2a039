using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Edge statistics of a welded triangle mesh: degenerate triangles, boundary, non-manifold and
    /// inconsistently wound edges, and whether the surface is closed. "First" fields hold the lowest
    /// triangle index concerned, or −1.
    /// </summary>
    public struct MeshTopology
    {
        /// <summary>
        /// A triangle with distinct particles counts as zero-area when twice its area is at most this
        /// fraction of its longest edge squared: |e₁ × e₂| ≤ 1e-6·ℓ²ₘₐₓ. The vertices carry float32
        /// round-off (relative ε ≈ 1.2e-7 per coordinate), so a flatter triangle cannot be told from a line.
        /// </summary>
        public const double ZeroAreaFraction = 1e-6;

        /// <summary>Triangles in the mesh.</summary>
        public int TriangleCount;
        /// <summary>Distinct edges of the triangles that do not repeat a particle.</summary>
        public int EdgeCount;
        /// <summary>Triangles with a repeated particle or zero area.</summary>
        public int DegenerateTriangleCount;
        /// <summary>Lowest-numbered degenerate triangle, or −1.</summary>
        public int FirstDegenerateTriangle;
        /// <summary>Edges used by exactly one triangle.</summary>
        public int BoundaryEdgeCount;
        /// <summary>Lowest-numbered triangle on a boundary edge, or −1.</summary>
        public int FirstBoundaryTriangle;
        /// <summary>Edges used by more than two triangles.</summary>
        public int NonManifoldEdgeCount;
        /// <summary>Lowest-numbered triangle on a non-manifold edge, or −1.</summary>
        public int FirstNonManifoldTriangle;
        /// <summary>Edges used by two triangles that traverse it in the same direction.</summary>
        public int InconsistentEdgeCount;
        /// <summary>Lowest-numbered triangle on an inconsistently wound edge, or −1.</summary>
        public int FirstInconsistentTriangle;

        /// <summary>Every edge is used by exactly two triangles (triangles with a repeated particle are left out).</summary>
        public bool IsClosed => EdgeCount > 0 && BoundaryEdgeCount == 0 && NonManifoldEdgeCount == 0;
        /// <summary>Every edge used by two triangles is traversed once in each direction.</summary>
        public bool IsConsistentlyWound => InconsistentEdgeCount == 0;

        /// <summary>
        /// Why the surface is not closed, for an issue message ("12 edges belong to only one triangle (the first to
        /// triangle 4)"), and the triangle the issue should name. Only meaningful when <see cref="IsClosed"/> is false.
        /// </summary>
        public string OpeningDescription(out int triangle)
        {
            triangle = BoundaryEdgeCount > 0 ? FirstBoundaryTriangle : FirstNonManifoldTriangle;
            return BoundaryEdgeCount > 0
                ? System.FormattableString.Invariant($"{BoundaryEdgeCount} edges belong to only one triangle (the first to triangle {FirstBoundaryTriangle})")
                : NonManifoldEdgeCount > 0
                    ? System.FormattableString.Invariant($"{NonManifoldEdgeCount} edges are shared by more than two triangles (the first by triangle {FirstNonManifoldTriangle})")
                    : "no triangle has three distinct corners";
        }

        /// <summary>True when a triangle repeats a particle: it has no edges and is skipped by topology and inside tests.</summary>
        public static bool RepeatsParticle(int a, int b, int c) => a == b || b == c || c == a;

        /// <summary>True when the triangle (p0, p1, p2) has zero area to float32 precision (see <see cref="ZeroAreaFraction"/>).</summary>
        public static bool HasZeroArea(float3 p0, float3 p1, float3 p2)
        {
            double e1x = (double)p1.x - p0.x, e1y = (double)p1.y - p0.y, e1z = (double)p1.z - p0.z;
            double e2x = (double)p2.x - p0.x, e2y = (double)p2.y - p0.y, e2z = (double)p2.z - p0.z;
            double cx = e1y * e2z - e1z * e2y, cy = e1z * e2x - e1x * e2z, cz = e1x * e2y - e1y * e2x;
            double e3x = e2x - e1x, e3y = e2y - e1y, e3z = e2z - e1z;
            double longest = Math.Max(e1x * e1x + e1y * e1y + e1z * e1z,
                Math.Max(e2x * e2x + e2y * e2y + e2z * e2z, e3x * e3x + e3y * e3y + e3z * e3z));
            return Math.Sqrt(cx * cx + cy * cy + cz * cz) <= ZeroAreaFraction * longest;
        }

        /// <summary>
        /// Counts degenerate triangles and classifies every undirected edge by how many triangles use it
        /// and in which directions. Sorting edge keys makes the result independent of any hash order.
        /// </summary>
        /// <param name="particles">Welded positions (m).</param>
        /// <param name="triangles">Particle indices (in range), three per triangle.</param>
        public static MeshTopology Analyse(ReadOnlySpan<float3> particles, ReadOnlySpan<int> triangles)
        {
            int triangleCount = triangles.Length / 3;
            var topology = new MeshTopology
            {
                TriangleCount = triangleCount,
                FirstDegenerateTriangle = -1,
                FirstBoundaryTriangle = -1,
                FirstNonManifoldTriangle = -1,
                FirstInconsistentTriangle = -1,
            };

            var keys = new long[3 * triangleCount];
            var uses = new int[3 * triangleCount];
            int edges = 0;
            long n = particles.Length;
            for (int t = 0; t < triangleCount; t++)
            {
                int a = triangles[3 * t], b = triangles[3 * t + 1], c = triangles[3 * t + 2];
                bool repeats = RepeatsParticle(a, b, c);
                if (repeats || HasZeroArea(particles[a], particles[b], particles[c]))
                {
                    topology.DegenerateTriangleCount++;
                    if (topology.FirstDegenerateTriangle < 0)
                        topology.FirstDegenerateTriangle = t;
                }
                if (repeats)
                    continue;
                AddEdge(a, b, t, n, keys, uses, ref edges);
                AddEdge(b, c, t, n, keys, uses, ref edges);
                AddEdge(c, a, t, n, keys, uses, ref edges);
            }

            Array.Sort(keys, uses, 0, edges);
            for (int start = 0; start < edges;)
            {
                int end = start, forward = 0, firstTriangle = int.MaxValue;
                while (end < edges && keys[end] == keys[start])
                {
                    forward += uses[end] & 1;
                    firstTriangle = Math.Min(firstTriangle, uses[end] >> 1);
                    end++;
                }
                int count = end - start;
                topology.EdgeCount++;
                if (count == 1)
                    Note(ref topology.BoundaryEdgeCount, ref topology.FirstBoundaryTriangle, firstTriangle);
                else if (count > 2)
                    Note(ref topology.NonManifoldEdgeCount, ref topology.FirstNonManifoldTriangle, firstTriangle);
                else if (forward != 1)
                    Note(ref topology.InconsistentEdgeCount, ref topology.FirstInconsistentTriangle, firstTriangle);
                start = end;
            }
            return topology;
        }

        /// <summary>Key: lower particle × n + higher particle. Use: triangle × 2 + (1 when traversed low → high).</summary>
        static void AddEdge(int from, int to, int triangle, long n, long[] keys, int[] uses, ref int edges)
        {
            bool forward = from < to;
            keys[edges] = forward ? from * n + to : to * n + from;
            uses[edges] = (triangle << 1) | (forward ? 1 : 0);
            edges++;
        }

        static void Note(ref int count, ref int first, int triangle)
        {
            count++;
            if (first < 0 || triangle < first)
                first = triangle;
        }
    }
}
