using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>A fluid and a rigid proxy acting on each other (<see cref="FluidCoupling"/>).</summary>
    public class FluidCouplingTests
    {
        const float Spacing = 0.02f;

        /// <summary>A water blob 0.16 m on a side at rest, weightless, in the middle of a 1 m box it never reaches.</summary>
        static (FluidConstants, FluidBuffers) Blob()
        {
            FluidParameters p = FluidTestScenes.Water(Spacing, float3.zero, new float3(1f));
            p.Gravity = float3.zero;
            var c = new FluidConstants(p);
            return (c, FluidTestScenes.Block(c, 512, new float3(0.42f), new float3(0.58f)));
        }

        static Vector3d Momentum(in FluidConstants c, FluidBuffers b)
        {
            var sum = new Vector3d();
            for (int i = 0; i < b.Status.Count; i++)
                sum = sum + (Vector3d)b.Velocities[i];
            return c.Mass * sum;
        }

        static FluidBodyProxy Ball(float mass, float3 velocity) => new FluidBodyProxy
        {
            Shape = ColliderShape.Sphere(new float3(0.3f, 0.5f, 0.5f), 0.04f).Moving(velocity, float3.zero),
            Mass = mass,
            InverseInertia = float3x3.identity * (2.5f / (mass * 0.04f * 0.04f)),
        };

        /// <summary>
        /// A 0.3 kg ball thrown at 1 m/s into the weightless blob: the fluid gains what the ball loses. Every ghost force and
        /// contact is counted twice with opposite signs, so the sum changes only by round-off and by the fluid's own
        /// unconserved parts (the truncated Jacobi viscosity); the bound, 10⁻³ of the ball's momentum, over 0.5 s.
        /// </summary>
        [Test]
        public void BallThrownIntoWater_TradesMomentumWithIt()
        {
            var (c, b) = Blob();
            var bodies = new[] { Ball(0.3f, new float3(1f, 0f, 0f)) };
            Vector3d before = Momentum(c, b) + (Vector3d)(bodies[0].Mass * bodies[0].Shape.Velocity);
            Vector3d fluidGain = new Vector3d(), ballImpulse = new Vector3d();
            for (int f = 0; f < 30; f++)
            {
                Vector3d p0 = Momentum(c, b);
                FluidCoupling.Step(c, default, bodies, 1f / 60f, b.Particles, b.Scratch, ref b.Status);
                fluidGain = fluidGain + (Momentum(c, b) - p0);
                ballImpulse = ballImpulse + (Vector3d)bodies[0].Impulse;
            }
            Vector3d after = Momentum(c, b) + (Vector3d)(bodies[0].Mass * bodies[0].Shape.Velocity);
            double scale = 0.3;
            Assert.That(bodies[0].Shape.Velocity.x, Is.LessThan(0.9f), "the water slowed the ball");
            Assert.That(fluidGain.X, Is.GreaterThan(0.03), "the ball pushed the water");
            Assert.That((after - before).Length / scale, Is.LessThan(1e-3), $"momentum change {(after - before).X}, {(after - before).Y}, {(after - before).Z}");
            Assert.That((fluidGain + ballImpulse).Length / scale, Is.LessThan(1e-3), $"fluid gained {fluidGain.X}, ball took {ballImpulse.X}");
        }

        /// <summary>The loads are summed in slot order on one thread: any batch count gives the same bits, fluid and ball.</summary>
        [Test]
        public void CoupledStep_HasTheSameBitsForEveryBatchCount()
        {
            var (c, one) = Blob();
            var (_, three) = Blob();
            var a = new[] { Ball(0.3f, new float3(1f, 0f, 0f)) };
            var d = new[] { Ball(0.3f, new float3(1f, 0f, 0f)) };
            for (int f = 0; f < 12; f++)
            {
                FluidCoupling.Step(c, default, a, 1f / 60f, one.Particles, one.Scratch, ref one.Status, 1);
                FluidCoupling.Step(c, default, d, 1f / 60f, three.Particles, three.Scratch, ref three.Status, 3);
            }
            Assert.That(three.Status.Count, Is.EqualTo(one.Status.Count));
            for (int i = 0; i < one.Status.Count; i++)
                Assert.That(three.Positions[i], Is.EqualTo(one.Positions[i]), $"slot {i}");
            Assert.That(d[0].Shape.Center, Is.EqualTo(a[0].Shape.Center));
            Assert.That(d[0].Impulse, Is.EqualTo(a[0].Impulse));
        }

        /// <summary>
        /// A wall moving along its normal at u reflects a source's velocity in its own frame, v_g = v − 2(v·n − u)n: a source
        /// at rest beside a sphere receding at 0.5 m/s has a ghost that recedes at 1 m/s; the wall's speed is read at the
        /// surface point (ω × r included), and a static wall (u = 0) mirrors as before.
        /// </summary>
        [Test]
        public void MovingWall_MirrorsVelocitiesInItsOwnFrame()
        {
            var c = new FluidConstants(FluidTestScenes.Water(Spacing, float3.zero, new float3(1f)));
            var sphere = ColliderShape.Sphere(new float3(0.5f, 0.5f, 0.5f), 0.05f);
            float3 xi = new float3(0.5f, 0.56f, 0.5f);
            var moving = new[] { sphere.Moving(new float3(0f, -0.5f, 0f), float3.zero) };
            var walls = FluidGhostWalls.Near(c, moving, xi);
            Assert.That(walls.Count, Is.EqualTo(1));
            Assert.That(walls.NormalSpeed(0), Is.EqualTo(-0.5f).Within(1e-6f));
            Assert.That(walls.Collider(0), Is.EqualTo(0));
            float3 y = new float3(0f, 0.005f, 0f), v = float3.zero;
            Assert.That(walls.Mirror(1, ref y, ref v), Is.True);
            Assert.That(v.y, Is.EqualTo(-1f).Within(1e-6f));
            var spinning = new[] { sphere.Moving(float3.zero, new float3(0f, 0f, 10f)) };
            float3 beside = new float3(0.56f, 0.5f, 0.5f);
            // ω × r at the surface point (0.55, 0.5, 0.5): (0, 0.5, 0), tangential: no normal speed.
            Assert.That(FluidGhostWalls.Near(c, spinning, beside).NormalSpeed(0), Is.EqualTo(0f).Within(1e-6f));
            var still = FluidGhostWalls.Near(c, new[] { sphere }, xi);
            float3 y2 = new float3(0f, 0.005f, 0f), v2 = new float3(0.1f, -0.2f, 0.3f);
            Assert.That(still.Mirror(1, ref y2, ref v2), Is.True);
            Assert.That(v2, Is.EqualTo(new float3(0.1f, 0.2f, 0.3f)));
        }
    }
}
