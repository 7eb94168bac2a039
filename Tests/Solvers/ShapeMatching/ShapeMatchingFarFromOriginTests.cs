using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// A body far from the world origin behaves like one at the origin. Its particles are simulated relative to
    /// <see cref="ParticleBodyStatus.Origin"/>, whole metres near the body, and colliders are seen from there; a whole
    /// metre is exact in float32, so a body placed d metres away on a floor translated by exactly d metres computes
    /// with the very same numbers as its twin at the origin.
    /// </summary>
    public class ShapeMatchingFarFromOriginTests
    {
        static bool SameBits(float3 a, float3 b) =>
            math.asuint(a.x) == math.asuint(b.x) && math.asuint(a.y) == math.asuint(b.y) && math.asuint(a.z) == math.asuint(b.z);

        /// <summary>
        /// A Jelly body dropped 2 cm onto a floor at x = 1 km, 10 km and 100 km (where float32 world coordinates are
        /// 6e-5, 1e-3 and 8e-3 m apart) and its twin at the origin: after every step the local positions and velocities
        /// are bit-identical, the origin is the whole-metre offset and the world centre is that offset plus the twin's.
        /// And it is at rest: from 5 s to 10 s no particle moves faster than 16 ulp of its 0.5 m local coordinates per
        /// substep (16 × 6e-8 m × 240 /s ≈ 2.3e-4 m/s): the contacts and goals reproduce a resting body to a few ulp, and
        /// a particle moved by n ulp in a substep has a speed of n ulp / h.
        /// </summary>
        [Test]
        public void RestingBody_FarFromOrigin_IsBitIdenticalToOneAtTheOrigin([Values(1e3f, 1e4f, 1e5f)] float distance)
        {
            var model = LatticeBody.Create(new int3(5, 5, 5), 0.1f, 3, 1f);
            var p = ShapeMatchingMaterial.Jelly.ApplyTo(ShapeMatchingParameters.Default);
            p.Body.SleepSpeed = 0f;
            var offset = new float3(distance, 0f, 0f);
            // 0.25 and 0.125 m are exact at 100 km too (float32 spacing there: 2⁻⁷ m), so both bodies start at the same local position.
            var start = new float3(0.25f, 0.2f + p.Body.ParticleRadius + 0.02f, -0.125f);
            var near = new ShapeMatchingInstance(model, p, start, quaternion.identity);
            var far = new ShapeMatchingInstance(model, p, start + offset, quaternion.identity);
            Assert.That(far.Status.Origin, Is.EqualTo(offset));
            var nearFloor = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            var farFloor = new[] { ColliderShape.Plane(offset, new float3(0f, 1f, 0f)) };
            const float dt = 1f / 60f;
            float worstSpeed = 0f;
            for (int step = 1; step <= 600; step++)
            {
                near.Step(dt, nearFloor);
                far.Step(dt, farFloor);
                for (int i = 0; i < near.Positions.Length; i++)
                {
                    Assert.That(SameBits(far.Positions[i], near.Positions[i]), Is.True, $"step {step}, particle {i}: position");
                    Assert.That(SameBits(far.Velocities[i], near.Velocities[i]), Is.True, $"step {step}, particle {i}: velocity");
                    if (step > 300)
                        worstSpeed = math.max(worstSpeed, math.length(far.Velocities[i]));
                }
            }
            Assert.That(far.Status.Origin, Is.EqualTo(offset));
            Assert.That(far.Status.Center, Is.EqualTo(offset + near.Status.Center));
            int substeps = ShapeMatchingSolver.SubstepCount(p, dt);
            float ulp = 0.5f * 1.1920929e-7f; // float32 spacing for |x| in [0.5, 1) m
            Assert.That(worstSpeed, Is.LessThanOrEqualTo(16f * ulp * substeps / dt), "largest particle speed from 5 s to 10 s (m/s)");
        }

        /// <summary>
        /// A body sliding at 4 m/s on an icy floor (μ = 0) across the rebase distance: starting at x = 60 m, its origin
        /// moves to whole metres once its centre passes 64 m. Its twin slides the same path 64 m to the left, from
        /// x = −4 m, and is never rebased. Rebasing shifts positions by whole metres (exact: Sterbenz) and never touches
        /// velocities, so there is no jump: at every step each particle's velocity differs from its twin's only by what
        /// the different rounding of the coordinates before the rebase (≤ ulp(64 m) = 7.6e-6 m a substep) does to the
        /// pull, at most ω times the accumulated position difference. With μ = 0 and a vertical floor normal the
        /// horizontal motion is untouched by contacts, so the centres end at the same place up to that accumulated
        /// rounding, N × ulp(64)/2 over the N = 240 substeps before the rebase (≤ 9.2e-4 m).
        /// </summary>
        [Test]
        public void SlidingBody_CrossesTheRebaseDistanceWithoutAJump()
        {
            var model = LatticeBody.Create(new int3(5, 5, 5), 0.1f, 3, 1f);
            var p = ShapeMatchingMaterial.Jelly.ApplyTo(ShapeMatchingParameters.Default);
            p.Body.SleepSpeed = 0f;
            p.Body.Friction = 0f;
            var floor = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            var velocity = new float3(4f, 0f, 0f);
            float height = 0.2f + p.Body.ParticleRadius;
            var far = new ShapeMatchingInstance(model, p, new float3(60f, height, 0f), quaternion.identity, velocity);
            var near = new ShapeMatchingInstance(model, p, new float3(-4f, height, 0f), quaternion.identity, velocity);
            Assert.That(far.Status.Origin, Is.EqualTo(float3.zero), "60 m is within the rebase distance");
            const float dt = 1f / 60f;
            int substeps = ShapeMatchingSolver.SubstepCount(p, dt);
            const float ulp64 = 64f * 1.1920929e-7f;
            int rebaseStep = -1;
            for (int step = 0; step < 120; step++)
            {
                far.Step(dt, floor);
                near.Step(dt, floor);
                if (rebaseStep < 0 && math.any(far.Status.Origin != float3.zero))
                    rebaseStep = step;
                int roundedSubsteps = (rebaseStep < 0 ? step + 1 : rebaseStep + 1) * substeps;
                float positionBound = roundedSubsteps * 0.5f * ulp64;
                float velocityBound = p.AngularFrequency * positionBound;
                for (int i = 0; i < far.Velocities.Length; i++)
                    Assert.That(math.length(far.Velocities[i] - near.Velocities[i]), Is.LessThanOrEqualTo(velocityBound),
                        $"step {step}, particle {i}");
            }
            Assert.That(rebaseStep, Is.GreaterThanOrEqualTo(0), "the body was rebased");
            Assert.That(far.Status.Origin.x, Is.EqualTo(math.round(far.Status.Origin.x)), "whole metres");
            Assert.That(far.Status.Origin.x, Is.GreaterThanOrEqualTo(ShapeMatchingSolver.RebaseDistance));
            float3 expected = near.Status.Center + new float3(64f, 0f, 0f);
            float bound = (rebaseStep + 1) * substeps * 0.5f * ulp64;
            Assert.That(math.length(far.Status.Center - expected), Is.LessThanOrEqualTo(bound), "end position (m)");
            Assert.That(far.Status.Center.x, Is.EqualTo(60f + 4f * 2f).Within(0.01f), "it slid 8 m");
        }
    }
}
