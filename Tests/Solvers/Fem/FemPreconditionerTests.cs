using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The implicit step's preconditioners (block-Jacobi, rest factor) and its warm start.</summary>
    public class FemPreconditionerTests
    {
        static readonly ElasticMaterial s_Rubber = new ElasticMaterial(1e6f, 0.45f, 1100f, 0f);
        const float H = 1f / 60f;

        static FemModelData Beam(FemElementOrder order)
        {
            TetrahedralMesh mesh = FemTestBodies.Box(4, 1, 1, new float3(0.4f, 0.1f, 0.1f));
            var pinned = new bool[mesh.NodeCount];
            for (int i = 0; i < pinned.Length; i++)
                pinned[i] = mesh.Positions[i].x == 0f;
            return FemTestBodies.Bake(mesh, s_Rubber, pinned, order);
        }

        /// <summary>q = (M + c K_R) u at the free nodes, 0 at pinned ones.</summary>
        static float3[] SystemTimes(FemModelData data, quaternion[] rotations, float3[] u, float c)
        {
            FemModel model = data.AsModel();
            var slots = new float3[model.SlotCount];
            var k = new float3[model.ParticleCount];
            FemForces.WarpedStiffness(model, rotations, u, slots, 0, model.ElementCount);
            FemForces.Gather(model, slots, k, 0, model.ParticleCount);
            var q = new float3[u.Length];
            for (int i = 0; i < u.Length; i++)
                q[i] = model.InverseMasses[i] > 0f ? model.Masses[i] * u[i] - c * k[i] : float3.zero;
            return q;
        }

        static quaternion[] Rotations(FemModelData data, quaternion rotation)
        {
            var rotations = new quaternion[data.AsModel().PointCount];
            Array.Fill(rotations, rotation);
            return rotations;
        }

        /// <summary>
        /// Each node's block-Jacobi block is the inverse of its 3×3 diagonal block of A = M + c K_R: probing A with a unit
        /// vector at one node and component reads that block's column (float32 sums of a few dozen terms: 1e-5 relative).
        /// </summary>
        [TestCase(FemElementOrder.Linear)]
        [TestCase(FemElementOrder.Quadratic)]
        public void BlockJacobi_InvertsEachNodesDiagonalBlock(FemElementOrder order)
        {
            FemModelData data = Beam(order);
            FemModel model = data.AsModel();
            int n = model.ParticleCount;
            quaternion rotation = quaternion.AxisAngle(math.normalize(new float3(0.3f, 1f, -0.5f)), 0.7f);
            quaternion[] rotations = Rotations(data, rotation);
            float c = H * H;
            var work = new float3[FemState.WorkVectors * n];
            FemBlockJacobi.Build(model, rotations, new float3[model.SlotCount], work, c);
            for (int i = 0; i < n; i++)
            {
                if (!(model.InverseMasses[i] > 0f))
                    continue;
                var block = new float3x3();
                for (int k = 0; k < 3; k++)
                {
                    var u = new float3[n];
                    u[i][k] = 1f;
                    block[k] = SystemTimes(data, rotations, u, c)[i];
                }
                // B⁻¹ B = I.
                var rhs = new float3[n];
                var z = new float3[n];
                for (int k = 0; k < 3; k++)
                {
                    rhs[i] = block[k];
                    FemBlockJacobi.Apply(work.AsSpan(5 * n, n), work.AsSpan(6 * n, n), rhs, z);
                    var unit = new float3();
                    unit[k] = 1f;
                    Assert.That(math.distance(z[i], unit), Is.LessThan(1e-4f), $"node {i} column {k}");
                }
            }
        }

        /// <summary>
        /// The rest factor is the exact inverse of the rest system, and of a rigidly rotated one once warped by the node
        /// rotations: P⁻¹ A u = u (float32 triangular solves of a few hundred rows, condition ~1e4: 1e-3 relative).
        /// </summary>
        [TestCase(FemElementOrder.Linear)]
        [TestCase(FemElementOrder.Quadratic)]
        public void RestFactor_InvertsTheSystem_OfARigidlyRotatedBody(FemElementOrder order)
        {
            FemModelData data = Beam(order);
            float c = H * H;
            Assert.That(data.BuildRestFactor(H, 0f), Is.True);
            FemModel model = data.AsModel();
            int n = model.ParticleCount;
            foreach (quaternion rotation in new[] { quaternion.identity, quaternion.AxisAngle(math.normalize(new float3(1f, 2f, 0.5f)), 1.3f) })
            {
                quaternion[] rotations = Rotations(data, rotation);
                var random = new Unity.Mathematics.Random(3);
                var u = new float3[n];
                for (int i = 0; i < n; i++)
                    u[i] = model.InverseMasses[i] > 0f ? random.NextFloat3(-1f, 1f) : float3.zero;
                float3[] au = SystemTimes(data, rotations, u, c);
                var nodeRotations = new float3[n];
                FemRestFactor.NodeRotations(model, rotations, nodeRotations);
                var z = new float3[n];
                FemRestFactor.Apply(model, nodeRotations, au, z, new float[3 * n]);
                double err = 0, norm = 0;
                for (int i = 0; i < n; i++)
                {
                    err += math.distancesq(z[i], u[i]);
                    norm += math.lengthsq(u[i]);
                }
                Assert.That(Math.Sqrt(err / norm), Is.LessThan(1e-3), $"rotation {rotation}");
            }
        }

        /// <summary>
        /// With the rest factor a cantilever's 1/60 s substep converges in a handful of iterations where block-Jacobi takes
        /// dozens, and both reach the same velocities (to the tolerance times the condition number, ~1e-3).
        /// </summary>
        [TestCase(FemElementOrder.Linear)]
        [TestCase(FemElementOrder.Quadratic)]
        public void RestFactor_TakesFewerIterations_ForTheSameSolution(FemElementOrder order)
        {
            FemParameters p = FemParameters.Default;
            p.Body.SleepSpeed = 0f;
            p.Body.Substeps = 1;
            p.CgIterations = 2000;
            p.CgTolerance = 1e-6f;
            var plain = new FemTestBody(Beam(order), p);
            FemModelData factored = Beam(order);
            factored.BuildRestFactor(H, FemSolver.DampingCoefficient(factored.AsModel(), p));
            var fast = new FemTestBody(factored, p);
            int plainIterations = 0, fastIterations = 0;
            for (int step = 0; step < 30; step++)
            {
                plainIterations += plain.Step(H).TotalCgIterations;
                fastIterations += fast.Step(H).TotalCgIterations;
            }
            TestContext.WriteLine($"{order}: CG iterations over 30 steps, block-Jacobi {plainIterations}, rest factor {fastIterations}");
            Assert.That(fastIterations, Is.LessThan(plainIterations / 4));
            double err = 0, norm = 0;
            for (int i = 0; i < plain.Positions.Length; i++)
            {
                err += math.distancesq(plain.Velocities[i], fast.Velocities[i]);
                norm += math.lengthsq(plain.Velocities[i]);
            }
            Assert.That(Math.Sqrt(err / norm), Is.LessThan(1e-2));
        }

        /// <summary>A warm start at the solution ends the solve at once; a cold one iterates (the warm start is read, not ignored).</summary>
        [Test]
        public void WarmStart_AtTheSolution_TakesNoIterations()
        {
            FemModelData data = Beam(FemElementOrder.Quadratic);
            data.BuildRestFactor(H, 0f);
            FemModel model = data.AsModel();
            int n = model.ParticleCount;
            var x = Array.ConvertAll(data.RestPositions, r => r + new float3(0f, -0.05f * r.x * r.x, 0f));
            var v0 = new float3[n];
            for (int i = 0; i < n; i++)
                v0[i] = model.InverseMasses[i] > 0f ? new float3(0f, -0.1f * data.RestPositions[i].x, 0f) : float3.zero;
            float3[] Solve(float3[] warm, out int iterations)
            {
                FemModel m = data.AsModel();
                var v = (float3[])v0.Clone();
                iterations = FemImplicitEuler.Solve(m, FemMaterialModel.CoRotational, x, v, Rotations(data, quaternion.identity), default, 20,
                    new float3[m.SlotCount], new float3[n], new float3[FemState.WorkVectors * n], warm, default, H, 0f, 1, 2000, 1e-6f, out bool converged,
                    out float residual, out _);
                Assert.That(converged);
                Assert.That(residual, Is.LessThanOrEqualTo(1e-6f));
                return v;
            }
            var warmStart = new float3[n];
            float3[] first = Solve(warmStart, out int cold);
            float3[] second = Solve(warmStart, out int warm);
            Assert.That(cold, Is.GreaterThan(0));
            Assert.That(warm, Is.LessThanOrEqualTo(1));
            for (int i = 0; i < n; i++)
                Assert.That(math.distance(first[i], second[i]), Is.LessThan(1e-4f * (1f + math.length(first[i]))));
        }
    }
}
