using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// An undisturbed body with no damping (ζ = 0), no gravity and sleeping off stays at its rest shape for 2000 steps
    /// (67 s at 30 Hz, 17 s at 120 Hz), in every mode, at β = 0, 0.5 and 1, near the world origin and 10 km from it.
    /// Nothing drains energy, so any bias of the step accumulates instead of decaying.
    /// <para>Bound. The goals reproduce the positions only up to the round-off of the local coordinates: a short chain of
    /// float32 operations on numbers of size X (the largest local coordinate), plus the rotation's 1e-6 stopping
    /// tolerance, e ≈ 8 ulp with ulp = εX. Its constant part is a bias the pull balances at an offset e/s, where s is
    /// the smallest restoring fraction: deformations the goals follow by β are pulled back by 1 − β, at least
    /// 1 − <see cref="ShapeMatchingParameters.MaxBeta"/> = 0.01 (rigid goals follow nothing: s = 1). Undamped, the body
    /// oscillates about that offset and reaches twice it: 2e/s. Its varying part kicks the oscillation every substep:
    /// a velocity change α e / h, α ≈ (ωh)², is an amplitude ωh·e / √s in a mode of frequency ω√s; unbiased kicks add
    /// as a random walk, ≤ 5√N·ωh·e/√s after N substeps (five standard deviations). The RMS distance from the rest
    /// shape is asserted below the sum, B = 2e/s + 5√N·ωh·e/√s (at most 0.7 % of the 0.4 m body here), and the volume
    /// ratio follows from it: a residual of RMS B allows ‖F − R‖ ≤ B/σ (σ = √0.02 m, the lattice's RMS radius per
    /// axis), so |det F − 1| ≤ (1 + B/σ)³ − 1.</para>
    /// </summary>
    public class ShapeMatchingRestDriftTests
    {
        const int k_Steps = 2000;

        [Test]
        public void UndisturbedUndampedBody_StaysAtItsRestShape(
            [Values] ShapeMatchingMode mode,
            [Values(0f, 0.5f, 1f)] float beta,
            [Values(1f / 30f, 1f / 120f)] float dt,
            [Values(0f, 1e4f)] float distance)
        {
            var model = LatticeBody.Create(new int3(5, 5, 5), 0.1f, 3, 1f, mode == ShapeMatchingMode.Quadratic);
            var p = ShapeMatchingParameters.Default;
            p.Mode = mode;
            p.Beta = beta;
            p.DampingRatio = 0f;
            p.Body.Acceleration = float3.zero;
            p.Body.SleepSpeed = 0f;
            var body = new ShapeMatchingInstance(model, p, new float3(distance + 0.3f, 1f, -0.2f), quaternion.identity);
            float extent = 0f;
            foreach (float3 x in body.Positions)
                extent = math.max(extent, math.cmax(math.abs(x)));
            Assert.That(extent, Is.LessThan(2f), "local coordinates, also 10 km away");

            double e = 8.0 * 1.1920929e-7 * extent;
            // The documented cap; a larger one (or none) would leave these deformations without a restoring force.
            Assert.That(ShapeMatchingParameters.MaxBeta, Is.LessThanOrEqualTo(0.99f));
            double s = mode == ShapeMatchingMode.Rigid ? 1.0 : 1.0 - Math.Min(beta, 0.99);
            int substeps = ShapeMatchingSolver.SubstepCount(p, dt);
            double phase = p.AngularFrequency * (dt / substeps);
            double bound = 2.0 * e / s + 5.0 * Math.Sqrt((double)k_Steps * substeps) * phase * e / Math.Sqrt(s);
            double sigma = Math.Sqrt(0.02);
            double volumeBound = Math.Pow(1.0 + bound / sigma, 3) - 1.0;

            var view = model.AsModel();
            double worstShape = 0, worstVolume = 0;
            for (int step = 1; step <= k_Steps; step++)
            {
                Assert.That(body.Step(dt).Reset, Is.False, $"step {step}");
                if (step % 20 == 0)
                {
                    worstShape = Math.Max(worstShape, BodyMeasures.ShapeError(body.Positions, view));
                    worstVolume = Math.Max(worstVolume, Math.Abs(BodyMeasures.VolumeRatio(body.Positions, view) - 1.0));
                }
            }
            Assert.That(worstShape, Is.LessThanOrEqualTo(bound), "largest RMS distance from the rest shape (m)");
            Assert.That(worstVolume, Is.LessThanOrEqualTo(volumeBound), "largest |volume ratio − 1|");
        }
    }
}
