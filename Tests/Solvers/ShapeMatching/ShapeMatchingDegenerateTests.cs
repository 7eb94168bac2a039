using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Degenerate rest shapes (stability plan #5): every particle at one point, a planar cloth, a
    /// collinear rope. A_qq is singular, so linear and quadratic modes fall back, and nothing may blow
    /// up. Bound: the plan's criterion max |v| ≤ max |v₀| + g·t, plus 1e-4 m/s for float32 round-off.
    /// It is a heuristic, not a theorem (the pull can move speed between particles), kept because the
    /// failures it guards against — NaN or an Inf-sized goal from a singular A_qq — exceed it by orders
    /// of magnitude.
    /// </summary>
    public class ShapeMatchingDegenerateTests
    {
        public enum Degenerate { SinglePoint, PlanarCloth, CollinearRope }

        static ShapeMatchingModelData Build(Degenerate kind, bool quadratic)
        {
            switch (kind)
            {
                case Degenerate.SinglePoint:
                {
                    var rest = new float3[8];
                    var masses = new float[8];
                    for (int i = 0; i < 8; i++) { rest[i] = new float3(0.5f, 0.5f, 0.5f); masses[i] = 0.1f; }
                    return ShapeMatchingModelData.Create(rest, masses, new[] { 0, 8 }, new[] { 0, 1, 2, 3, 4, 5, 6, 7 }, quadratic);
                }
                case Degenerate.PlanarCloth:
                    return LatticeBody.Create(new int3(6, 1, 6), 0.1f, 3, 1f, quadratic);
                default:
                    return LatticeBody.Create(new int3(10, 1, 1), 0.1f, 4, 1f, quadratic);
            }
        }

        [Test]
        public void DegenerateCluster_StaysFiniteAndBounded(
            [Values] Degenerate kind,
            [Values(ShapeMatchingMode.Rigid, ShapeMatchingMode.Linear, ShapeMatchingMode.Quadratic)] ShapeMatchingMode mode)
        {
            var model = Build(kind, mode == ShapeMatchingMode.Quadratic);
            var p = ShapeMatchingParameters.Default;
            p.Mode = mode;
            p.Frequency = 16f;
            p.DampingRatio = 0.2f;
            p.Body.SleepSpeed = 0f;
            var body = new ShapeMatchingInstance(model, p, new float3(0f, 5f, 0f), quaternion.identity);
            var rng = new Random(7u + (uint)kind);
            float v0 = 0f;
            for (int i = 0; i < body.Velocities.Length; i++)
            {
                body.Velocities[i] = (rng.NextFloat3() - 0.5f) * 2f;
                v0 = math.max(v0, math.length(body.Velocities[i]));
            }
            const float dt = 1f / 60f;
            float g = math.length(p.Body.Acceleration);
            int fallbacks = 0;
            for (int step = 1; step <= 300; step++)
            {
                ShapeMatchingStepReport report = body.Step(dt);
                Assert.That(report.Reset, Is.False, $"step {step}");
                fallbacks += report.Fallbacks;
                float bound = v0 + g * step * dt + 1e-4f;
                foreach (float3 v in body.Velocities)
                {
                    Assert.That(math.all(math.isfinite(v)), Is.True);
                    Assert.That(math.length(v), Is.LessThanOrEqualTo(bound), $"step {step}");
                }
            }
            if (mode != ShapeMatchingMode.Rigid)
                Assert.That(fallbacks, Is.GreaterThan(0), "the degenerate cluster must report its fallback");
        }
    }
}
