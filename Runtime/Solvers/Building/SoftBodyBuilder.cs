using System;
using System.Collections.Generic;
using Unity.Mathematics;
using static System.FormattableString;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Turns a render mesh into a shape-matching soft body at bake time: checks the input, welds the
    /// render vertices into surface particles, optionally fills a closed surface with interior
    /// particles, builds overlapping clusters, spreads the mass uniformly and precomputes the model.
    /// Particles 0 .. surface − 1 are the welded vertices (in order of first use), interior particles
    /// follow. Deterministic: the same input gives the same bits. Managed allocations; not a hot path.
    /// </summary>
    public static class SoftBodyBuilder
    {
        /// <summary>
        /// Builds the body. Every problem found is in <see cref="SoftBodyBuildResult.Issues"/>; on any error
        /// <see cref="SoftBodyBuildResult.Model"/> is null and <see cref="SoftBodyBuildResult.Succeeded"/> false.
        /// </summary>
        /// <param name="vertices">Render-vertex positions in the body's local space (m).</param>
        /// <param name="triangles">Vertex indices, three per triangle.</param>
        /// <param name="settings">Build settings (<see cref="SoftBodyBuildSettings.Default"/> for a start).</param>
        public static SoftBodyBuildResult Build(ReadOnlySpan<float3> vertices, ReadOnlySpan<int> triangles, in SoftBodyBuildSettings settings)
        {
            var result = new SoftBodyBuildResult();
            List<ValidationIssue> issues = result.Issues;
            bool settingsValid = SoftBodyBuildSettingsValidation.Validate(settings, issues);
            bool meshValid = MeshChecks.CheckInput(vertices, triangles, issues);
            if (!settingsValid || !meshValid)
                return result;

            AxisAlignedBox bounds = AxisAlignedBox.Of(vertices);
            if (!MeshWelding.TryWeld(vertices, bounds, settings.WeldTolerance, settings.WeldDistance, issues, out WeldedVertices welded))
                return result;
            result.VertexToParticle = welded.VertexToParticle;
            result.ParticleTriangles = MeshWelding.RemapTriangles(triangles, welded.VertexToParticle);
            result.SurfaceParticleCount = welded.ParticleCount;
            if (!CheckWelded(welded, vertices.Length, bounds, settings, issues))
                return result;

            MeshTopology topology = MeshTopology.Analyse(welded.Positions, result.ParticleTriangles);
            result.IsClosed = topology.IsClosed;
            ReportTopology(topology, issues);

            var interior = new List<float3>();
            if (settings.AddInteriorParticles && CanFill(topology, issues)
                && !AddInterior(welded, result.ParticleTriangles, settings, interior, issues))
                return result;
            result.InteriorParticleCount = interior.Count;

            var positions = new float3[welded.ParticleCount + interior.Count];
            Array.Copy(welded.Positions, positions, welded.ParticleCount);
            interior.CopyTo(positions, welded.ParticleCount);

            ClusterSet clusters = BuildClusters(positions, settings.ClusterSize, issues);
            if (clusters == null)
                return result;
            result.ClusterCount = clusters.Count;
            result.MeanClusterSize = clusters.MeanSize;

            var masses = new float[positions.Length];
            float mass = settings.TotalMass / positions.Length;
            for (int i = 0; i < masses.Length; i++)
                masses[i] = mass;
            if (!ValidationIssue.AnyError(issues))
                result.Model = ShapeMatchingModelData.Create(positions, masses, clusters.Offsets, clusters.Particles, settings.BuildQuadratic);
            return result;
        }

        static bool CheckWelded(WeldedVertices welded, int vertexCount, in AxisAlignedBox bounds, in SoftBodyBuildSettings settings,
            List<ValidationIssue> issues)
        {
            if (welded.ParticleCount == 1)
            {
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.ZeroSize, -1, Invariant(
                    $"All {vertexCount} vertices were welded into one particle: the weld distance {welded.Tolerance} m is not small against the mesh diagonal {bounds.Diagonal} m. Lower WeldTolerance or WeldDistance.")));
                return false;
            }
            if (welded.ParticleCount > settings.MaxParticles)
            {
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.TooManyParticles, -1, Invariant(
                    $"The mesh's {vertexCount} vertices weld to {welded.ParticleCount} particles; the limit is {settings.MaxParticles}. Use a simpler mesh or raise MaxParticles.")));
                return false;
            }
            return true;
        }

        static void ReportTopology(in MeshTopology topology, List<ValidationIssue> issues)
        {
            if (topology.DegenerateTriangleCount > 0)
                issues.Add(ValidationIssue.Warning(MeshBuildIssueCode.DegenerateTriangles, topology.FirstDegenerateTriangle, Invariant(
                    $"{topology.DegenerateTriangleCount} of {topology.TriangleCount} triangles are degenerate (zero area, or two corners welded into one particle); the first is triangle {topology.FirstDegenerateTriangle}. They add nothing to the body; remove them in the modelling tool to silence this.")));
            if (topology.NonManifoldEdgeCount > 0)
                issues.Add(ValidationIssue.Warning(MeshBuildIssueCode.NonManifoldEdges, topology.FirstNonManifoldTriangle, Invariant(
                    $"{topology.NonManifoldEdgeCount} edges are shared by more than two triangles (non-manifold); the first is used by triangle {topology.FirstNonManifoldTriangle}. The surface has no well-defined inside there; separate the overlapping parts of the mesh.")));
        }

        /// <summary>True when the surface encloses a volume; otherwise warns that interior particles are skipped.</summary>
        static bool CanFill(in MeshTopology topology, List<ValidationIssue> issues)
        {
            if (!topology.IsClosed)
            {
                string why = topology.OpeningDescription(out int index);
                issues.Add(ValidationIssue.Warning(MeshBuildIssueCode.NotClosed, index, Invariant(
                    $"The mesh is not closed: {why}, so it has no inside. Interior particles were skipped; close the holes in the mesh, or raise WeldTolerance if its seams are split.")));
                return false;
            }
            if (!topology.IsConsistentlyWound)
            {
                issues.Add(ValidationIssue.Warning(MeshBuildIssueCode.InconsistentWinding, topology.FirstInconsistentTriangle, Invariant(
                    $"{topology.InconsistentEdgeCount} edges are traversed in the same direction by both of their triangles (the first by triangle {topology.FirstInconsistentTriangle}): some triangles face the wrong way, so inside and outside cannot be told apart. Interior particles were skipped; unify the normals in the modelling tool.")));
                return false;
            }
            return true;
        }

        /// <summary>Samples the interior into <paramref name="interior"/>; false (with an error) when the spacing or the particle limit does not allow it.</summary>
        static bool AddInterior(WeldedVertices welded, int[] particleTriangles, in SoftBodyBuildSettings settings, List<float3> interior,
            List<ValidationIssue> issues)
        {
            AxisAlignedBox bounds = AxisAlignedBox.Of(welded.Positions);
            float spacing = settings.InteriorSpacing > 0f ? settings.InteriorSpacing : InteriorSampling.AutoSpacing(bounds);
            double lattice = CubicLattice.PointCount(bounds, spacing);
            if (lattice > InteriorSampling.MaxLatticePoints)
            {
                float3 size = bounds.Extent;
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.InteriorSpacingInvalid, -1, Invariant(
                    $"InteriorSpacing {spacing} m is too small for a mesh of {size.x} × {size.y} × {size.z} m: its lattice would have {lattice:0} points (at most {InteriorSampling.MaxLatticePoints:0} are tested). Increase InteriorSpacing.")));
                return false;
            }
            int budget = settings.MaxParticles - welded.ParticleCount;
            int found = InteriorSampling.Sample(welded.Positions, particleTriangles, spacing, budget, interior);
            if (found > budget)
            {
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.TooManyParticles, -1, Invariant(
                    $"With interior particles every {spacing} m the body would have at least {welded.ParticleCount + found} particles ({welded.ParticleCount} on the surface, {found} or more inside); the limit is {settings.MaxParticles}. Increase InteriorSpacing or raise MaxParticles.")));
                return false;
            }
            return true;
        }

        static ClusterSet BuildClusters(float3[] positions, float clusterSize, List<ValidationIssue> issues)
        {
            AxisAlignedBox bounds = AxisAlignedBox.Of(positions);
            if (ClusterBuilder.IsTooFine(bounds, clusterSize))
            {
                issues.Add(ValidationIssue.Error(MeshBuildIssueCode.ClusterSizeInvalid, -1, Invariant(
                    $"ClusterSize {clusterSize} m is too small for a body {bounds.LongestExtent} m long: the cluster lattice would exceed {ClusterBuilder.MaxCentresPerAxis:0} centres per side. Use a size near a quarter of the body, or 0 for one cluster.")));
                return null;
            }
            ClusterSet clusters = ClusterBuilder.Build(positions, clusterSize);
            if (clusters.WeakClusterCount > 0)
                issues.Add(ValidationIssue.Warning(MeshBuildIssueCode.WeakClusters, -1, Invariant(
                    $"{clusters.WeakClusterCount} of {clusters.Count} clusters have fewer than {ClusterBuilder.MinStrongClusterSize} particles or lie in a plane, and were kept because they alone hold some particles; they can only move rigidly (a single particle is not held at all). Increase ClusterSize (now {clusterSize} m) or enable AddInteriorParticles.")));
            return clusters;
        }
    }
}
