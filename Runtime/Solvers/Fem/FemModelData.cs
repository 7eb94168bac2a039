using System;
using System.Collections.Generic;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The baked finite-element model of a tetrahedral mesh (managed arrays; built once). <see cref="Create"/> checks
    /// the mesh and material and reports every problem with a specific <see cref="IssueCode"/>;
    /// <see cref="AsModel"/> gives the spans the step reads.
    /// </summary>
    public sealed class FemModelData
    {
        /// <summary>
        /// Quality q = 6√2 V / l_rms³ (l_rms the root mean square of the six edge lengths) below which a tetrahedron is
        /// reported as a sliver. q = 1 for a regular tetrahedron, 0.66 for the six tetrahedra of a split cube, → 0 for a flat one.
        /// </summary>
        public const float SliverQuality = 0.1f;

        /// <summary>|q| at or below which a tetrahedron counts as flat (zero volume): float32 round-off of the volume is ~10⁻⁷ l³.</summary>
        public const float DegenerateQuality = 1e-5f;

        /// <summary>Rest positions (m).</summary>
        public float3[] RestPositions;
        /// <summary>Lumped masses (kg).</summary>
        public float[] Masses;
        /// <summary>Inverse masses (1/kg), 0 = pinned.</summary>
        public float[] InverseMasses;
        /// <summary>Elements.</summary>
        public TetElement[] Elements;
        /// <summary>Incidence of the element corners (4 per element).</summary>
        public ElementIncidence Incidence;
        /// <summary>Colouring of the elements.</summary>
        public GraphColoring Coloring;
        /// <summary>See <see cref="FemModel.StiffnessDiagonal"/> (N/m).</summary>
        public float[] StiffnessDiagonal;
        /// <summary>Rest centre of mass (m).</summary>
        public float3 RestCenter;
        /// <summary>Shear modulus μ (Pa).</summary>
        public float Mu;
        /// <summary>Lamé λ (Pa).</summary>
        public float Lambda;
        /// <summary>Damping ratio ζ.</summary>
        public float DampingRatio;
        /// <summary>See <see cref="FemModel.DefaultDampingFrequency"/> (rad/s).</summary>
        public float DefaultDampingFrequency;
        /// <summary>See <see cref="FemModel.ElementNodes"/> (empty for linear elements).</summary>
        public int[] ElementNodes = new int[0];
        /// <summary>See <see cref="FemModel.PointGradients"/> (1/m; empty for linear elements).</summary>
        public float3[] PointGradients = new float3[0];
        /// <summary>See <see cref="FemModel.PointVolumes"/> (m³; empty for linear elements).</summary>
        public float[] PointVolumes = new float[0];
        /// <summary>Quadratic elements: the two corner nodes of each edge node (edge node k is node <c>CornerCount + k</c>); empty for linear ones. Render vertices skin to them.</summary>
        public int2[] EdgeEnds = new int2[0];

        /// <summary>See <see cref="FemModel.FactorNodes"/> (empty until <see cref="BuildRestFactor"/>).</summary>
        public int[] FactorNodes = new int[0];
        /// <summary>See <see cref="FemModel.FactorRowStarts"/>.</summary>
        public int[] FactorRowStarts = new int[0];
        /// <summary>See <see cref="FemModel.FactorValues"/>.</summary>
        public float[] FactorValues = new float[0];
        /// <summary>The c₀ = hβ + h² (s²) the factor was built for; 0 = none.</summary>
        public float FactorC;

        /// <summary>
        /// Builds the <see cref="FemRestFactor"/> preconditioner for substeps of <paramref name="substep"/> seconds and Rayleigh
        /// coefficient <paramref name="beta"/> (s): c₀ = hβ + h². The implicit step uses it at any h (fewer iterations the
        /// closer h is). Returns false (and keeps block-Jacobi) when the rest system is not positive definite. Memory: the
        /// envelope of the free nodes' rows in reverse Cuthill–McKee order (about 3 × bandwidth floats per row).
        /// </summary>
        public bool BuildRestFactor(float substep, float beta)
        {
            float c = substep * beta + substep * substep;
            if (!(c > 0f) || !math.isfinite(c) || !FemRestFactor.Build(AsModel(), c, out int[] nodes, out int[] starts, out float[] values))
            {
                FactorNodes = new int[0];
                FactorRowStarts = new int[0];
                FactorValues = new float[0];
                FactorC = 0f;
                return false;
            }
            FactorNodes = nodes;
            FactorRowStarts = starts;
            FactorValues = values;
            FactorC = c;
            return true;
        }

        /// <summary>The element order of the model.</summary>
        public FemElementOrder Order => ElementNodes.Length > 0 ? FemElementOrder.Quadratic : FemElementOrder.Linear;

        /// <summary>The spans of the model.</summary>
        public FemModel AsModel() => new FemModel(RestPositions, Masses, InverseMasses, Elements, Incidence.Offsets, Incidence.Slots,
            Coloring.ColorOffsets, Coloring.Elements, StiffnessDiagonal, RestCenter, Mu, Lambda, DampingRatio, DefaultDampingFrequency,
            ElementNodes, PointGradients, PointVolumes, FactorNodes, FactorRowStarts, FactorValues);

        /// <summary>Quality 6√2 V / l_rms³ of a tetrahedron (dimensionless, signed like its volume): 1 = regular.</summary>
        public static float Quality(float3 a, float3 b, float3 c, float3 d)
        {
            float volume = TetrahedralMesh.SignedVolume(a, b, c, d);
            float l2 = (math.distancesq(a, b) + math.distancesq(a, c) + math.distancesq(a, d) + math.distancesq(b, c)
                        + math.distancesq(b, d) + math.distancesq(c, d)) / 6f;
            float lrms3 = l2 * math.sqrt(l2);
            return lrms3 > 0f ? 6f * math.sqrt(2f) * volume / lrms3 : 0f;
        }

        /// <summary>
        /// Bakes <paramref name="mesh"/> with <paramref name="material"/>. Lumped masses mᵢ = ρ Σ V_t / 4, inverse masses
        /// (0 where <paramref name="pinned"/> is true; empty = nothing pinned), Dm⁻¹ and volume per tetrahedron, incidence,
        /// colouring, Lamé parameters. Appends issues to <paramref name="issues"/>; returns null when any is an error.
        /// <para>
        /// <see cref="FemElementOrder.Quadratic"/>: a node at the midpoint of every edge (<see cref="QuadraticTetrahedra"/>),
        /// after the mesh's own nodes; an edge node is pinned when both its corners are. Masses are lumped by
        /// <see cref="QuadraticTet.CornerMassFraction"/> and <see cref="QuadraticTet.EdgeMassFraction"/> (all positive).
        /// </para>
        /// </summary>
        public static FemModelData Create(TetrahedralMesh mesh, in ElasticMaterial material, ReadOnlySpan<bool> pinned,
            List<ValidationIssue> issues, FemElementOrder order = FemElementOrder.Linear)
        {
            int start = issues.Count;
            if (order != FemElementOrder.Linear && order != FemElementOrder.Quadratic)
                issues.Add(ValidationIssue.Error(FemIssueCode.ElementOrderInvalid, -1,
                    $"Element order {(int)order} is not Linear or Quadratic."));
            if (!material.IsValid)
                issues.Add(ValidationIssue.Error(FemIssueCode.MaterialInvalid, -1,
                    $"The material is invalid (E = {material.YoungsModulus} Pa, ν = {material.PoissonRatio}, ρ = {material.Density} kg/m³, " +
                    $"ζ = {material.DampingRatio}): use E > 0, 0 ≤ ν < 0.5 (0.5 is incompressible, which linear tetrahedra cannot represent), ρ > 0, ζ ≥ 0."));
            if (mesh == null || mesh.Positions == null || mesh.Tetrahedra == null || mesh.NodeCount == 0 || mesh.TetrahedronCount == 0)
            {
                issues.Add(ValidationIssue.Error(FemIssueCode.MeshEmpty, -1, "The tetrahedral mesh has no nodes or no tetrahedra."));
                return null;
            }
            int n = mesh.NodeCount;
            if (pinned.Length != 0 && pinned.Length != n)
                issues.Add(ValidationIssue.Error(FemIssueCode.PinnedCountMismatch, -1,
                    $"The pinned-node list has {pinned.Length} entries but the mesh has {n} nodes."));

            var used = new bool[n];
            for (int t = 0; t < mesh.TetrahedronCount; t++)
            {
                int4 nodes = mesh.Tetrahedra[t];
                bool valid = true;
                for (int k = 0; k < 4; k++)
                {
                    valid &= (uint)nodes[k] < (uint)n;
                    for (int j = 0; j < k; j++)
                        valid &= nodes[j] != nodes[k];
                }
                if (!valid)
                {
                    issues.Add(ValidationIssue.Error(FemIssueCode.TetrahedronNodeInvalid, t,
                        $"Tetrahedron {t} has nodes {nodes}: each must be a distinct node index below {n}."));
                    continue;
                }
                for (int k = 0; k < 4; k++)
                    used[nodes[k]] = true;
                float3 a = mesh.Positions[nodes.x], b = mesh.Positions[nodes.y], c = mesh.Positions[nodes.z], d = mesh.Positions[nodes.w];
                float q = Quality(a, b, c, d);
                if (!(math.abs(q) > DegenerateQuality))
                    issues.Add(ValidationIssue.Error(FemIssueCode.TetrahedronDegenerate, t,
                        $"Tetrahedron {t} (nodes {nodes}) has zero volume at rest (quality {q}): its nodes are coplanar or not finite. Remove it or fix the tetrahedralisation."));
                else if (q < 0f)
                    issues.Add(ValidationIssue.Error(FemIssueCode.TetrahedronInverted, t,
                        $"Tetrahedron {t} (nodes {nodes}) is inverted at rest (volume {TetrahedralMesh.SignedVolume(a, b, c, d)} m³): swap two of its nodes."));
                else if (q < SliverQuality)
                    issues.Add(ValidationIssue.Warning(FemIssueCode.TetrahedronSliver, t,
                        $"Tetrahedron {t} (nodes {nodes}) is a sliver (quality 6√2·V/l_rms³ = {q:G3} < {SliverQuality}): it makes the body stiffer and the explicit stable step shorter."));
            }
            for (int i = 0; i < n; i++)
                if (!used[i])
                    issues.Add(ValidationIssue.Warning(FemIssueCode.NodeUnused, i,
                        $"Node {i} belongs to no tetrahedron: it has no mass or stiffness of its own and is held in place."));
            if (ValidationIssue.AnyError(issues, start))
                return null;

            bool quadratic = order == FemElementOrder.Quadratic;
            float3[] positions = mesh.Positions;
            int[] elementNodes = new int[0];
            int2[] edgeEnds = new int2[0];
            if (quadratic)
                QuadraticTetrahedra.Build(mesh, out positions, out elementNodes, out edgeEnds);
            int nodeCount = positions.Length, tets = mesh.TetrahedronCount, perElement = quadratic ? QuadraticTet.NodeCount : 4;
            var data = new FemModelData
            {
                RestPositions = (float3[])positions.Clone(),
                Masses = new float[nodeCount],
                InverseMasses = new float[nodeCount],
                Elements = new TetElement[tets],
                StiffnessDiagonal = new float[nodeCount],
                Mu = material.LameMu,
                Lambda = material.LameLambda,
                DampingRatio = material.DampingRatio,
                ElementNodes = elementNodes,
                EdgeEnds = edgeEnds,
                PointGradients = new float3[quadratic ? QuadraticTet.PointCount * QuadraticTet.NodeCount * tets : 0],
                PointVolumes = new float[quadratic ? QuadraticTet.PointCount * tets : 0],
            };
            var corners = new int[perElement * tets];
            float diagonalFactor = data.Mu + (data.Mu + data.Lambda) / 3f;
            Span<float3> cornerGradients = stackalloc float3[4];
            for (int t = 0; t < tets; t++)
            {
                int4 tet = mesh.Tetrahedra[t];
                float3 x0 = mesh.Positions[tet.x];
                var dm = new float3x3(mesh.Positions[tet.y] - x0, mesh.Positions[tet.z] - x0, mesh.Positions[tet.w] - x0);
                float volume = math.determinant(dm) / 6f;
                float3x3 dmInv = math.inverse(dm);
                data.Elements[t] = new TetElement { Nodes = tet, InverseRestShape = dmInv, RestVolume = volume };
                TetElement.CornerGradients(dmInv, cornerGradients);
                float mass = material.Density * volume;
                if (!quadratic)
                {
                    for (int k = 0; k < 4; k++)
                    {
                        corners[4 * t + k] = tet[k];
                        data.Masses[tet[k]] += mass / 4f;
                        data.StiffnessDiagonal[tet[k]] += volume * diagonalFactor * math.lengthsq(cornerGradients[k]);
                    }
                    continue;
                }
                for (int a = 0; a < QuadraticTet.NodeCount; a++)
                {
                    int node = elementNodes[QuadraticTet.NodeCount * t + a];
                    corners[QuadraticTet.NodeCount * t + a] = node;
                    data.Masses[node] += mass * (a < 4 ? QuadraticTet.CornerMassFraction : QuadraticTet.EdgeMassFraction);
                }
                for (int q = 0; q < QuadraticTet.PointCount; q++)
                {
                    int point = QuadraticTet.PointCount * t + q;
                    Span<float3> gq = data.PointGradients.AsSpan(QuadraticTet.NodeCount * point, QuadraticTet.NodeCount);
                    QuadraticTet.Gradients(q, cornerGradients, gq);
                    float pointVolume = volume / QuadraticTet.PointCount;
                    data.PointVolumes[point] = pointVolume;
                    for (int a = 0; a < QuadraticTet.NodeCount; a++)
                        data.StiffnessDiagonal[elementNodes[QuadraticTet.NodeCount * t + a]] += pointVolume * diagonalFactor * math.lengthsq(gq[a]);
                }
            }
            float massSum = 0f;
            int massCount = 0;
            for (int i = 0; i < n; i++)
                if (used[i])
                {
                    massSum += data.Masses[i];
                    massCount++;
                }
            float meanMass = massSum / massCount;
            float3 center = float3.zero;
            float3 lo = positions[0], hi = positions[0];
            for (int i = 0; i < nodeCount; i++)
            {
                // An unused node gets the mean mass (the shared step needs mᵢ > 0) and is pinned; an edge node is pinned with both its corners.
                bool unused = i < n && !used[i];
                if (unused)
                    data.Masses[i] = meanMass;
                bool pin = unused || (pinned.Length == n && (i < n
                    ? pinned[i]
                    : pinned[edgeEnds[i - n].x] && pinned[edgeEnds[i - n].y]));
                data.InverseMasses[i] = pin ? 0f : 1f / data.Masses[i];
                center += data.Masses[i] * positions[i];
                lo = math.min(lo, positions[i]);
                hi = math.max(hi, positions[i]);
            }
            float totalMass = 0f;
            for (int i = 0; i < nodeCount; i++)
                totalMass += data.Masses[i];
            data.RestCenter = center / totalMass;
            data.DefaultDampingFrequency = DefaultReferenceFrequency(material, math.cmax(hi - lo));
            data.Incidence = ElementIncidence.Build(corners, perElement, nodeCount);
            data.Coloring = GraphColoring.Build(corners, perElement, nodeCount);
            return data;
        }

        /// <summary>ω_ref = π √(μ/ρ) / L (rad/s): the lowest bending/shear mode of a body of longest size L, roughly (the mass-spring method's rule).</summary>
        public static float DefaultReferenceFrequency(in ElasticMaterial material, float longestSide) =>
            longestSide > 0f ? math.PI * material.ShearWaveSpeed / longestSide : 0f;
    }
}
