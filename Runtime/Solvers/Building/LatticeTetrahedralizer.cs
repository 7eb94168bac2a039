using System;
using System.Collections.Generic;
using Unity.Mathematics;
using static System.FormattableString;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Fills a closed triangle mesh with tetrahedra on a cubic lattice, without external tools, and embeds its render
    /// vertices for mesh write-back. Steps:
    /// <list type="number">
    /// <item>Checks the settings and the mesh (<see cref="MeshChecks"/>), welds seams (<see cref="MeshWelding"/>) and
    /// requires a closed, consistently wound surface (<see cref="MeshTopology"/>): only a closed mesh has a volume.</item>
    /// <item>Lays cubic cells of side h = longest extent / Resolution over the bounds: Resolution cells on the longest
    /// axis, ⌈extent / h⌉ on the others, centred on the bounds.</item>
    /// <item>Keeps a cell when (a) the surface passes through its interior (a triangle overlaps the open cube with
    /// positive depth, by <see cref="TriangleBoxSeparation"/>), or (b) a render vertex lies in it (a vertex on a cell
    /// face counts for the cell above it on that axis, clamped to the lattice), or (c) its centre is inside the surface
    /// (generalised winding number |w| &gt; 1/2). Rule (a) puts the whole surface inside the volume mesh, (b) every
    /// render vertex. The winding number is evaluated only at the first cell after cells the surface comes near
    /// (within 1e-4·h) on each x-row, and carried over elsewhere (from w = 0 before the row), since w cannot change
    /// between neighbouring cells the surface does not touch.</item>
    /// <item>Splits each kept cell into 6 tetrahedra by <see cref="KuhnSplit"/> (the same diagonal everywhere, so the
    /// mesh conforms), numbering nodes in order of first use (cells z-major, then y, then x) so that only used nodes
    /// exist. Node (i, j, k) sits at origin + (i, j, k)·h, computed in double and rounded once, so shared nodes are
    /// identical.</item>
    /// <item>Checks the result (<see cref="TetrahedralMeshChecks"/>) and embeds each render vertex
    /// (<see cref="TetrahedralEmbedding"/>).</item>
    /// </list>
    /// Deterministic: the same input gives the same bits. Managed allocations; a bake-time tool.
    /// </summary>
    public static class LatticeTetrahedralizer
    {
        /// <summary>Cells within this fraction of h of the surface count as near it (the winding number is re-evaluated after them).</summary>
        public const double NearSurfaceFraction = 1e-4;

        const byte k_Cut = 1, k_Near = 2, k_Vertex = 4;

        /// <summary>
        /// Builds the volume mesh and the embedding. Every problem found is in <see cref="TetrahedralizationResult.Issues"/>;
        /// on any error <see cref="TetrahedralizationResult.Mesh"/> is null and <see cref="TetrahedralizationResult.Succeeded"/> false.
        /// </summary>
        /// <param name="vertices">Render-vertex positions in the body's local space (m).</param>
        /// <param name="triangles">Vertex indices, three per triangle; the welded surface must be closed.</param>
        /// <param name="settings">Build settings (<see cref="TetrahedralizationSettings.Default"/> for a start).</param>
        public static TetrahedralizationResult Build(ReadOnlySpan<float3> vertices, ReadOnlySpan<int> triangles, in TetrahedralizationSettings settings)
        {
            var result = new TetrahedralizationResult();
            List<ValidationIssue> issues = result.Issues;
            bool settingsValid = TetrahedralizationSettings.Validate(settings, issues);
            bool meshValid = MeshChecks.CheckInput(vertices, triangles, issues);
            if (!settingsValid || !meshValid)
                return result;

            AxisAlignedBox bounds = AxisAlignedBox.Of(vertices);
            if (!MeshWelding.TryWeld(vertices, bounds, settings.WeldTolerance, settings.WeldDistance, issues, out WeldedVertices welded))
                return result;
            if (welded.ParticleCount == 1)
            {
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.ZeroSize, -1, Invariant(
                    $"All {vertices.Length} vertices were welded into one point: the weld distance {welded.Tolerance} m is not small against the mesh diagonal {bounds.Diagonal} m. Lower WeldTolerance or WeldDistance.")));
                return result;
            }
            int[] surface = MeshWelding.RemapTriangles(triangles, welded.VertexToParticle);
            MeshTopology topology = MeshTopology.Analyse(welded.Positions, surface);
            if (!CheckClosed(topology, issues))
                return result;
            result.SurfaceVolume = Math.Abs(EnclosedVolume(welded.Positions, surface));

            var lattice = new Lattice(bounds, settings.Resolution);
            result.CellSize = (float)lattice.H;
            byte[] flags = MarkCells(lattice, welded.Positions, surface, vertices);
            ClassifyInterior(lattice, welded.Positions, surface, flags);

            TetrahedralMesh mesh = Split(lattice, flags, settings.MaxNodes, out int cellCount, out int nodeCount);
            if (mesh == null)
            {
                float3 size = bounds.Extent;
                issues.Add(ValidationIssue.Error(TetrahedralMeshIssueCode.TooManyNodes, -1, Invariant(
                    $"At Resolution {settings.Resolution} the {size.x} × {size.y} × {size.z} m mesh fills {cellCount} cells with {nodeCount} nodes; the limit is {settings.MaxNodes}. Lower Resolution or raise MaxNodes.")));
                return result;
            }
            result.CellCount = cellCount;
            if (!TetrahedralMeshChecks.Check(mesh, issues))
                return result;
            result.TetrahedralVolume = TetrahedralMeshChecks.TotalVolume(mesh);
            result.Embedding = TetrahedralEmbedding.Embed(mesh, vertices);
            result.Mesh = mesh;
            return result;
        }

        /// <summary>Errors for a surface that is not closed or not consistently wound; a warning for degenerate triangles.</summary>
        static bool CheckClosed(in MeshTopology topology, List<ValidationIssue> issues)
        {
            if (topology.DegenerateTriangleCount > 0)
                issues.Add(ValidationIssue.Warning(MeshBuildIssueCode.DegenerateTriangles, topology.FirstDegenerateTriangle, Invariant(
                    $"{topology.DegenerateTriangleCount} of {topology.TriangleCount} triangles are degenerate (zero area, or two corners welded into one point); the first is triangle {topology.FirstDegenerateTriangle}. They are ignored; remove them in the modelling tool to silence this.")));
            if (!topology.IsClosed)
            {
                string why = topology.OpeningDescription(out int index);
                issues.Add(ValidationIssue.Error(TetrahedralMeshIssueCode.VolumeMeshNotClosed, index, Invariant(
                    $"The mesh is not closed: {why}, so it encloses no volume to fill with tetrahedra. Close the holes in the mesh, or raise WeldTolerance if its seams are split.")));
                return false;
            }
            if (!topology.IsConsistentlyWound)
            {
                issues.Add(ValidationIssue.Error(TetrahedralMeshIssueCode.VolumeMeshInconsistentWinding, topology.FirstInconsistentTriangle, Invariant(
                    $"{topology.InconsistentEdgeCount} edges are traversed in the same direction by both of their triangles (the first by triangle {topology.FirstInconsistentTriangle}): some triangles face the wrong way, so the inside of the volume is undefined. Unify the normals in the modelling tool.")));
                return false;
            }
            return true;
        }

        /// <summary>Σ a·(b × c) / 6 over the triangles (divergence theorem, in double; positive when they face outwards).</summary>
        static double EnclosedVolume(float3[] positions, int[] triangles)
        {
            double sum = 0.0;
            for (int t = 0; t + 2 < triangles.Length; t += 3)
            {
                float3 a = positions[triangles[t]], b = positions[triangles[t + 1]], c = positions[triangles[t + 2]];
                sum += a.x * ((double)b.y * c.z - (double)b.z * c.y) + a.y * ((double)b.z * c.x - (double)b.x * c.z)
                       + a.z * ((double)b.x * c.y - (double)b.y * c.x);
            }
            return sum / 6.0;
        }

        /// <summary>Flags each cell: cut by a triangle (overlap with positive depth), near one, or holding a render vertex.</summary>
        static byte[] MarkCells(in Lattice lattice, float3[] positions, int[] triangles, ReadOnlySpan<float3> vertices)
        {
            var flags = new byte[lattice.CellCount];
            double near = NearSurfaceFraction * lattice.H;
            var half = new Double3(0.5 * lattice.H, 0.5 * lattice.H, 0.5 * lattice.H);
            for (int t = 0; t + 2 < triangles.Length; t += 3)
            {
                int ia = triangles[t], ib = triangles[t + 1], ic = triangles[t + 2];
                if (MeshTopology.RepeatsParticle(ia, ib, ic))
                    continue;
                float3 a = positions[ia], b = positions[ib], c = positions[ic];
                float3 min = math.min(a, math.min(b, c)), max = math.max(a, math.max(b, c));
                lattice.CellRange(min, -near, out int i0, out int j0, out int k0);
                lattice.CellRange(max, near, out int i1, out int j1, out int k1);
                var da = new Double3(a.x, a.y, a.z);
                var db = new Double3(b.x, b.y, b.z);
                var dc = new Double3(c.x, c.y, c.z);
                for (int k = k0; k <= k1; k++)
                for (int j = j0; j <= j1; j++)
                for (int i = i0; i <= i1; i++)
                {
                    int cell = lattice.Index(i, j, k);
                    if ((flags[cell] & k_Cut) != 0)
                        continue;
                    double gap = TriangleBoxSeparation.Separation(da, db, dc, lattice.Centre(i, j, k), half);
                    if (gap < 0.0)
                        flags[cell] |= k_Cut | k_Near;
                    else if (gap <= near)
                        flags[cell] |= k_Near;
                }
            }
            for (int v = 0; v < vertices.Length; v++)
            {
                lattice.CellRange(vertices[v], 0.0, out int i, out int j, out int k);
                flags[lattice.Index(i, j, k)] |= k_Vertex;
            }
            return flags;
        }

        /// <summary>Marks as kept (bit 8) every cut, vertex or inside cell; inside is tested at the first far cell after near cells.</summary>
        static void ClassifyInterior(in Lattice lattice, float3[] positions, int[] triangles, byte[] flags)
        {
            var winding = new WindingNumber(positions, triangles);
            double onSurface = NearSurfaceFraction * lattice.H;
            for (int k = 0; k < lattice.Nz; k++)
            for (int j = 0; j < lattice.Ny; j++)
            {
                bool inside = false, stale = false;
                for (int i = 0; i < lattice.Nx; i++)
                {
                    int cell = lattice.Index(i, j, k);
                    byte f = flags[cell];
                    bool keep = (f & (k_Cut | k_Vertex)) != 0;
                    if ((f & k_Near) != 0)
                    {
                        stale = true;
                        if (!keep)
                            keep = IsInside(winding, lattice.Centre(i, j, k), onSurface);
                    }
                    else
                    {
                        if (stale)
                        {
                            inside = IsInside(winding, lattice.Centre(i, j, k), onSurface);
                            stale = false;
                        }
                        keep |= inside;
                    }
                    if (keep)
                        flags[cell] |= k_Kept;
                }
            }
        }

        const byte k_Kept = 8;

        static bool IsInside(WindingNumber winding, Double3 p, double onSurface)
        {
            // A centre on the surface would make the cell cut; should round-off put it there, keep the cell.
            if (!winding.TryEvaluate(new float3((float)p.x, (float)p.y, (float)p.z), onSurface, out double w))
                return true;
            return Math.Abs(w) > 0.5;
        }

        /// <summary>6 tetrahedra per kept cell, nodes numbered in order of first use; null when there would be more than <paramref name="maxNodes"/>.</summary>
        static TetrahedralMesh Split(in Lattice lattice, byte[] flags, int maxNodes, out int cellCount, out int nodeCount)
        {
            int px = lattice.Nx + 1, py = lattice.Ny + 1;
            var node = new int[px * py * (lattice.Nz + 1)];
            for (int n = 0; n < node.Length; n++)
                node[n] = -1;
            var corner = new int[8];
            cellCount = 0;
            nodeCount = 0;
            for (int pass = 0; pass < 2; pass++)
            {
                float3[] positions = pass == 1 ? new float3[nodeCount] : null;
                int4[] tetrahedra = pass == 1 ? new int4[KuhnSplit.TetrahedraPerBox * cellCount] : null;
                int t = 0;
                for (int k = 0; k < lattice.Nz; k++)
                for (int j = 0; j < lattice.Ny; j++)
                for (int i = 0; i < lattice.Nx; i++)
                {
                    if ((flags[lattice.Index(i, j, k)] & k_Kept) == 0)
                        continue;
                    if (pass == 0)
                        cellCount++;
                    for (int c = 0; c < 8; c++)
                        corner[c] = (i + (c & 1)) + px * ((j + ((c >> 1) & 1)) + py * (k + ((c >> 2) & 1)));
                    for (int s = 0; s < 4 * KuhnSplit.TetrahedraPerBox; s++)
                    {
                        int c = KuhnSplit.Corners[s];
                        int lp = corner[c];
                        if (pass == 0)
                        {
                            if (node[lp] < 0)
                                node[lp] = nodeCount++;
                        }
                        else
                        {
                            positions[node[lp]] = lattice.Node(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
                        }
                    }
                    if (pass == 1)
                        for (int s = 0; s < KuhnSplit.TetrahedraPerBox; s++)
                            tetrahedra[t++] = new int4(node[corner[KuhnSplit.Corners[4 * s]]], node[corner[KuhnSplit.Corners[4 * s + 1]]],
                                node[corner[KuhnSplit.Corners[4 * s + 2]]], node[corner[KuhnSplit.Corners[4 * s + 3]]]);
                }
                if (pass == 0 && nodeCount > maxNodes)
                    return null;
                if (pass == 1)
                    return new TetrahedralMesh(positions, tetrahedra);
            }
            return null;
        }

        /// <summary>Cubic cells of side H over a box: Nx × Ny × Nz, cell (i, j, k) spans origin + [i, i + 1]·H on x, and so on.</summary>
        readonly struct Lattice
        {
            public readonly int Nx, Ny, Nz;
            public readonly double H;
            readonly double m_X, m_Y, m_Z;

            public Lattice(in AxisAlignedBox bounds, int resolution)
            {
                double ex = (double)bounds.Max.x - bounds.Min.x, ey = (double)bounds.Max.y - bounds.Min.y, ez = (double)bounds.Max.z - bounds.Min.z;
                double longest = Math.Max(ex, Math.Max(ey, ez));
                H = longest / resolution;
                // The longest axis gets exactly `resolution` cells; the 1e-6 keeps round-off from adding a cell elsewhere.
                Nx = Cells(ex, H, resolution);
                Ny = Cells(ey, H, resolution);
                Nz = Cells(ez, H, resolution);
                m_X = 0.5 * ((double)bounds.Min.x + bounds.Max.x) - 0.5 * Nx * H;
                m_Y = 0.5 * ((double)bounds.Min.y + bounds.Max.y) - 0.5 * Ny * H;
                m_Z = 0.5 * ((double)bounds.Min.z + bounds.Max.z) - 0.5 * Nz * H;
            }

            static int Cells(double extent, double h, int resolution) =>
                Math.Min(resolution, Math.Max(1, (int)Math.Ceiling(extent / h * (1.0 - 1e-6))));

            public int CellCount => Nx * Ny * Nz;

            public int Index(int i, int j, int k) => i + Nx * (j + Ny * k);

            public Double3 Centre(int i, int j, int k) => new Double3(m_X + (i + 0.5) * H, m_Y + (j + 0.5) * H, m_Z + (k + 0.5) * H);

            public float3 Node(int i, int j, int k) => new float3((float)(m_X + i * H), (float)(m_Y + j * H), (float)(m_Z + k * H));

            /// <summary>The cell holding p + offset on every axis, clamped to the lattice.</summary>
            public void CellRange(float3 p, double offset, out int i, out int j, out int k)
            {
                i = Cell(p.x + offset, m_X, Nx);
                j = Cell(p.y + offset, m_Y, Ny);
                k = Cell(p.z + offset, m_Z, Nz);
            }

            int Cell(double x, double origin, int n) => (int)Math.Min(Math.Max(Math.Floor((x - origin) / H), 0.0), n - 1);
        }
    }
}
