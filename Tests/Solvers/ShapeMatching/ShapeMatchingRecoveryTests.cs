using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Rest and recovery of the default (jelly) body.</summary>
    public class ShapeMatchingRecoveryTests
    {
        static ShapeMatchingParameters Weightless(ShapeMatchingMode mode)
        {
            var p = ShapeMatchingParameters.Default;
            p.Mode = mode;
            p.Acceleration = float3.zero;
            return p;
        }

        /// <summary>
        /// A body placed at its rest shape with no force and no velocity stays there. Recomputing the
        /// goals (centre, A_pq, R·q) reproduces the positions only to the round-off of the coordinates,
        /// n = ulp(max |x|); each substep's pull kicks the particles by that much, and a kick decays by
        /// √(1 − α_sub) per substep, so even kicks that all add up stay below n / (1 − √(1 − α_sub)) ≈
        /// 2n/α_sub. Translation and spin have no restoring pull, but the pull is made free of momentum
        /// and angular momentum, so they do not drift. Once asleep the body is frozen bit for bit.
        /// </summary>
        [Test]
        public void UndisturbedBody_StaysAtRest([Values] ShapeMatchingMode mode)
        {
            var model = LatticeBody.Create(new int3(5, 5, 5), 0.1f, 3, 1f, mode == ShapeMatchingMode.Quadratic);
            var body = new ShapeMatchingInstance(model, Weightless(mode), new float3(0.3f, 1f, -0.2f), quaternion.identity);
            var start = (float3[])body.Positions.Clone();
            float worst = 0f;
            for (int step = 0; step < 1000; step++)
            {
                body.Step(1f / 60f);
                for (int i = 0; i < start.Length; i++)
                    worst = math.max(worst, math.distance(start[i], body.Positions[i]));
            }
            float extent = 0f;
            foreach (float3 x in start)
                extent = math.max(extent, math.cmax(math.abs(x)));
            float ulp = extent * 1.1920929e-7f; // ≥ the spacing of floats near the largest coordinate
            var p = body.Parameters;
            int substeps = ShapeMatchingSolver.SubstepCount(p, 1f / 60f);
            float alphaSub = OscillatorDiscretization.Compute(p.AngularFrequency, p.DampingRatio, 1f / 60f / substeps).Pull;
            Assert.That(worst, Is.LessThanOrEqualTo(2f * ulp / alphaSub));
            Assert.That(body.Status.Asleep, Is.True, "a body at rest falls asleep");
            var frozen = (float3[])body.Positions.Clone();
            body.Step(1f / 60f);
            Assert.That(body.Positions, Is.EqualTo(frozen));
        }

        /// <summary>
        /// Squashed to half its height (volume kept), released without gravity, the default jelly body
        /// (linear, α = 0.2 per 1/60 s step, β = 0.5, damping 1/s) must be back within 1% of its size
        /// (RMS distance from its best-fit rest placement) within 3 s. Stated requirement: the goal
        /// pull alone removes (1 − α) of the deviation per step, 1 − 0.8^180 ≈ 1; the damping bounds the
        /// wobble the pull's velocity causes.
        /// </summary>
        [Test]
        public void SquashedBody_RecoversRestShapeWithin3Seconds([Values] ShapeMatchingMode mode, [Values(5, 3)] int clusterSize)
        {
            var model = LatticeBody.Create(new int3(5, 5, 5), 0.1f, clusterSize, 1f, mode == ShapeMatchingMode.Quadratic);
            var body = new ShapeMatchingInstance(model, Weightless(mode), float3.zero, quaternion.identity);
            float s = math.sqrt(2f);
            for (int i = 0; i < body.Positions.Length; i++)
                body.Positions[i] *= new float3(s, 0.5f, s);
            var view = model.AsModel();
            double size = BodyMeasures.RestSize(view);
            Assert.That(BodyMeasures.ShapeError(body.Positions, view) / size, Is.GreaterThan(0.1));
            for (int step = 0; step < 180; step++)
                Assert.That(body.Step(1f / 60f).Reset, Is.False);
            Assert.That(BodyMeasures.ShapeError(body.Positions, view) / size, Is.LessThanOrEqualTo(0.01));
        }
    }
}
