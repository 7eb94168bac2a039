using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Inverted bodies recover (stability plan #4): the rotation is a proper rotation at every step
    /// (unit quaternion → det R = 1; float32 round-off of the 3×3 product keeps |det R − 1| ≤ 1e-5),
    /// the volume ratio returns to within 10% of rest within 2 s at 16 Hz, ζ = 0.2, and nothing is NaN.
    /// </summary>
    public class ShapeMatchingInversionTests
    {
        [TestCase(ShapeMatchingMode.Rigid, true)]
        [TestCase(ShapeMatchingMode.Rigid, false)]
        [TestCase(ShapeMatchingMode.Linear, true)]
        [TestCase(ShapeMatchingMode.Linear, false)]
        [TestCase(ShapeMatchingMode.Quadratic, true)]
        [TestCase(ShapeMatchingMode.Quadratic, false)]
        public void InvertedBody_RecoversWithProperRotationEveryStep(ShapeMatchingMode mode, bool mirrorWholeBody)
        {
            var model = LatticeBody.Create(new int3(4, 4, 4), 0.1f, 4, 1f, mode == ShapeMatchingMode.Quadratic);
            var p = ShapeMatchingParameters.Default;
            p.Mode = mode;
            p.Frequency = 16f;
            p.DampingRatio = 0.2f;
            p.Body.Acceleration = float3.zero;
            p.Body.SleepSpeed = 0f;
            var body = new ShapeMatchingInstance(model, p, float3.zero, quaternion.identity);
            // Mirror x: all particles (det A = −1), or only those with x < 0 folded onto the other half.
            for (int i = 0; i < body.Positions.Length; i++)
                if (mirrorWholeBody || body.Positions[i].x < 0f)
                    body.Positions[i].x = -body.Positions[i].x;
            var view = model.AsModel();
            Assert.That(BodyMeasures.VolumeRatio(body.Positions, view), mirrorWholeBody ? Is.LessThan(-0.99) : Is.LessThan(1e-6));

            for (int step = 0; step < 120; step++)
            {
                body.Step(1f / 60f);
                foreach (ClusterState c in body.Clusters)
                    Assert.That(math.determinant(new float3x3(c.Rotation)), Is.EqualTo(1f).Within(1e-5f), $"det R, step {step}");
                foreach (float3 x in body.Positions)
                    Assert.That(math.all(math.isfinite(x)), Is.True, $"finite, step {step}");
            }
            Assert.That(BodyMeasures.VolumeRatio(body.Positions, view), Is.EqualTo(1.0).Within(0.1), "volume ratio after 2 s");
        }
    }
}
