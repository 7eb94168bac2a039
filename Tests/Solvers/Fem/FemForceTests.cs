using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using static SoftBodyDynamics.Tests.Solvers.DoubleMatrix3;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The element forces of both constitutive models are −∂E/∂x, vanish at rest and under rotations, and pass the patch test.</summary>
    public class FemForceTests
    {
        const float Mu = 3.4e3f, Lambda = 3.1e4f;

        static float3[] Forces(FemMaterialModel model, TetElement element, float3[] x, out float3x3 f)
        {
            f = FemElasticity.DeformationGradient(x[0], x[1], x[2], x[3], element.InverseRestShape);
            float3x3 p;
            if (model == FemMaterialModel.CoRotational)
            {
                quaternion q = quaternion.identity;
                RotationExtraction.Extract(f, ref q, 100, 1e-7f);
                p = FemElasticity.CoRotationalStress(f, new float3x3(q), Mu, Lambda);
            }
            else
            {
                p = FemElasticity.NeoHookeanStress(f, Mu, FemElasticity.NeoHookeanLambda(Mu, Lambda));
            }
            var slots = new float3[4];
            FemElasticity.NodalForces(p, element, slots);
            return slots;
        }

        // ---- float64 reference energy

        static double[,] Edges(double[][] x)
        {
            var d = new double[3, 3];
            for (int c = 0; c < 3; c++)
                for (int r = 0; r < 3; r++)
                    d[r, c] = x[c + 1][r] - x[0][r];
            return d;
        }

        /// <summary>V Ψ(F) in double; co-rotational with the polar rotation by Higham's iteration R ← ½(R + R⁻ᵀ).</summary>
        static double Energy(FemMaterialModel model, double[][] x, double[,] dmInv, double volume)
        {
            double[,] f = Mul(Edges(x), dmInv);
            double mu = Mu, lambda = Lambda;
            if (model == FemMaterialModel.CoRotational)
            {
                var r = (double[,])f.Clone();
                for (int it = 0; it < 60; it++)
                {
                    double[,] rit = InverseTranspose(r);
                    for (int i = 0; i < 3; i++)
                        for (int j = 0; j < 3; j++)
                            r[i, j] = 0.5 * (r[i, j] + rit[i, j]);
                }
                double fr = 0, tr = 0;
                for (int i = 0; i < 3; i++)
                    for (int j = 0; j < 3; j++)
                    {
                        fr += (f[i, j] - r[i, j]) * (f[i, j] - r[i, j]);
                        tr += r[i, j] * f[i, j];
                    }
                return volume * (mu * fr + 0.5 * lambda * (tr - 3) * (tr - 3));
            }
            double ls = lambda + mu, alpha = 1 + mu / ls, ic = 0;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    ic += f[i, j] * f[i, j];
            double jm = Det(f) - alpha;
            return volume * (0.5 * mu * (ic - 3) + 0.5 * ls * jm * jm);
        }

        [Test]
        public void Forces_AreMinusEnergyGradient([Values] FemMaterialModel model, [Values(1, 2, 3)] int seed) =>
            CheckGradient(model, seed, false);

        /// <summary>The co-rotational energy uses the polar rotation, defined for det F &gt; 0 only; its inverted forces are checked by the recovery tests.</summary>
        [Test]
        public void NeoHookeanForces_AreMinusEnergyGradient_WhenInverted([Values(1, 2, 3)] int seed) =>
            CheckGradient(FemMaterialModel.NeoHookean, seed, true);

        static void CheckGradient(FemMaterialModel model, int seed, bool inverted)
        {
            var random = new System.Random(seed);
            float R() => (float)(random.NextDouble() * 2 - 1);
            var rest = new[] { new float3(0f, 0f, 0f), new float3(0.1f, 0.01f, 0f), new float3(0.02f, 0.09f, 0.01f), new float3(0.01f, 0.02f, 0.11f) };
            var dm = new float3x3(rest[1] - rest[0], rest[2] - rest[0], rest[3] - rest[0]);
            var element = new TetElement { Nodes = new int4(0, 1, 2, 3), InverseRestShape = math.inverse(dm), RestVolume = math.determinant(dm) / 6f };
            // Deformation: a random F with singular values near 1 (±30 %), mirrored for the inverted case, plus a translation.
            var f0 = new float3x3(1f + 0.3f * R(), 0.3f * R(), 0.3f * R(), 0.3f * R(), 1f + 0.3f * R(), 0.3f * R(), 0.3f * R(), 0.3f * R(), 1f + 0.3f * R());
            if (inverted)
                f0.c0 = -f0.c0;
            var x = new float3[4];
            for (int i = 0; i < 4; i++)
                x[i] = math.mul(f0, rest[i]) + new float3(0.3f, -0.2f, 0.1f);
            float3[] forces = Forces(model, element, x, out float3x3 f);
            Assert.That(math.determinant(f) > 0f, Is.EqualTo(!inverted));

            double[][] xd = Array.ConvertAll(x, p => new double[] { p.x, p.y, p.z });
            double[][] restD = Array.ConvertAll(rest, p => new double[] { p.x, p.y, p.z });
            double[,] dmD = Edges(restD);
            double[,] dmInvD = Inverse(dmD);
            double volume = Det(dmD) / 6;
            // Central difference with δ = 1e-6 m (1e-5 of the size): truncation (δ/L)² E''' ~ 1e-10 relative, far below
            // the float32 force's round-off (~1e-6 of the largest force: a dozen float operations on F ~ 1).
            const double delta = 1e-6;
            double largest = 0;
            foreach (float3 fi in forces)
                largest = Math.Max(largest, math.length(fi));
            double worst = 0;
            for (int node = 0; node < 4; node++)
                for (int a = 0; a < 3; a++)
                {
                    double keep = xd[node][a];
                    xd[node][a] = keep + delta;
                    double ePlus = Energy(model, xd, dmInvD, volume);
                    xd[node][a] = keep - delta;
                    double eMinus = Energy(model, xd, dmInvD, volume);
                    xd[node][a] = keep;
                    double reference = -(ePlus - eMinus) / (2 * delta);
                    worst = Math.Max(worst, Math.Abs(forces[node][a] - reference));
                }
            TestContext.WriteLine($"largest force {largest:G4} N, worst difference {worst:G3} N ({worst / largest:G3} relative)");
            // Measured ≤ 6e-7 relative; the float positions are rounded to 1e-7 of |x| ~ 0.4 m (4e-7 of an edge of 0.1 m),
            // which moves F by ~1e-6 relative at worst: 5e-6 of the largest force.
            Assert.That(worst, Is.LessThan(5e-6 * largest));
        }

        static float3[] BodyForces(FemModelData data, FemMaterialModel model, float3[] x)
        {
            FemModel m = data.AsModel();
            var rotations = new quaternion[m.ElementCount];
            Array.Fill(rotations, quaternion.identity);
            var slots = new float3[4 * m.ElementCount];
            var result = new float3[m.ParticleCount];
            FemForces.Elastic(m, model, x, default, 0f, rotations, 50, slots, 0, m.ElementCount);
            FemForces.Gather(m, slots, result, 0, m.ParticleCount);
            return result;
        }

        [Test]
        public void Forces_ZeroAtRestAndUnderRotation([Values] FemMaterialModel model)
        {
            FemModelData data = FemTestBodies.Bake(FemTestBodies.Box(2, 2, 2, new float3(0.2f)), new ElasticMaterial(1e4f, 0.45f, 1000f, 0f));
            const float h = 0.1f;
            // Round-off bound: positions rounded to ε|x| (|x| ≤ 0.4 m from the origin after the shift) give a strain of
            // ~ε·|x|/h ≈ 5e-7 per element; the force is ~ (λ + 2μ) strain h² summed over ≤ 24 elements: ~1.2e-5 (λ + 2μ) h².
            // Measured ≤ 7e-6 (λ + 2μ) h².
            float bound = 3e-5f * (data.Lambda + 2f * data.Mu) * h * h;
            var random = new System.Random(7);
            for (int trial = 0; trial < 4; trial++)
            {
                quaternion q = trial == 0 ? quaternion.identity
                    : math.normalize(new quaternion((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, (float)random.NextDouble()));
                var rot = new float3x3(q);
                var x = new float3[data.RestPositions.Length];
                for (int i = 0; i < x.Length; i++)
                    x[i] = math.mul(rot, data.RestPositions[i]) + new float3(0.1f, 0.2f, -0.05f);
                float3[] f = BodyForces(data, model, x);
                float worst = 0f;
                foreach (float3 fi in f)
                    worst = math.max(worst, math.length(fi));
                TestContext.WriteLine($"trial {trial}: largest |f| {worst:G3} N (bound {bound:G3} N)");
                Assert.That(worst, Is.LessThan(bound));
            }
        }

        [Test]
        public void PatchTest_UniformStretch_SameStressEverywhere_InteriorForceZero([Values] FemMaterialModel model)
        {
            FemModelData data = FemTestBodies.Bake(FemTestBodies.Box(3, 3, 3, new float3(0.3f)), new ElasticMaterial(1e4f, 0.45f, 1000f, 0f));
            var f0 = new float3x3(1.1f, 0.05f, 0f, -0.02f, 0.95f, 0.03f, 0.01f, 0f, 1.04f);
            var x = new float3[data.RestPositions.Length];
            for (int i = 0; i < x.Length; i++)
                x[i] = math.mul(f0, data.RestPositions[i]);
            foreach (TetElement t in data.Elements)
            {
                float3x3 f = FemElasticity.DeformationGradient(x[t.Nodes.x], x[t.Nodes.y], x[t.Nodes.z], x[t.Nodes.w], t.InverseRestShape);
                // F of every element equals F₀ to the rounding of the positions (~1e-7 relative, amplified by |x|/h = 3).
                Assert.That(Matrix3.MaxAbs(f - f0), Is.LessThan(2e-6f));
            }
            float3[] forces = BodyForces(data, model, x);
            float largest = 0f, interior = 0f;
            for (int i = 0; i < x.Length; i++)
            {
                float3 r = data.RestPositions[i] / 0.1f;
                bool inside = math.all(r > 0.5f) && math.all(r < 2.5f);
                largest = math.max(largest, math.length(forces[i]));
                if (inside)
                    interior = math.max(interior, math.length(forces[i]));
            }
            TestContext.WriteLine($"largest boundary force {largest:G4} N, largest interior {interior:G3} N");
            Assert.That(largest, Is.GreaterThan(1f));
            // The interior sum cancels 24 element forces of size ~largest: round-off ~1e-6 of it.
            Assert.That(interior, Is.LessThan(1e-4f * largest));
        }
    }
}
