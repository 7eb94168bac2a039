using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The 10-node quadratic tetrahedron: its shape functions, quadrature, lumped masses and baked model.</summary>
    public class QuadraticTetTests
    {
        static readonly ElasticMaterial s_Rubber = new ElasticMaterial(1e6f, 0.45f, 1100f, 0f);

        static FemModelData Cube(int cells = 2, float side = 0.2f, bool[] pinned = null) =>
            FemTestBodies.Bake(FemTestBodies.Box(cells, cells, cells, new float3(side)), s_Rubber, pinned, FemElementOrder.Quadratic);

        [Test]
        public void ShapeFunctions_AreOneAtTheirNode_AndZeroAtTheOthers()
        {
            // Nodes in barycentric coordinates: the corners, then the edge midpoints.
            var nodes = new float[10][];
            for (int a = 0; a < 4; a++)
            {
                nodes[a] = new float[4];
                nodes[a][a] = 1f;
            }
            for (int k = 0; k < 6; k++)
            {
                int2 e = QuadraticTet.EdgeCorners(k);
                nodes[4 + k] = new float[4];
                nodes[4 + k][e.x] = 0.5f;
                nodes[4 + k][e.y] = 0.5f;
            }
            var n = new float[10];
            for (int b = 0; b < 10; b++)
            {
                QuadraticTet.ShapeFunctions(nodes[b][0], nodes[b][1], nodes[b][2], nodes[b][3], n);
                for (int a = 0; a < 10; a++)
                    Assert.That(n[a], Is.EqualTo(a == b ? 1f : 0f).Within(1e-6f), $"N_{a} at node {b}");
            }
        }

        [Test]
        public void LumpedMasses_ArePositive_AndSumToTheBodyMass()
        {
            FemModelData data = Cube();
            double sum = 0;
            foreach (float m in data.Masses)
            {
                Assert.That(m, Is.GreaterThan(0f));
                sum += m;
            }
            double expected = s_Rubber.Density * 0.2 * 0.2 * 0.2;
            // float32 sums of a few hundred positive terms: relative error ≲ n ε.
            Assert.That(sum, Is.EqualTo(expected).Within(1e-5 * expected));
            Assert.That(4 * QuadraticTet.CornerMassFraction + 6 * QuadraticTet.EdgeMassFraction, Is.EqualTo(1f).Within(1e-6f));
        }

        [Test]
        public void EdgeNodes_AreSharedMidpoints_AndPinnedWithBothCorners()
        {
            TetrahedralMesh mesh = FemTestBodies.Box(2, 2, 2, new float3(0.2f));
            var pinned = new bool[mesh.NodeCount];
            for (int i = 0; i < pinned.Length; i++)
                pinned[i] = mesh.Positions[i].x == 0f;
            FemModelData data = Cube(pinned: pinned);
            // 3×3×3 corners; Kuhn-split cells conform, so every edge node is shared: the nodes are those of the 5×5×5 grid.
            Assert.That(data.RestPositions.Length, Is.EqualTo(125));
            int corners = mesh.NodeCount;
            for (int k = 0; k < data.EdgeEnds.Length; k++)
            {
                int2 ends = data.EdgeEnds[k];
                int node = corners + k;
                Assert.That(math.distance(data.RestPositions[node], 0.5f * (mesh.Positions[ends.x] + mesh.Positions[ends.y])), Is.LessThan(1e-7f));
                bool bothPinned = pinned[ends.x] && pinned[ends.y];
                Assert.That(data.InverseMasses[node] == 0f, Is.EqualTo(bothPinned), $"edge node {node} between {ends}");
            }
        }

        /// <summary>
        /// The element reproduces every quadratic displacement field: F at each integration point equals the field's gradient
        /// there (to float32 round-off of the ~10 products per entry), so its strain varies linearly, as bending needs.
        /// </summary>
        [Test]
        public void DeformationGradient_OfAQuadraticField_IsExactAtEveryPoint()
        {
            FemModelData data = Cube(1);
            FemModel model = data.AsModel();
            // x = X + (0.3 X·X, 0.7 X_x X_z, −0.2 X_y²) has ∇x = I + [[0.6X_x, 0.6X_y, 0.6X_z], [0.7X_z, 0, 0.7X_x], [0, −0.4X_y, 0]].
            static float3 Field(float3 p) => p + new float3(0.3f * math.dot(p, p), 0.7f * p.x * p.z, -0.2f * p.y * p.y);
            var x = Array.ConvertAll(data.RestPositions, Field);
            var n = new float[10];
            for (int e = 0; e < model.ElementCount; e++)
                for (int q = 0; q < QuadraticTet.PointCount; q++)
                {
                    ReadOnlySpan<int> nodes = model.ElementNodes.Slice(10 * e, 10);
                    int point = 4 * e + q;
                    QuadraticTet.ShapeFunctions(q, n);
                    float3 at = float3.zero;
                    for (int a = 0; a < 10; a++)
                        at += n[a] * data.RestPositions[nodes[a]];
                    var expected = new float3x3(
                        1f + 0.6f * at.x, 0.6f * at.y, 0.6f * at.z,
                        0.7f * at.z, 1f, 0.7f * at.x,
                        0f, -0.4f * at.y, 1f);
                    float3x3 f = QuadraticTet.DeformationGradient(x, nodes, model.PointGradients.Slice(10 * point, 10));
                    for (int c = 0; c < 3; c++)
                        Assert.That(math.distance(f[c], expected[c]), Is.LessThan(2e-5f), $"element {e} point {q} column {c}");
                }
        }

        /// <summary>
        /// A render vertex skinned to a quadratic element follows a quadratic deformation of the nodes exactly (to float32
        /// round-off), where the corner tetrahedron's linear map misses the curvature; at rest both give the vertex back.
        /// </summary>
        [Test]
        public void QuadraticSkinning_FollowsAQuadraticField()
        {
            TetrahedralMesh mesh = FemTestBodies.Box(1, 1, 1, new float3(0.2f));
            FemModelData data = FemTestBodies.Bake(mesh, s_Rubber, null, FemElementOrder.Quadratic);
            int4 tet = mesh.Tetrahedra[0];
            var weights = new float4(0.1f, 0.2f, 0.3f, 0.4f);
            var vertex = new EmbeddedVertex { Nodes = tet, Weights = weights };
            float3 rest = weights.x * mesh.Positions[tet.x] + weights.y * mesh.Positions[tet.y] + weights.z * mesh.Positions[tet.z]
                          + weights.w * mesh.Positions[tet.w];
            int[] edgeNodes = QuadraticTetrahedra.EmbeddingEdgeNodes(new[] { vertex }, mesh.NodeCount, data.EdgeEnds);
            Assert.That(math.distance(EmbeddedMeshDeformation.QuadraticPosition(vertex, edgeNodes, data.RestPositions), rest), Is.LessThan(1e-6f));
            static float3 Field(float3 p) => p + new float3(2f * p.y * p.y, -1.5f * p.x * p.z, 0.8f * p.x * p.x);
            var x = Array.ConvertAll(data.RestPositions, Field);
            float3 quadratic = EmbeddedMeshDeformation.QuadraticPosition(vertex, edgeNodes, x);
            float3 linear = EmbeddedMeshDeformation.Position(vertex, x);
            Assert.That(math.distance(quadratic, Field(rest)), Is.LessThan(1e-6f));
            Assert.That(math.distance(linear, Field(rest)), Is.GreaterThan(1e-3f), "the linear map misses the curvature");
        }

        /// <summary>
        /// The study's volume of a quadratic body splits each element at its edge nodes into 8 tetrahedra: at rest and under
        /// an affine map it is the mesh's volume times det (float32 positions: 1e-6 relative); a bulge of the edge nodes counts.
        /// </summary>
        [Test]
        public void StudyVolume_OfAQuadraticBody_CountsItsEdgeNodes()
        {
            TetrahedralMesh mesh = FemTestBodies.Box(2, 2, 2, new float3(0.2f));
            FemModelData data = FemTestBodies.Bake(mesh, s_Rubber, null, FemElementOrder.Quadratic);
            double rest = SoftBodyDynamics.Benchmarks.Scenarios.StudyBox.Volume(mesh, data.RestPositions);
            Assert.That(rest, Is.EqualTo(0.008).Within(1e-6 * 0.008));
            var stretched = Array.ConvertAll(data.RestPositions, p => p * new float3(1.2f, 0.9f, 1.1f));
            Assert.That(SoftBodyDynamics.Benchmarks.Scenarios.StudyBox.Volume(mesh, stretched), Is.EqualTo(0.008 * 1.188).Within(1e-5 * 0.008));
            var bulged = (float3[])data.RestPositions.Clone();
            for (int i = mesh.NodeCount; i < bulged.Length; i++)
                bulged[i] *= 1.01f;
            Assert.That(SoftBodyDynamics.Benchmarks.Scenarios.StudyBox.Volume(mesh, bulged), Is.GreaterThan(rest * 1.001));
        }

        [Test]
        public void IntegrationVolumes_SumToTheBodyVolume()
        {
            FemModel model = Cube().AsModel();
            double volume = 0;
            foreach (float v in model.PointVolumes)
                volume += v;
            // Each point volume is det(Dm)/24 in float32 (a few ε ≈ 1e-6 relative each), summed in double: 1e-5 relative bounds it.
            Assert.That(volume, Is.EqualTo(0.008).Within(1e-5 * 0.008));
        }

        /// <summary>A rigid rotation and translation of the rest shape stores no stress: every node force is zero (to round-off of μ × ε_rotation).</summary>
        [TestCase(FemMaterialModel.CoRotational)]
        [TestCase(FemMaterialModel.NeoHookean)]
        public void RigidMotion_GivesNoElasticForce(FemMaterialModel materialModel)
        {
            FemModelData data = Cube();
            FemModel model = data.AsModel();
            quaternion rotation = quaternion.AxisAngle(math.normalize(new float3(1f, 2f, 3f)), 1.1f);
            var x = Array.ConvertAll(data.RestPositions, p => math.mul(rotation, p) + new float3(0.5f, -1f, 2f));
            var rotations = new quaternion[model.PointCount];
            Array.Fill(rotations, quaternion.identity);
            var slots = new float3[model.SlotCount];
            var forces = new float3[model.ParticleCount];
            int inverted = FemForces.Elastic(model, materialModel, x, default, 0f, rotations, 30, slots, 0, model.ElementCount);
            FemForces.Gather(model, slots, forces, 0, model.ParticleCount);
            Assert.That(inverted, Is.Zero);
            // Scale of one node's force under a unit strain: μ × (element side)²; float32 F is exact to ~1e-6.
            float scale = model.Mu * 0.1f * 0.1f;
            foreach (float3 f in forces)
                Assert.That(math.length(f), Is.LessThan(1e-4f * scale));
        }

        /// <summary>Uniform stretch: the forces of a homogeneous stress cancel at every interior node and sum to zero over the body.</summary>
        [Test]
        public void UniformStretch_ForcesCancelInside_AndSumToZero()
        {
            FemModelData data = Cube();
            FemModel model = data.AsModel();
            var x = Array.ConvertAll(data.RestPositions, p => p * new float3(1.1f, 0.95f, 1f));
            var rotations = new quaternion[model.PointCount];
            Array.Fill(rotations, quaternion.identity);
            var slots = new float3[model.SlotCount];
            var forces = new float3[model.ParticleCount];
            FemForces.Elastic(model, FemMaterialModel.CoRotational, x, default, 0f, rotations, 30, slots, 0, model.ElementCount);
            FemForces.Gather(model, slots, forces, 0, model.ParticleCount);
            float scale = (2f * model.Mu + model.Lambda) * 0.1f * 0.01f * 0.1f, total = 0f;
            float3 sum = float3.zero;
            for (int i = 0; i < forces.Length; i++)
            {
                sum += forces[i];
                float3 p = data.RestPositions[i];
                bool interior = math.all(p > 1e-4f) && math.all(p < 0.2f - 1e-4f);
                if (interior)
                    Assert.That(math.length(forces[i]), Is.LessThan(1e-3f * scale), $"interior node {i} at {p}");
                total += math.length(forces[i]);
            }
            Assert.That(total, Is.GreaterThan(scale), "the boundary carries the stress");
            Assert.That(math.length(sum), Is.LessThan(1e-5f * total));
        }

        /// <summary>
        /// The stiffness is the derivative of the forces: −K_R u equals (f(x + εu) − f(x − εu)) / 2ε at a sheared state, to the
        /// float32 cancellation: with R held the co-rotational force is linear in x, so the quotient has no truncation error (ε = 1e-3 m).
        /// </summary>
        [Test]
        public void WarpedStiffness_IsTheForceDerivative_ForSmallStrains()
        {
            FemModelData data = Cube(1);
            FemModel model = data.AsModel();
            var x = Array.ConvertAll(data.RestPositions, p => p + new float3(0.01f * p.y, 0f, 0f));
            var random = new Unity.Mathematics.Random(7);
            var u = new float3[model.ParticleCount];
            for (int i = 0; i < u.Length; i++)
                u[i] = random.NextFloat3(-1f, 1f);
            var rotations = new quaternion[model.PointCount];
            Array.Fill(rotations, quaternion.identity);
            var slots = new float3[model.SlotCount];
            // Linear co-rotational forces are K_R (x − R X) with R held: the difference quotient of the elastic force at fixed R.
            FemForces.Elastic(model, FemMaterialModel.CoRotational, x, default, 0f, rotations, 30, slots, 0, model.ElementCount);
            var k = new float3[model.ParticleCount];
            FemForces.WarpedStiffness(model, rotations, u, slots, 0, model.ElementCount);
            FemForces.Gather(model, slots, k, 0, model.ParticleCount);
            const float eps = 1e-3f;
            var plus = Array.ConvertAll(x, p => p);
            var minus = Array.ConvertAll(x, p => p);
            for (int i = 0; i < u.Length; i++)
            {
                plus[i] += eps * u[i];
                minus[i] -= eps * u[i];
            }
            var fPlus = new float3[u.Length];
            var fMinus = new float3[u.Length];
            var held = (quaternion[])rotations.Clone();
            FemForces.Elastic(model, FemMaterialModel.CoRotational, plus, default, 0f, held, 0, slots, 0, model.ElementCount);
            FemForces.Gather(model, slots, fPlus, 0, u.Length);
            held = (quaternion[])rotations.Clone();
            FemForces.Elastic(model, FemMaterialModel.CoRotational, minus, default, 0f, held, 0, slots, 0, model.ElementCount);
            FemForces.Gather(model, slots, fMinus, 0, u.Length);
            float norm = 0f, err = 0f;
            for (int i = 0; i < u.Length; i++)
            {
                float3 fd = (fPlus[i] - fMinus[i]) / (2f * eps);
                norm += math.lengthsq(k[i]);
                err += math.lengthsq(fd - k[i]);
            }
            Assert.That(math.sqrt(err), Is.LessThan(1e-2f * math.sqrt(norm)));
        }
    }
}
