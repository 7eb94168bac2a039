using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Structural assertions on tetrahedral meshes shared by the tetrahedralisation tests.</summary>
    static class TetMeshAssert
    {
        /// <summary>Float32 machine epsilon 2⁻²³.</summary>
        public const float Epsilon = 1.1920929e-7f;

        public static void AllPositive(TetrahedralMesh mesh)
        {
            for (int t = 0; t < mesh.TetrahedronCount; t++)
            {
                int4 q = mesh.Tetrahedra[t];
                double v = TetrahedralMeshChecks.SignedVolume(mesh.Positions[q.x], mesh.Positions[q.y], mesh.Positions[q.z], mesh.Positions[q.w]);
                Assert.That(v, Is.GreaterThan(0.0), $"tetrahedron {t}");
            }
        }

        /// <summary>
        /// Conformity: every triangular face is used by one or two tetrahedra, a shared face with opposite
        /// orientations, and a face used once is on the boundary of the union: a point just outside it (by 1e-3 of
        /// its longest edge along the outward normal) lies in no tetrahedron, so no tetrahedron has a hanging face.
        /// Returns the number of boundary faces.
        /// </summary>
        public static int Conforms(TetrahedralMesh mesh)
        {
            var faces = new Dictionary<(int, int, int), (int count, int parity, int tet, int opposite)>();
            int[][] local = { new[] { 1, 2, 3, 0 }, new[] { 0, 2, 3, 1 }, new[] { 0, 1, 3, 2 }, new[] { 0, 1, 2, 3 } };
            for (int t = 0; t < mesh.TetrahedronCount; t++)
            {
                int4 q = mesh.Tetrahedra[t];
                foreach (int[] f in local)
                {
                    int a = q[f[0]], b = q[f[1]], c = q[f[2]];
                    int[] s = { a, b, c };
                    Array.Sort(s);
                    // The parity of the face's orientation seen from outside the tetrahedron, relative to the sorted key.
                    int parity = (f[3] % 2) ^ Parity(a, b, c);
                    var key = (s[0], s[1], s[2]);
                    if (faces.TryGetValue(key, out var e))
                    {
                        Assert.That(e.count, Is.EqualTo(1), $"face {key} used more than twice");
                        Assert.That(e.parity, Is.Not.EqualTo(parity), $"face {key} has the same orientation in both tetrahedra");
                        faces[key] = (2, parity, t, f[3]);
                    }
                    else
                        faces[key] = (1, parity, t, q[f[3]]);
                }
            }
            var min = new float3[mesh.TetrahedronCount];
            var max = new float3[mesh.TetrahedronCount];
            for (int t = 0; t < mesh.TetrahedronCount; t++)
            {
                int4 q = mesh.Tetrahedra[t];
                min[t] = math.min(math.min(mesh.Positions[q.x], mesh.Positions[q.y]), math.min(mesh.Positions[q.z], mesh.Positions[q.w]));
                max[t] = math.max(math.max(mesh.Positions[q.x], mesh.Positions[q.y]), math.max(mesh.Positions[q.z], mesh.Positions[q.w]));
            }
            int boundary = 0;
            foreach (var pair in faces)
            {
                if (pair.Value.count != 1)
                    continue;
                boundary++;
                float3 a = mesh.Positions[pair.Key.Item1], b = mesh.Positions[pair.Key.Item2], c = mesh.Positions[pair.Key.Item3];
                float3 opposite = mesh.Positions[pair.Value.opposite];
                float3 centroid = (a + b + c) / 3f;
                float3 n = math.normalize(math.cross(b - a, c - a));
                if (math.dot(n, opposite - centroid) > 0f)
                    n = -n;
                float longest = math.max(math.length(b - a), math.max(math.length(c - b), math.length(a - c)));
                float3 probe = centroid + 1e-3f * longest * n;
                for (int t = 0; t < mesh.TetrahedronCount; t++)
                {
                    if (math.any(probe < min[t]) || math.any(probe > max[t]))
                        continue;
                    int4 q = mesh.Tetrahedra[t];
                    TetrahedralEmbedding.Barycentric(probe, mesh.Positions[q.x], mesh.Positions[q.y], mesh.Positions[q.z], mesh.Positions[q.w],
                        out double l0, out double l1, out double l2, out double l3);
                    Assert.That(Math.Min(Math.Min(l0, l1), Math.Min(l2, l3)), Is.LessThan(0.0),
                        $"boundary face {pair.Key} has tetrahedron {t} on its outer side: the mesh does not conform");
                }
            }
            return boundary;
        }

        /// <summary>Parity of the permutation that sorts (a, b, c): 0 even, 1 odd.</summary>
        static int Parity(int a, int b, int c)
        {
            int inversions = (a > b ? 1 : 0) + (a > c ? 1 : 0) + (b > c ? 1 : 0);
            return inversions & 1;
        }
    }
}
