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
            float radius = body.Parameters.Body.ParticleRadius;
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
            float top = 0.525f + body.Parameters.Body.ParticleRadius;
            for (int i = 0; i < 120; i++)
            {
                body.Step(1f / 60f, step);
                foreach (float3 x in body.Positions)
                    Assert.That(x.y, Is.GreaterThanOrEqualTo(top - k_Tolerance), $"step {i}");
            }
        }

        /// <summary>The oracle itself, on points whose distance is known by hand.</summary>
        [Test]
        public void ColliderDistance_MatchesHandComputedValues()
        {
            var plane = ColliderShape.Plane(new float3(0f, -0.1f, 0f), new float3(0f, 1f, 1f));
            Assert.That(ColliderDistance.SignedDistance(plane, new float3(0f, 1f, 0f)), Is.EqualTo(1.1 / System.Math.Sqrt(2.0)).Within(1e-6));
            var sphere = ColliderShape.Sphere(float3.zero, 0.5f);
            Assert.That(ColliderDistance.SignedDistance(sphere, new float3(0.3f, 0.4f, 0f)), Is.EqualTo(0.0).Within(1e-6));
            Assert.That(ColliderDistance.SignedDistance(sphere, new float3(0f, 0f, 0.2f)), Is.EqualTo(-0.3).Within(1e-6));
            var capsule = ColliderShape.Capsule(new float3(-0.5f, 0f, 0f), new float3(0.5f, 0f, 0f), 0.3f);
            Assert.That(ColliderDistance.SignedDistance(capsule, new float3(0.8f, 0.4f, 0f)), Is.EqualTo(0.2).Within(1e-6));
            Assert.That(ColliderDistance.SignedDistance(capsule, new float3(0f, 0.1f, 0f)), Is.EqualTo(-0.2).Within(1e-6));
            // Turned 90° about z: the 0.4 half extent lies along world y, the 0.2 one along world x.
            var box = ColliderShape.Box(float3.zero, quaternion.AxisAngle(new float3(0f, 0f, 1f), 0.5f * math.PI), new float3(0.4f, 0.2f, 0.3f));
            Assert.That(ColliderDistance.SignedDistance(box, new float3(0.5f, 0f, 0f)), Is.EqualTo(0.3).Within(1e-6));
            Assert.That(ColliderDistance.SignedDistance(box, new float3(0f, 0.5f, 0f)), Is.EqualTo(0.1).Within(1e-6));
            Assert.That(ColliderDistance.SignedDistance(box, float3.zero), Is.EqualTo(-0.2).Within(1e-6));
            Assert.That(ColliderDistance.SignedDistance(box, new float3(0.5f, 0.7f, 0f)), Is.EqualTo(System.Math.Sqrt(0.18)).Within(1e-6));
        }

        /// <summary>
        /// Every primitive, checked against an independent float64 signed distance (<see cref="ColliderDistance"/>): a
        /// particle of radius r at x overlaps by r − SignedDistance(x), the push reports exactly that depth, and the
        /// pushed particle is clear of the surface. Tolerance: one push and one distance of O(1) m float32 coordinates,
        /// a few ulp (1e-5 m asserted).
        /// </summary>
        [Test]
        public void Particles_ArePushedOutOfEveryPrimitive()
        {
            float r = 0.02f;
            var shapes = new[]
            {
                ColliderShape.Sphere(new float3(0f, 0f, 0f), 0.5f),
                ColliderShape.Capsule(new float3(-0.5f, 0f, 0f), new float3(0.5f, 0f, 0f), 0.3f),
                ColliderShape.Capsule(new float3(-0.3f, -0.2f, 0.1f), new float3(0.4f, 0.3f, -0.2f), 0.2f),
                ColliderShape.Box(float3.zero, quaternion.AxisAngle(new float3(0f, 0f, 1f), 0.5f), new float3(0.4f, 0.2f, 0.3f)),
                ColliderShape.Box(new float3(0.1f, 0f, -0.1f), quaternion.AxisAngle(math.normalize(new float3(1f, 2f, -1f)), 1.1f),
                    new float3(0.3f, 0.15f, 0.35f)),
                ColliderShape.Plane(new float3(0f, -0.1f, 0f), new float3(0f, 1f, 1f)),
            };
            var rng = new Random(3u);
            foreach (ColliderShape shape in shapes)
            {
                int hits = 0;
                for (int k = 0; k < 400; k++)
                {
                    float3 x = (rng.NextFloat3() - 0.5f) * 1.2f;
                    double overlap = ColliderDistance.Overlap(shape, x, r);
                    bool hit = ParticleCollision.Penetration(shape, x, r, out float3 n, out float depth);
                    // Exactly on the surface (overlap ~ 0) either answer is right.
                    if (overlap > k_Tolerance || overlap == 0.0)
                        Assert.That(hit, Is.EqualTo(overlap > 0.0), $"{shape.Type} at {x}: overlap {overlap}");
                    if (!hit)
                        continue;
                    hits++;
                    Assert.That(math.length(n), Is.EqualTo(1f).Within(1e-5f));
                    Assert.That(depth, Is.EqualTo(overlap).Within(k_Tolerance), $"{shape.Type} at {x}: depth");
                    float3 pushed = x + depth * n;
                    Assert.That(ColliderDistance.Overlap(shape, pushed, r), Is.LessThanOrEqualTo(k_Tolerance), $"{shape.Type} at {x}: pushed out");
                }
                Assert.That(hits, Is.GreaterThan(20), $"{shape.Type}: enough samples inside");
            }
        }

        /// <summary>
        /// On a 30° slope (tan 30° ≈ 0.58) a body with μ = 1 holds, one with μ = 0 slides. Position-based
        /// friction cancels tangential motion up to μ × the penetration gravity causes each substep, so
        /// the static limit is exactly tan θ &lt; μ. A stiff body (rigid goals, 30 Hz, critically damped) keeps the test about
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
                p.Body.Friction = mu;
                p.Body.SleepSpeed = 0f;
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
            p.Body.Restitution = e;
            p.Body.Friction = 0f;
            p.Body.SleepSpeed = 0f;
            float r = p.Body.ParticleRadius;
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
        /// A step 6 and 30 times the usual (0.1 s and 0.5 s) must not blow up or collapse. The step adds substeps until
        /// ωh ≤ <see cref="ShapeMatchingParameters.MaxSubstepPhase"/> and each substep is stable at any h, and the floor is
        /// a half-space: the body stays finite, outside the floor, and far slower than an exploding body would be. And
        /// it comes to rest at the height it rests at with the usual step (1/60 s): the substep reproduces the material's
        /// oscillator exactly, so its static sag is the continuous one, ω²δ = g, up to a relative error ζωh + (ωh)²/12
        /// (<see cref="OscillatorDiscretization"/>), at most 0.13 × 0.5 + 0.5²/12 ≈ 0.09 for ωh ≤ 0.5. The resting centre
        /// height may therefore differ from the small-step one by at most 10 % of the small-step sag (rest height minus
        /// resting height), plus 1 mm for what the landing leaves locked in by friction. A collapse, or a body that
        /// never settles, misses that by the body's size.
        /// </summary>
        [Test]
        public void HugeStep_StaysFiniteAndOutOfTheFloor([Values] ShapeMatchingMode mode, [Values(0.1f, 0.5f)] float dt)
        {
            var model = LatticeBody.Create(new int3(5, 5, 5), 0.1f, 3, 1f, mode == ShapeMatchingMode.Quadratic);
            var p = ShapeMatchingParameters.Default;
            p.Mode = mode;
            p.Body.SleepSpeed = 0f;
            var floor = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            ShapeMatchingInstance Drop() =>
                new ShapeMatchingInstance(model, p, new float3(0f, 3f, 0f), quaternion.AxisAngle(new float3(1f, 0f, 0f), 0.5f));
            ShapeMatchingInstance body = Drop();
            int steps = (int)math.round(10f / dt);
            for (int step = 0; step < steps; step++)
            {
                Assert.That(body.Step(dt, floor).Reset, Is.False, $"step {step}");
                foreach (float3 x in body.Positions)
                    Assert.That(x.y, Is.GreaterThanOrEqualTo(p.Body.ParticleRadius - k_Tolerance));
                // A loose bound that catches an explosion: no particle faster than ten steps of free fall
                // (the body falls 3 m, reaching √(2g·3) ≈ 1.6 g·dt at dt = 0.5 s, and the pull only redistributes momentum).
                foreach (float3 v in body.Velocities)
                    Assert.That(math.length(v), Is.LessThan(10f * 9.81f * math.max(dt, 0.5f)));
            }
            ShapeMatchingInstance reference = Drop();
            for (int step = 0; step < 600; step++)
                reference.Step(1f / 60f, floor);
            float restHeight = 0.2f + p.Body.ParticleRadius;
            float sag = restHeight - reference.Status.Center.y;
            Assert.That(sag, Is.GreaterThan(0f));
            Assert.That(body.Status.Center.y, Is.EqualTo(reference.Status.Center.y).Within(0.1f * sag + 1e-3f),
                $"resting height at dt = {dt} s against 1/60 s (sag {sag} m)");
        }
    }
}
