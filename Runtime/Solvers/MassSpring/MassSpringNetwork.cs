using System;
using System.Collections.Generic;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The springs of a tetrahedral mesh before a material is given (Teschner et al. 2003, §3.1): one structural
    /// spring per unique edge of the tetrahedra, and optionally one bending spring per pair of tetrahedra sharing a
    /// face. Rest lengths come from the rest shape; stiffness and damping are zero until
    /// <see cref="MassSpringCalibration.Apply"/> sets them. Built at bake time (managed arrays).
    /// </summary>
    public sealed class MassSpringNetwork
    {
        /// <summary>Springs: structural ones first, sorted by (A, B) with A &lt; B, then bending ones sorted the same way.</summary>
        public Spring[] Springs;
        /// <summary>Σ V_t over the tetrahedra that contain each spring (m³): its share of the body in the calibration k = c E V / L².</summary>
        public float[] SupportVolumes;
        /// <summary>Springs [0, StructuralCount) are edges of the tetrahedra; the rest are bending springs.</summary>
        public int StructuralCount;
        /// <summary>Volume of each node, Σ V_t / 4 over the tetrahedra that contain it (m³); lumped mass = ρ × this.</summary>
        public float[] NodeVolumes;
        /// <summary>Number of nodes (particles).</summary>
        public int NodeCount;

        /// <summary>Springs of <paramref name="mesh"/>; problems go to <paramref name="issues"/>. Null when an error leaves nothing to build.</summary>
        public static MassSpringNetwork Build(TetrahedralMesh mesh, in MassSpringBuildSettings settings, List<ValidationIssue> issues)
        {
            int start = issues.Count;
            if (mesh == null || mesh.Positions == null || mesh.Tetrahedra == null || mesh.NodeCount == 0 || mesh.TetrahedronCount == 0)
            {
                issues.Add(ValidationIssue.Error(MassSpringIssueCode.EmptyMesh, -1,
                    "The tetrahedral mesh has no nodes or no tetrahedra: there is nothing to connect with springs."));
                return null;
            }
            int n = mesh.NodeCount;
            for (int i = 0; i < n; i++)
                if (!math.all(math.isfinite(mesh.Positions[i])))
                {
                    issues.Add(ValidationIssue.Error(MassSpringIssueCode.NonFiniteNode, i,
                        $"Node {i} has a NaN or infinite position. Fix the mesh that produced it."));
                    return null;
                }
            for (int t = 0; t < mesh.TetrahedronCount; t++)
            {
                int4 q = mesh.Tetrahedra[t];
                if ((uint)q.x >= (uint)n || (uint)q.y >= (uint)n || (uint)q.z >= (uint)n || (uint)q.w >= (uint)n)
                {
                    issues.Add(ValidationIssue.Error(MassSpringIssueCode.TetrahedronIndexOutOfRange, t,
                        $"Tetrahedron {t} refers to node {OutOfRange(q, n)}, but the mesh has {n} nodes."));
                    return null;
                }
            }

            bool[] keep = UniqueTetrahedra(mesh, issues);
            var volumes = new double[mesh.TetrahedronCount];
            var nodeVolumes = new double[n];
            int firstDegenerate = -1, degenerate = 0;
            for (int t = 0; t < mesh.TetrahedronCount; t++)
            {
                if (!keep[t])
                    continue;
                int4 q = mesh.Tetrahedra[t];
                double v = Math.Abs(SignedVolume(mesh.Positions, q));
                if (!(v > 0.0))
                {
                    degenerate++;
                    if (firstDegenerate < 0)
                        firstDegenerate = t;
                }
                volumes[t] = v;
                for (int k = 0; k < 4; k++)
                    nodeVolumes[q[k]] += v / 4.0;
            }
            if (degenerate > 0)
                issues.Add(ValidationIssue.Warning(MassSpringIssueCode.DegenerateTetrahedron, firstDegenerate,
                    $"{degenerate} tetrahedra have zero volume (first: {firstDegenerate}); they add no stiffness and no mass."));

            // Structural springs: (edge key, volume) per tetrahedron edge, sorted and merged.
            var keys = new List<long>(6 * mesh.TetrahedronCount);
            var edgeVolumes = new List<double>(6 * mesh.TetrahedronCount);
            var edgeTets = new List<int>(6 * mesh.TetrahedronCount);
            for (int t = 0; t < mesh.TetrahedronCount; t++)
            {
                if (!keep[t])
                    continue;
                int4 q = mesh.Tetrahedra[t];
                for (int a = 0; a < 4; a++)
                    for (int b = a + 1; b < 4; b++)
                    {
                        keys.Add(Key(q[a], q[b]));
                        edgeVolumes.Add(volumes[t]);
                        edgeTets.Add(t);
                    }
            }
            var springs = new List<Spring>();
            var support = new List<float>();
            var structural = new HashSet<long>();
            int zeroLength = 0, firstZero = -1;
            AddMerged(mesh.Positions, keys, edgeVolumes, edgeTets, springs, support, structural, ref zeroLength, ref firstZero);
            int structuralCount = springs.Count;

            if (settings.BendingSprings)
            {
                // Faces (sorted node triple) with their tetrahedron's opposite node; a face in exactly two tetrahedra
                // gives a spring between the two opposite nodes.
                var faces = new List<(long hi, int lo, int opposite, int tet)>();
                for (int t = 0; t < mesh.TetrahedronCount; t++)
                {
                    if (!keep[t])
                        continue;
                    int4 q = mesh.Tetrahedra[t];
                    for (int k = 0; k < 4; k++)
                    {
                        Span<int> f = stackalloc int[3];
                        int m = 0;
                        for (int j = 0; j < 4; j++)
                            if (j != k)
                                f[m++] = q[j];
                        Sort3(f);
                        faces.Add((Key(f[0], f[1]), f[2], q[k], t));
                    }
                }
                faces.Sort((x, y) => x.hi != y.hi ? x.hi.CompareTo(y.hi) : x.lo != y.lo ? x.lo.CompareTo(y.lo) : x.tet.CompareTo(y.tet));
                var bendKeys = new List<long>();
                var bendVolumes = new List<double>();
                var bendTets = new List<int>();
                for (int i = 0; i < faces.Count;)
                {
                    int j = i + 1;
                    while (j < faces.Count && faces[j].hi == faces[i].hi && faces[j].lo == faces[i].lo)
                        j++;
                    if (j - i == 2 && faces[i].opposite != faces[i + 1].opposite)
                    {
                        long key = Key(faces[i].opposite, faces[i + 1].opposite);
                        if (!structural.Contains(key))
                        {
                            bendKeys.Add(key);
                            bendVolumes.Add(volumes[faces[i].tet] + volumes[faces[i + 1].tet]);
                            bendTets.Add(faces[i].tet);
                        }
                    }
                    i = j;
                }
                AddMerged(mesh.Positions, bendKeys, bendVolumes, bendTets, springs, support, null, ref zeroLength, ref firstZero);
            }
            if (zeroLength > 0)
                issues.Add(ValidationIssue.Warning(MassSpringIssueCode.ZeroLengthEdge, firstZero,
                    $"{zeroLength} edges have zero rest length (first in tetrahedron {firstZero}: a repeated node or two coincident nodes); their springs are left out."));
            if (springs.Count == 0)
            {
                issues.Add(ValidationIssue.Error(MassSpringIssueCode.NoSprings, -1,
                    "No spring is left: every edge of the tetrahedra has zero length."));
                return null;
            }

            var network = new MassSpringNetwork
            {
                Springs = springs.ToArray(),
                SupportVolumes = support.ToArray(),
                StructuralCount = structuralCount,
                NodeVolumes = new float[n],
                NodeCount = n,
            };
            double total = 0.0;
            int used = 0, firstIsolated = -1, isolated = 0;
            for (int i = 0; i < n; i++)
                if (nodeVolumes[i] > 0.0)
                {
                    total += nodeVolumes[i];
                    used++;
                }
            double mean = used > 0 ? total / used : 0.0;
            for (int i = 0; i < n; i++)
            {
                if (!(nodeVolumes[i] > 0.0))
                {
                    isolated++;
                    if (firstIsolated < 0)
                        firstIsolated = i;
                    nodeVolumes[i] = mean;
                }
                network.NodeVolumes[i] = (float)nodeVolumes[i];
            }
            if (isolated > 0)
                issues.Add(ValidationIssue.Warning(MassSpringIssueCode.IsolatedNode, firstIsolated,
                    $"{isolated} nodes belong to no tetrahedron of non-zero volume (first: {firstIsolated}); they get the mean mass and no spring holds them."));
            if (!(mean > 0.0))
            {
                issues.Add(ValidationIssue.Error(MassSpringIssueCode.NoSprings, -1,
                    "Every tetrahedron has zero volume: the body has no mass and no stiffness."));
                return null;
            }
            return ValidationIssue.AnyError(issues, start) ? null : network;
        }

        /// <summary>False for the second and later copies of a tetrahedron (the same four nodes in any order); warns once.</summary>
        static bool[] UniqueTetrahedra(TetrahedralMesh mesh, List<ValidationIssue> issues)
        {
            int count = mesh.TetrahedronCount;
            var keep = new bool[count];
            var sorted = new (int a, int b, int c, int d, int t)[count];
            var s = new int[4];
            for (int t = 0; t < count; t++)
            {
                int4 q = mesh.Tetrahedra[t];
                s[0] = q.x; s[1] = q.y; s[2] = q.z; s[3] = q.w;
                Array.Sort(s);
                sorted[t] = (s[0], s[1], s[2], s[3], t);
                keep[t] = true;
            }
            Array.Sort(sorted);
            int duplicates = 0, first = -1;
            for (int i = 1; i < count; i++)
            {
                var p = sorted[i - 1];
                var q = sorted[i];
                if (p.a == q.a && p.b == q.b && p.c == q.c && p.d == q.d)
                {
                    keep[q.t] = false;
                    duplicates++;
                    first = first < 0 ? q.t : Math.Min(first, q.t);
                }
            }
            if (duplicates > 0)
                issues.Add(ValidationIssue.Warning(MassSpringIssueCode.DuplicateTetrahedron, first,
                    $"{duplicates} tetrahedra repeat the nodes of another (first: {first}); each copy is merged with its original."));
            return keep;
        }

        /// <summary>Sorts the (key, volume) entries by key and adds one spring per key, summing the volumes; zero-length edges are counted and skipped.</summary>
        static void AddMerged(float3[] positions, List<long> keys, List<double> volumes, List<int> tets, List<Spring> springs,
            List<float> support, HashSet<long> seen, ref int zeroLength, ref int firstZero)
        {
            int count = keys.Count;
            var order = new int[count];
            var sortKeys = keys.ToArray();
            for (int i = 0; i < count; i++)
                order[i] = i;
            Array.Sort(sortKeys, order);
            for (int i = 0; i < count;)
            {
                long key = sortKeys[i];
                double volume = 0.0;
                int j = i;
                int firstTet = int.MaxValue;
                for (; j < count && sortKeys[j] == key; j++)
                {
                    volume += volumes[order[j]];
                    firstTet = Math.Min(firstTet, tets[order[j]]);
                }
                i = j;
                int a = (int)(key >> 32), b = (int)(key & 0xFFFFFFFF);
                float length = math.distance(positions[a], positions[b]);
                if (a == b || !(length > 0f))
                {
                    zeroLength++;
                    firstZero = firstZero < 0 ? firstTet : Math.Min(firstZero, firstTet);
                    continue;
                }
                seen?.Add(key);
                springs.Add(new Spring(a, b, length, 0f, 0f));
                support.Add((float)volume);
            }
        }

        static long Key(int a, int b) => a <= b ? ((long)a << 32) | (uint)b : ((long)b << 32) | (uint)a;

        static void Sort3(Span<int> f)
        {
            if (f[0] > f[1]) (f[0], f[1]) = (f[1], f[0]);
            if (f[1] > f[2]) (f[1], f[2]) = (f[2], f[1]);
            if (f[0] > f[1]) (f[0], f[1]) = (f[1], f[0]);
        }

        static int OutOfRange(int4 q, int n) => (uint)q.x >= (uint)n ? q.x : (uint)q.y >= (uint)n ? q.y : (uint)q.z >= (uint)n ? q.z : q.w;

        /// <summary>Signed volume of tetrahedron <paramref name="q"/> in double (m³).</summary>
        internal static double SignedVolume(float3[] x, int4 q)
        {
            double ax = x[q.y].x - x[q.x].x, ay = x[q.y].y - x[q.x].y, az = x[q.y].z - x[q.x].z;
            double bx = x[q.z].x - x[q.x].x, by = x[q.z].y - x[q.x].y, bz = x[q.z].z - x[q.x].z;
            double cx = x[q.w].x - x[q.x].x, cy = x[q.w].y - x[q.x].y, cz = x[q.w].z - x[q.x].z;
            return (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6.0;
        }
    }
}
