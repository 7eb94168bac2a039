using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Collisions. Contacts are resolved last in every substep, so at the end of a step every particle
    /// is outside every collider up to the round-off of one projection (a few ulp of O(1) m coordinates):
    /// 1e-5 m is asserted.
    /// </summary>
    public class ShapeMatchingContactTests
    {
        const float k_Tolerance = 1e-5f;

        static ShapeMatchingInstance Cube(float3 position, float3 velocity, ShapeMatchingMode mode = ShapeMatchingMode.Linear)
        {
            var model = LatticeBody.Create(new int3(5, 5, 5), 0.1f, 3, 1f);
            var p = ShapeMatchingParameters.Default;
            p.Mode = mode;
            return new ShapeMatchingInstance(model, p, position, quaternion.AxisAngle(math.normalize(new float3(1f, 0f, 1f)), 0.4f),
                velocity);
        }

        /// <summary>
        /// Dropped from the sample's heights (≤ 5 m, 10 m/s at impact) and thrown down at 30 m/s, a body
        /// never ends a step inside the floor: the plane is a half-space, so no speed can skip it.
        /// </summary>
        [TestCase(5f, 0f)]
        [TestCase(2f, -30f)]
        public void DroppedBody_NeverTunnelsThroughFloor(float height, float downwardSpeed)
        {
            ShapeMatchingInstance body = Cube(new float3(0f, height, 0f), new float3(0f, downwardSpeed, 0f));
            var floor = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            float radius = body.Parameters.ParticleRadius;
            for (int step = 0; step < 240; step++)
            {
                body.Step(1f / 60f, floor);
                foreach (float3 x in body.Positions)
                    Assert.That(x.y, Is.GreaterThanOrEqualTo(radius - k_Tolerance), $"step {step}");
            }
        }

        /// <summary>
        /// A 5 cm thick step hit at 30 m/s: 12.5 cm per substep, more than the inflated box is thick, so
        /// only the swept test keeps the particles on top.
        /// </summary>
        [Test]
        public void FastBody_NeverTunnelsThroughThinStep()
        {
            ShapeMatchingInstance body = Cube(new float3(0f, 1.5f, 0f), new float3(0f, -30f, 0f));
            var step = new[] { ColliderShape.Box(new float3(0f, 0.5f, 0f), quaternion.identity, new float3(3f, 0.025f, 3f)) };
            float top = 0.525f + body.Parameters.ParticleRadius;
            for (int i = 0; i < 120; i++)
            {
                body.Step(1f / 60f, step);
                foreach (float3 x in body.Positions)
                    Assert.That(x.y, Is.GreaterThanOrEqualTo(top - k_Tolerance), $"step {i}");
            }
        }

        [Test]
        public void Particles_ArePushedOutOfEveryPrimitive()
        {
            float r = 0.02f;
            var shapes = new[]
            {
                ColliderShape.Sphere(new float3(0f, 0f, 0f), 0.5f),
                ColliderShape.Capsule(new float3(-0.5f, 0f, 0f), new float3(0.5f, 0f, 0f), 0.3f),
                ColliderShape.Box(float3.zero, quaternion.AxisAngle(new float3(0f, 0f, 1f), 0.5f), new float3(0.4f, 0.2f, 0.3f)),
                ColliderShape.Plane(new float3(0f, -0.1f, 0f), new float3(0f, 1f, 1f)),
            };
            var rng = new Random(3u);
            foreach (ColliderShape shape in shapes)
            {
                for (int k = 0; k < 200; k++)
                {
                    float3 x = (rng.NextFloat3() - 0.5f) * 1.2f;
                    if (!ParticleCollision.Penetration(shape, x, r, out float3 n, out float depth))
                        continue;
                    Assert.That(math.length(n), Is.EqualTo(1f).Within(1e-5f));
                    Assert.That(depth, Is.GreaterThan(0f));
                    float3 pushed = x + depth * n;
                    Assert.That(ParticleCollision.Penetration(shape, pushed, r, out _, out float after) ? after : 0f,
                        Is.LessThanOrEqualTo(k_Tolerance), $"{shape.Type} at {x}");
                }
            }
        }

        /// <summary>
        /// On a 30° slope (tan 30° ≈ 0.58) a body with μ = 1 holds, one with μ = 0 slides. Position-based
        /// friction cancels tangential motion up to μ × the penetration gravity causes each substep, so
        /// the static limit is exactly tan θ &lt; μ. A stiff body (rigid goals, α = 1) keeps the test about
        /// friction: a soft jelly shears under its weight and tumbles down even where it cannot slide.
        /// </summary>
        [Test]
        public void Friction_HoldsOnSlopeBelowItsAngleAndSlidesWithout()
        {
            float3 normal = new float3(-0.5f, math.sqrt(3f) / 2f, 0f);
            var slope = new[] { ColliderShape.Plane(float3.zero, normal) };
            float Slide(float mu)
            {
                var model = LatticeBody.Create(new int3(4, 4, 4), 0.1f, 4, 1f);
                var p = ShapeMatchingParameters.Default;
                p.Mode = ShapeMatchingMode.Rigid;
                p.Frequency = 30f;
                p.DampingRatio = 1f;
                p.Friction = mu;
                p.SleepSpeed = 0f;
                quaternion tilt = quaternion.AxisAngle(new float3(0f, 0f, 1f), math.PI / 6f);
                var body = new ShapeMatchingInstance(model, p, normal * 0.18f, tilt);
                float3 start = body.Status.Center;
                for (int step = 0; step < 120; step++)
                    body.Step(1f / 60f, slope);
                return math.length(body.Status.Center - start);
            }
            Assert.That(Slide(1f), Is.LessThan(0.02f));
            Assert.That(Slide(0f), Is.GreaterThan(1f));
        }

        /// <summary>
        /// Restitution is a per-particle law: a free particle dropped from h₀ = 1 m rebounds to e²·h₀. The
        /// contact is found at the end of the substep in which the particle crossed the surface, so the
        /// impact speed is off by up to g·h (1% of √(2gh₀) ≈ 4.4 m/s) and the bounce starts up to v·h =
        /// 1.8 cm from the surface (≤ 3% of e²h₀ at e = 0.8): the rebound is asserted within 5% of e²h₀,
        /// and a particle with e = 0 stays down. (A whole body's rebound also depends on its elasticity:
        /// only the particles that touch bounce, the rest follow through the goal pull.)
        /// </summary>
        [TestCase(0.8f)]
        [TestCase(0.5f)]
        [TestCase(0f)]
        public void Restitution_FreeParticleReboundsToESquaredHeight(float e)
        {
            var model = ShapeMatchingModelData.Create(new[] { float3.zero }, new[] { 1f }, new[] { 0 }, new int[0], false);
            var p = ShapeMatchingParameters.Default;
            p.Restitution = e;
            p.Friction = 0f;
            p.SleepSpeed = 0f;
            float r = p.ParticleRadius;
            var body = new ShapeMatchingInstance(model, p, new float3(0f, 1f + r, 0f), quaternion.identity);
            var floor = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            bool landed = false;
            float apex = 0f;
            for (int step = 0; step < 150; step++)
            {
                landed |= body.Step(1f / 60f, floor).Contacts > 0;
                if (landed)
                    apex = math.max(apex, body.Positions[0].y - r);
            }
            Assert.That(landed, Is.True);
            if (e > 0f)
                Assert.That(apex, Is.EqualTo(e * e).Within(0.05f * e * e));
            else
                Assert.That(apex, Is.LessThan(1e-3f));
        }

        /// <summary>
        /// A step 30 times the usual (0.5 s, 125 ms per substep) must not blow up: goals are reached by a
        /// fraction α ≤ 1 of the way, so the pull cannot overshoot, and the floor is a half-space. The body
        /// stays finite, outside the floor, and far slower than an exploding body would be.
        /// </summary>
        [TestCase(ShapeMatchingMode.Rigid)]
        [TestCase(ShapeMatchingMode.Linear)]
        [TestCase(ShapeMatchingMode.Quadratic)]
        public void HugeStep_StaysFiniteAndOutOfTheFloor(ShapeMatchingMode mode)
        {
            var model = LatticeBody.Create(new int3(5, 5, 5), 0.1f, 3, 1f, mode == ShapeMatchingMode.Quadratic);
            var p = ShapeMatchingParameters.Default;
            p.Mode = mode;
            var body = new ShapeMatchingInstance(model, p, new float3(0f, 3f, 0f), quaternion.AxisAngle(new float3(1f, 0f, 0f), 0.5f));
            var floor = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            const float dt = 0.5f;
            for (int step = 0; step < 20; step++)
            {
                Assert.That(body.Step(dt, floor).Reset, Is.False, $"step {step}");
                foreach (float3 x in body.Positions)
                    Assert.That(x.y, Is.GreaterThanOrEqualTo(p.ParticleRadius - k_Tolerance));
                // A loose bound that catches an explosion: no particle faster than ten steps of free fall
                // (the body falls 3 m, reaching √(2g·3) ≈ 1.6 g·dt, and the pull only redistributes momentum).
                foreach (float3 v in body.Velocities)
                    Assert.That(math.length(v), Is.LessThan(10f * 9.81f * dt));
            }
        }
    }
}
