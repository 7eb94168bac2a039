using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Bodies at rest sleep, cost nothing, and wake on a force change, a written velocity or a collider overlap.</summary>
    public class ShapeMatchingSleepTests
    {
        static readonly ColliderShape[] s_Floor = { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };

        static ShapeMatchingInstance SleepingCube()
        {
            var model = LatticeBody.Create(new int3(4, 4, 4), 0.1f, 3, 1f);
            var body = new ShapeMatchingInstance(model, ShapeMatchingParameters.Default, new float3(0f, 0.2f, 0f), quaternion.identity);
            for (int step = 0; step < 1200 && !body.Status.Asleep; step++)
                body.Step(1f / 60f, s_Floor);
            Assert.That(body.Status.Asleep, Is.True, "a cube resting on the floor falls asleep within 20 s");
            return body;
        }

        [Test]
        public void RestingBody_SleepsAndIsNotStepped()
        {
            ShapeMatchingInstance body = SleepingCube();
            var frozen = (float3[])body.Positions.Clone();
            uint steps = body.Status.StepCount;
            for (int i = 0; i < 60; i++)
                Assert.That(body.Step(1f / 60f, s_Floor).Stepped, Is.False);
            Assert.That(body.Positions, Is.EqualTo(frozen));
            Assert.That(body.Status.StepCount, Is.EqualTo(steps));
        }

        [Test]
        public void SleepingBody_WakesWhenGravityChanges()
        {
            ShapeMatchingInstance body = SleepingCube();
            body.Parameters.Body.Acceleration = new float3(0f, 9.81f, 0f);
            ShapeMatchingStepReport r = body.Step(1f / 60f, s_Floor);
            Assert.That(r.WokeUp && r.Stepped, Is.True);
            for (int i = 0; i < 30; i++)
                body.Step(1f / 60f, s_Floor);
            Assert.That(body.Status.Center.y, Is.GreaterThan(0.5f), "it falls upward");
        }

        [Test]
        public void SleepingBody_WakesWhenAVelocityIsWritten()
        {
            ShapeMatchingInstance body = SleepingCube();
            float before = body.Status.Center.y;
            for (int i = 0; i < body.Velocities.Length; i++)
                body.Velocities[i] = new float3(0f, 3f, 0f); // an impulse
            Assert.That(body.Step(1f / 60f, s_Floor).WokeUp, Is.True);
            // 3 m/s for 1/60 s, less what gravity takes: ≈ 4.9 cm.
            Assert.That(body.Status.Center.y - before, Is.GreaterThan(0.04f));
        }

        [Test]
        public void SleepingBody_WakesWhenAColliderMovesIntoIt()
        {
            ShapeMatchingInstance body = SleepingCube();
            var colliders = new[] { s_Floor[0], ColliderShape.Sphere(body.Status.Center + new float3(0.3f, 0f, 0f), 0.2f) };
            Assert.That(body.Step(1f / 60f, s_Floor).Stepped, Is.False, "the floor it rests on does not wake it");
            ShapeMatchingStepReport r = body.Step(1f / 60f, colliders);
            Assert.That(r.WokeUp, Is.True);
            Assert.That(r.Contacts, Is.GreaterThan(0));
        }
    }
}
