using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Quadratic mode (stability plan #7). Scaling q by the cluster's RMS radius makes Ã_qq the same
    /// matrix at every size, so its condition must be size-independent and ≤ 1e3 for a 5³ lattice
    /// (the plan measured 11). Goals are compared with a float64 solve without scaling: the float32
    /// path multiplies O(1) numbers through a 9×9 inverse of condition κ, so its relative error is
    /// ≲ κ·ε ≈ 11 × 1.2e-7 plus the rotation's 1e-6 stop — the plan's 1e-4 (relative to the
    /// cluster size) leaves a wide margin. A planar cluster must fall back to linear (and then rigid).
    /// </summary>
    public class QuadraticConditioningTests
    {
        [TestCase(0.01f)]
        [TestCase(0.1f)]
        [TestCase(1f)]
        [TestCase(10f)]
        public void Quadratic_ConditionIsSizeIndependentAndGoalsMatchDouble(float size)
        {
            var model = LatticeBody.Create(new int3(5, 5, 5), size / 4f, 5, 1f, buildQuadratic: true);
            var view = model.AsModel();
            var blocks = new float3x3[QuadraticShapeMatching.BlocksPerCluster];
            bool valid = QuadraticShapeMatching.ComputeRestInverse(view.RestPositions, view.ClusterParticles, view.ClusterWeights,
                model.ClusterRest[0].RestCenter, float3x3.identity, model.ClusterRest[0].LengthScale, blocks, out double condition, out _, out _);
            Assert.That(valid, Is.True);
            Assert.That(model.ClusterRest[0].QuadraticValid, Is.True);
            Assert.That(condition, Is.LessThanOrEqualTo(1e3), "cond(Ã_qq) after scaling");

            // A bent, stretched (volume × 1.188, so the volume term acts), twisted and rotated copy of the rest shape, plus
            // noise the quadratic fit cannot follow.
            var rng = new Unity.Mathematics.Random(5u);
            var x = new float3[model.ParticleCount];
            quaternion rot = quaternion.AxisAngle(math.normalize(new float3(1f, 2f, 3f)), 0.7f);
            for (int i = 0; i < x.Length; i++)
            {
                float3 q = model.RestPositions[i] / size;
                float3 bent = new float3(1.2f, 0.9f, 1.1f) * q + new float3(0.3f * q.y * q.y, 0.2f * q.x * q.z, -0.25f * q.x * q.x)
                              + (rng.NextFloat3() - 0.5f) * 0.02f;
                x[i] = new float3(3f, -1f, 2f) * size + size * math.mul(rot, bent);
            }
            foreach (float beta in new[] { 0f, 0.5f, 1f })
            {
                float3[] goals = SolverGoals(model, x, ShapeMatchingMode.Quadratic, beta, out int fallbacks);
                Assert.That(fallbacks, Is.EqualTo(0));
                double[,] reference = QuadraticGoalsDouble.Goals(model.RestPositions, x, model.ClusterWeights, beta);
                double worst = 0;
                for (int i = 0; i < goals.Length; i++)
                for (int a = 0; a < 3; a++)
                    worst = Math.Max(worst, Math.Abs(goals[i][a] - reference[i, a]) / size);
                Assert.That(worst, Is.LessThanOrEqualTo(1e-4), $"β = {beta}, relative goal error");
            }
        }

        [Test]
        public void Quadratic_FitsAQuadraticDeformationExactly()
        {
            var model = LatticeBody.Create(new int3(4, 4, 4), 0.1f, 4, 1f, buildQuadratic: true);
            var x = new float3[model.ParticleCount];
            for (int i = 0; i < x.Length; i++)
            {
                float3 q = model.RestPositions[i];
                x[i] = q + new float3(2f * q.y * q.y, 0f, 0f); // a bend, no rotation
            }
            float3[] quadratic = SolverGoals(model, x, ShapeMatchingMode.Quadratic, 1f, out _);
            float3[] linear = SolverGoals(model, x, ShapeMatchingMode.Linear, 1f, out _);
            double quadraticError = 0, linearError = 0;
            for (int i = 0; i < x.Length; i++)
            {
                quadraticError = Math.Max(quadraticError, math.length(quadratic[i] - x[i]));
                linearError = Math.Max(linearError, math.length(linear[i] - x[i]));
            }
            // The bend lies in the quadratic span: goals reproduce it to float32 round-off of 0.1 m
            // coordinates through a κ ≈ 10 solve (≲ 1e-6 m). The linear mode cannot (bend amplitude 0.045 m).
            Assert.That(quadraticError, Is.LessThanOrEqualTo(1e-5));
            Assert.That(linearError, Is.GreaterThan(1e-2));
        }

        [Test]
        public void Quadratic_PlanarClusterFallsBackWithoutNaN()
        {
            var model = LatticeBody.Create(new int3(5, 1, 5), 0.1f, 5, 1f, buildQuadratic: true);
            Assert.That(model.ClusterRest[0].QuadraticValid, Is.False);
            Assert.That(model.ClusterRest[0].LinearValid, Is.False);
            var x = (float3[])model.RestPositions.Clone();
            for (int i = 0; i < x.Length; i++)
                x[i] += new float3(0f, 0.01f * x[i].x, 0f);
            float3[] goals = SolverGoals(model, x, ShapeMatchingMode.Quadratic, 0.5f, out int fallbacks);
            Assert.That(fallbacks, Is.EqualTo(1));
            foreach (float3 g in goals)
                Assert.That(math.all(math.isfinite(g)), Is.True);
        }

        static float3[] SolverGoals(ShapeMatchingModelData model, float3[] x, ShapeMatchingMode mode, float beta, out int fallbacks)
        {
            int n = model.ParticleCount;
            var clusters = new ClusterState[model.ClusterCount];
            for (int c = 0; c < clusters.Length; c++)
                clusters[c] = new ClusterState { Rotation = quaternion.identity, PlasticDeformation = float3x3.identity, Rest = model.ClusterRest[c] };
            var goals = new float3[n];
            var state = new ShapeMatchingState(new float3[n], new float3[n], clusters, Array.Empty<float3x3>(), (float3[])x.Clone(),
                goals, new float3[n]);
            var p = ShapeMatchingParameters.Default;
            p.Mode = mode;
            p.Beta = beta;
            fallbacks = ClusterGoals.Compute(model.AsModel(), p, state, x, 0f).Fallbacks;
            return goals;
        }
    }
}
