using System;
using System.Collections.Generic;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The stronger preconditioner of the implicit step: a sparse Cholesky factor L Lᵀ = M + c₀ K₀ of the rest system
    /// (free nodes only), computed once at bake time, applied warped by a rotation per node,
    /// P⁻¹ = R̄ (L Lᵀ)⁻¹ R̄ᵀ, R̄ = diag(Rᵢ) with Rᵢ the mean rotation of node i's integration points. For a body whose
    /// elements rotate together around each node this is A⁻¹ of the warped system A = M + c R K₀ Rᵀ exactly; CG then
    /// corrects what differs (rotations that vary between a node's elements, c ≠ c₀) in a few iterations. This is the
    /// factor reuse of corotational elastodynamics (Hecht, Lee, Shewchuk &amp; O'Brien 2012) without the updates.
    /// <para>
    /// Storage: free nodes in reverse Cuthill–McKee order (rank → node in <see cref="FemModel.FactorNodes"/>), three rows
    /// per node (x, y, z), L in envelope (skyline) form: row i holds columns [i − len + 1, i] with len =
    /// RowStarts[i + 1] − RowStarts[i], values in <see cref="FemModel.FactorValues"/>.
    /// </para>
    /// </summary>
    public static class FemRestFactor
    {
        /// <summary>
        /// Factors M + <paramref name="c"/> K₀ of <paramref name="model"/> (c = hβ + h², s²; K₀ the rest stiffness of its
        /// elements, R = I). Bake time, managed, in double; false (and empty arrays) when the matrix is not positive definite
        /// in float64 or the body has no free node.
        /// </summary>
        public static bool Build(in FemModel model, float c, out int[] nodes, out int[] rowStarts, out float[] values)
        {
            nodes = new int[0];
            rowStarts = new int[0];
            values = new float[0];
            int n = model.ParticleCount;
            int[] order = ReverseCuthillMcKee(model, out List<int>[] neighbours);
            if (order.Length == 0)
                return false;
            var rank = new int[n];
            for (int i = 0; i < n; i++)
                rank[i] = -1;
            for (int r = 0; r < order.Length; r++)
                rank[order[r]] = r;
            int dofs = 3 * order.Length;
            var starts = new int[dofs + 1];
            var first = new int[dofs];
            for (int r = 0; r < order.Length; r++)
            {
                int low = r;
                foreach (int j in neighbours[order[r]])
                    if (rank[j] >= 0)
                        low = math.min(low, rank[j]);
                for (int k = 0; k < 3; k++)
                {
                    first[3 * r + k] = 3 * low;
                    starts[3 * r + k + 1] = starts[3 * r + k] + 3 * r + k - 3 * low + 1;
                }
            }
            var a = new double[starts[dofs]];
            for (int r = 0; r < order.Length; r++)
                for (int k = 0; k < 3; k++)
                    a[starts[3 * r + k] + 3 * r + k - first[3 * r + k]] += model.Masses[order[r]];
            AssembleStiffness(model, c, rank, starts, first, a);
            if (!Factor(a, starts, first))
                return false;
            nodes = order;
            rowStarts = starts;
            values = Array.ConvertAll(a, v => (float)v);
            return true;
        }

        /// <summary>
        /// Per node, the sign-aligned normalised sum of the rotations of the integration points of its elements (in incidence
        /// order): its (x, y, z) with w ≥ 0 into <paramref name="nodeRotations"/> (w = √(1 − |xyz|²)).
        /// </summary>
        public static void NodeRotations(in FemModel model, ReadOnlySpan<quaternion> rotations, Span<float3> nodeRotations)
        {
            int perElement = model.NodesPerElement, points = model.PointsPerElement;
            for (int i = 0; i < model.ParticleCount; i++)
            {
                float4 sum = float4.zero, reference = float4.zero;
                for (int s = model.IncidenceOffsets[i]; s < model.IncidenceOffsets[i + 1]; s++)
                {
                    int e = model.IncidenceSlots[s] / perElement;
                    for (int q = 0; q < points; q++)
                    {
                        float4 value = rotations[points * e + q].value;
                        if (s == model.IncidenceOffsets[i] && q == 0)
                            reference = value;
                        sum += math.dot(value, reference) < 0f ? -value : value;
                    }
                }
                float length = math.length(sum);
                float4 mean = length > 0f ? sum / length : new float4(0f, 0f, 0f, 1f);
                nodeRotations[i] = mean.w < 0f ? -mean.xyz : mean.xyz;
            }
        }

        /// <summary>
        /// z = R̄ (L Lᵀ)⁻¹ R̄ᵀ r (0 at pinned nodes); returns r · z. <paramref name="nodeRotations"/> from
        /// <see cref="NodeRotations"/>; <paramref name="temp"/> holds 3 floats per free node.
        /// </summary>
        public static float Apply(in FemModel model, ReadOnlySpan<float3> nodeRotations, ReadOnlySpan<float3> r, Span<float3> z,
            Span<float> temp)
        {
            ReadOnlySpan<int> nodes = model.FactorNodes, starts = model.FactorRowStarts;
            ReadOnlySpan<float> l = model.FactorValues;
            int dofs = 3 * nodes.Length;
            for (int k = 0; k < nodes.Length; k++)
            {
                float3 local = math.mul(math.conjugate(Rotation(nodeRotations[nodes[k]])), r[nodes[k]]);
                temp[3 * k] = local.x;
                temp[3 * k + 1] = local.y;
                temp[3 * k + 2] = local.z;
            }
            // L y = b, row by row over each row's envelope.
            for (int i = 0; i < dofs; i++)
            {
                int start = starts[i], length = starts[i + 1] - start, firstColumn = i - length + 1;
                float sum = temp[i];
                for (int j = 0; j < length - 1; j++)
                    sum -= l[start + j] * temp[firstColumn + j];
                temp[i] = sum / l[start + length - 1];
            }
            // Lᵀ x = y, column by column from the last.
            for (int i = dofs - 1; i >= 0; i--)
            {
                int start = starts[i], length = starts[i + 1] - start, firstColumn = i - length + 1;
                float xi = temp[i] / l[start + length - 1];
                temp[i] = xi;
                for (int j = 0; j < length - 1; j++)
                    temp[firstColumn + j] -= l[start + j] * xi;
            }
            z.Clear();
            float rz = 0f;
            for (int k = 0; k < nodes.Length; k++)
            {
                int node = nodes[k];
                z[node] = math.mul(Rotation(nodeRotations[node]), new float3(temp[3 * k], temp[3 * k + 1], temp[3 * k + 2]));
                rz += math.dot(r[node], z[node]);
            }
            return rz;
        }

        static quaternion Rotation(float3 xyz) => new quaternion(new float4(xyz, math.sqrt(math.max(0f, 1f - math.lengthsq(xyz)))));

        /// <summary>Free nodes (inverse mass &gt; 0) in reverse Cuthill–McKee order of the element graph, each component from a node of least degree.</summary>
        static int[] ReverseCuthillMcKee(in FemModel model, out List<int>[] neighbours)
        {
            int n = model.ParticleCount, perElement = model.NodesPerElement;
            neighbours = new List<int>[n];
            var sets = new HashSet<int>[n];
            for (int i = 0; i < n; i++)
                sets[i] = new HashSet<int>();
            for (int e = 0; e < model.ElementCount; e++)
                for (int a = 0; a < perElement; a++)
                    for (int b = 0; b < perElement; b++)
                        if (a != b)
                            sets[ElementNode(model, e, a)].Add(ElementNode(model, e, b));
            var degree = new int[n];
            for (int i = 0; i < n; i++)
            {
                neighbours[i] = new List<int>(sets[i]);
                neighbours[i].Sort();
                degree[i] = neighbours[i].Count;
            }
            var visited = new bool[n];
            var order = new List<int>();
            while (true)
            {
                int seed = -1;
                for (int i = 0; i < n; i++)
                    if (!visited[i] && model.InverseMasses[i] > 0f && (seed < 0 || degree[i] < degree[seed]))
                        seed = i;
                if (seed < 0)
                    break;
                visited[seed] = true;
                int head = order.Count;
                order.Add(seed);
                while (head < order.Count)
                {
                    int node = order[head++];
                    var next = new List<int>();
                    foreach (int j in neighbours[node])
                        if (!visited[j] && model.InverseMasses[j] > 0f)
                        {
                            visited[j] = true;
                            next.Add(j);
                        }
                    next.Sort((p, q) => degree[p] != degree[q] ? degree[p].CompareTo(degree[q]) : p.CompareTo(q));
                    order.AddRange(next);
                }
            }
            order.Reverse();
            return order.ToArray();
        }

        static int ElementNode(in FemModel model, int e, int a) =>
            model.IsQuadratic ? model.ElementNodes[QuadraticTet.NodeCount * e + a] : model.Elements[e].Nodes[a];

        /// <summary>
        /// Adds c K₀ into the envelope: per integration point and pair of free nodes (a, b) with rank(a) ≥ rank(b) the block
        /// V (μ (g_a·g_b) I + μ g_b g_aᵀ + λ g_a g_bᵀ) (the force on a of a displacement of b, δP = μ(δF + δFᵀ) + λ tr δF I).
        /// </summary>
        static void AssembleStiffness(in FemModel model, float c, int[] rank, int[] starts, int[] first, double[] a)
        {
            int perElement = model.NodesPerElement, points = model.PointsPerElement;
            double mu = model.Mu, lambda = model.Lambda;
            var g = new float3[perElement];
            var node = new int[perElement];
            for (int e = 0; e < model.ElementCount; e++)
            {
                for (int k = 0; k < perElement; k++)
                    node[k] = ElementNode(model, e, k);
                for (int q = 0; q < points; q++)
                {
                    double volume;
                    if (model.IsQuadratic)
                    {
                        int point = points * e + q;
                        model.PointGradients.Slice(perElement * point, perElement).CopyTo(g);
                        volume = model.PointVolumes[point];
                    }
                    else
                    {
                        TetElement element = model.Elements[e];
                        TetElement.CornerGradients(element.InverseRestShape, g);
                        volume = element.RestVolume;
                    }
                    for (int x = 0; x < perElement; x++)
                    for (int y = 0; y < perElement; y++)
                    {
                        int ra = rank[node[x]], rb = rank[node[y]];
                        if (ra < 0 || rb < 0 || ra < rb)
                            continue;
                        double dot = (double)g[x].x * g[y].x + (double)g[x].y * g[y].y + (double)g[x].z * g[y].z;
                        for (int i = 0; i < 3; i++)
                        for (int j = 0; j < 3; j++)
                        {
                            int row = 3 * ra + i, column = 3 * rb + j;
                            if (column > row)
                                continue;
                            double k = mu * (i == j ? dot : 0.0) + mu * (double)g[y][i] * g[x][j] + lambda * (double)g[x][i] * g[y][j];
                            a[starts[row] + column - first[row]] += c * volume * k;
                        }
                    }
                }
            }
        }

        /// <summary>In-place envelope Cholesky (row by row): L_ij = (A_ij − Σ_k L_ik L_jk) / L_jj, L_ii = √(A_ii − Σ_k L_ik²).</summary>
        static bool Factor(double[] a, int[] starts, int[] first)
        {
            int dofs = first.Length;
            for (int i = 0; i < dofs; i++)
            {
                int fi = first[i], si = starts[i];
                for (int j = fi; j <= i; j++)
                {
                    int fj = first[j], sj = starts[j];
                    double sum = a[si + j - fi];
                    for (int k = math.max(fi, fj); k < j; k++)
                        sum -= a[si + k - fi] * a[sj + k - fj];
                    if (j < i)
                        a[si + j - fi] = sum / a[sj + j - fj];
                    else
                    {
                        if (!(sum > 0.0))
                            return false;
                        a[si + i - fi] = Math.Sqrt(sum);
                    }
                }
            }
            return true;
        }
    }
}
