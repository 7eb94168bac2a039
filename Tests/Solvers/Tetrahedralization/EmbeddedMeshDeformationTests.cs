using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Embedding of arbitrary points in a supplied mesh, and linear precision of the embedded deformation.</summary>
    public class EmbeddedMeshDeformationTests
    {
        static TetrahedralMesh Box() => BoxTetrahedra.Create(new float3(2f, 1f, 1.5f), new int3(4, 2, 3), new float3(0.5f, 0f, -0.25f));

        /// <summary>Points inside the box and up to 0.4 m outside it (those get extrapolated weights).</summary>
        static float3[] Points(int count, int seed)
        {
            var random = new System.Random(seed);
            var points = new float3[count];
            for (int i = 0; i < count; i++)
                points[i] = new float3(0.5f, 0f, -0.25f) + new float3(
                    (float)(random.NextDouble() * 2.8 - 1.4), (float)(random.NextDouble() * 1.8 - 0.9), (float)(random.NextDouble() * 2.3 - 1.15));
            return points;
        }

        static double DistanceToTet(TetrahedralMesh mesh, int t, float3 p)
        {
            int4 q = mesh.Tetrahedra[t];
            float3 a = mesh.Positions[q.x], b = mesh.Positions[q.y], c = mesh.Positions[q.z], d = mesh.Positions[q.w];
            double best = double.PositiveInfinity;
            // Dense barycentric sampling (step 1/24) of the solid: a brute-force upper bound on the distance.
            for (int i = 0; i <= 24; i++)
            for (int j = 0; j <= 24 - i; j++)
            for (int k = 0; k <= 24 - i - j; k++)
            {
                float w1 = i / 24f, w2 = j / 24f, w3 = k / 24f;
                float3 x = a + w1 * (b - a) + w2 * (c - a) + w3 * (d - a);
                best = Math.Min(best, math.length(x - p));
            }
            return best;
        }

        [Test]
        public void Embed_OutsidePoint_TakesNearestTetrahedron()
        {
            TetrahedralMesh mesh = Box();
            float3[] points = { new float3(2.1f, 0.2f, 0.1f), new float3(-1f, -0.8f, -1.3f), new float3(0.6f, 0.75f, 0.3f) };
            EmbeddedVertex[] embedding = TetrahedralEmbedding.Embed(mesh, points);
            for (int v = 0; v < points.Length; v++)
            {
                int chosen = Array.FindIndex(mesh.Tetrahedra, q => q.Equals(embedding[v].Nodes));
                double chosenDistance = DistanceToTet(mesh, chosen, points[v]);
                double nearest = double.PositiveInfinity;
                for (int t = 0; t < mesh.TetrahedronCount; t++)
                    nearest = Math.Min(nearest, DistanceToTet(mesh, t, points[v]));
                // Sampling at step 1/24 of a tetrahedron with edges ≤ 0.9 m overestimates a distance by ≤ 0.9·√3/24 ≈ 0.065 m.
                Assert.That(chosenDistance, Is.LessThanOrEqualTo(nearest + 0.065), $"point {v}");
            }
        }

        /// <summary>
        /// x' = s·R·x + t applied to the nodes moves every embedded point (inside or extrapolated) to s·R·p + t: the
        /// weights reproduce affine maps. Float round-off: the rest embedding is within 6ε·Σ|w||x| of p, and the
        /// deformed sum and the reference each add ≈ 4ε·Σ|w||x'|; with Σ|w| ≤ 3 for points ≤ 0.4 m outside and
        /// |x'| ≤ 4 m, 1e-5 m bounds them all.
        /// </summary>
        [Test]
        public void Deform_ScaledRotatedTranslatedNodes_MoveVerticesByTheSameMap()
        {
            TetrahedralMesh mesh = Box();
            float3[] points = Points(240, 7);
            EmbeddedVertex[] embedding = TetrahedralEmbedding.Embed(mesh, points);
            quaternion rotation = math.normalize(new quaternion(0.2f, -0.4f, 0.1f, 0.9f));
            float scale = 1.7f;
            var translation = new float3(0.3f, -1.1f, 2f);
            var nodes = new float3[mesh.NodeCount];
            for (int n = 0; n < nodes.Length; n++)
                nodes[n] = scale * math.rotate(rotation, mesh.Positions[n]) + translation;

            var deformed = new float3[points.Length];
            EmbeddedMeshDeformation.Deform(embedding, nodes, deformed, 0, 150);
            EmbeddedMeshDeformation.Deform(embedding, nodes, deformed, 150, points.Length);
            var normals = new float3[points.Length];
            var vertices = new DeformedVertex[points.Length];
            var random = new System.Random(3);
            for (int v = 0; v < points.Length; v++)
                normals[v] = math.normalize(new float3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f));
            AxisAlignedBox bounds = EmbeddedMeshDeformation.Deform(embedding, mesh.Positions, normals, nodes, vertices);

            int outside = 0;
            float3 min = new float3(float.PositiveInfinity), max = new float3(float.NegativeInfinity);
            for (int v = 0; v < points.Length; v++)
            {
                float4 w = embedding[v].Weights;
                if (math.min(math.min(w.x, w.y), math.min(w.z, w.w)) < -1e-6f)
                    outside++;
                float3 expected = scale * math.rotate(rotation, points[v]) + translation;
                Assert.That(math.length(deformed[v] - expected), Is.LessThan(1e-5f), $"vertex {v}");
                Assert.That(vertices[v].Position, Is.EqualTo(deformed[v]));
                // Nanson: cof(sR) N = s²·R N; normalised it is R N, to float round-off of the cross products (≈ 1e-6).
                Assert.That(math.length(vertices[v].Normal - math.rotate(rotation, normals[v])), Is.LessThan(1e-5f), $"normal {v}");
                min = math.min(min, deformed[v]);
                max = math.max(max, deformed[v]);
            }
            Assert.That(outside, Is.GreaterThan(50), "the sample includes extrapolated vertices");
            Assert.That(bounds.Min, Is.EqualTo(min));
            Assert.That(bounds.Max, Is.EqualTo(max));
        }

        /// <summary>A shear x' = x + 0.5·y·e_x maps the normal e_x (planes x = c, which become x − y/2 = c) to F⁻ᵀ e_x ∝ (1, −0.5, 0) (Nanson), not to F·e_x = e_x.</summary>
        [Test]
        public void DeformNormals_Shear_FollowsInverseTranspose()
        {
            TetrahedralMesh mesh = Box();
            float3[] points = { new float3(0.4f, 0.1f, 0f) };
            EmbeddedVertex[] embedding = TetrahedralEmbedding.Embed(mesh, points);
            var nodes = new float3[mesh.NodeCount];
            for (int n = 0; n < nodes.Length; n++)
                nodes[n] = mesh.Positions[n] + new float3(0.5f * mesh.Positions[n].y, 0f, 0f);
            var vertices = new DeformedVertex[1];
            EmbeddedMeshDeformation.Deform(embedding, mesh.Positions, new[] { new float3(1f, 0f, 0f) }, nodes, vertices);
            float3 expected = math.normalize(new float3(1f, -0.5f, 0f));
            Assert.That(math.length(vertices[0].Normal - expected), Is.LessThan(1e-5f));
        }
    }
}
