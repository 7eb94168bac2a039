using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// NaN guard (stability plan #27): NaN, +Inf or 1e20 written into one particle is detected in the
    /// next step with its index, the body is reset to its rest shape at its last good placement, and
    /// nothing else is touched: another body stepped alongside is bit-identical to an untouched twin.
    /// </summary>
    public class NaNGuardTests
    {
        public enum Injection { NaNPosition, InfinityVelocity, HugePosition, HugeVelocity }

        static ShapeMatchingInstance Body(float3 position, bool canSleep = false)
        {
            var model = LatticeBody.Create(new int3(4, 4, 4), 0.1f, 3, 1f);
            var p = ShapeMatchingParameters.Default;
            if (!canSleep)
                p.Body.SleepSpeed = 0f;
            return new ShapeMatchingInstance(model, p, position, quaternion.identity);
        }

        [Test]
        public void NaNGuard_DetectsInjectionWithinOneStepAndResets([Values] Injection injection)
        {
            var floor = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            ShapeMatchingInstance victim = Body(new float3(0f, 1f, 0f));
            ShapeMatchingInstance neighbour = Body(new float3(2f, 1f, 0f));
            ShapeMatchingInstance twin = Body(new float3(2f, 1f, 0f));
            for (int step = 0; step < 30; step++)
            {
                victim.Step(1f / 60f, floor);
                neighbour.Step(1f / 60f, floor);
                twin.Step(1f / 60f, floor);
            }
            ParticleBodyStatus lastGood = victim.Status;
            const int index = 17;
            switch (injection)
            {
                case Injection.NaNPosition: victim.Positions[index].y = float.NaN; break;
                case Injection.InfinityVelocity: victim.Velocities[index].x = float.PositiveInfinity; break;
                case Injection.HugePosition: victim.Positions[index] = new float3(1e20f, 0f, 0f); break;
                case Injection.HugeVelocity: victim.Velocities[index] = new float3(0f, 1e20f, 0f); break;
            }
            ShapeMatchingStepReport report = victim.Step(1f / 60f, floor);
            neighbour.Step(1f / 60f, floor);
            twin.Step(1f / 60f, floor);

            Assert.That(report.Reset, Is.True);
            Assert.That(report.BadParticle, Is.EqualTo(index));
            Assert.That(victim.Status.ResetCount, Is.EqualTo(1));
            // Reset = the rest shape at the last good centre and rotation, at rest.
            var model = victim.Model.AsModel();
            Assert.That(BodyMeasures.ShapeError(victim.Positions, model), Is.LessThanOrEqualTo(1e-5));
            Assert.That(math.distance(ShapeMatching.CenterOfMass(victim.Positions, victim.Model.Masses), lastGood.Center),
                Is.LessThanOrEqualTo(1e-5f));
            foreach (float3 v in victim.Velocities)
                Assert.That(math.all(v == float3.zero), Is.True);
            for (int i = 0; i < neighbour.Positions.Length; i++)
                Assert.That(neighbour.Positions[i], Is.EqualTo(twin.Positions[i]), "the neighbour is untouched");

            // And the body simulates normally afterwards.
            for (int step = 0; step < 60; step++)
                Assert.That(victim.Step(1f / 60f, floor).Reset, Is.False);
        }

        [Test]
        public void NaNGuard_WakesASleepingBodyToResetIt()
        {
            var floor = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            ShapeMatchingInstance body = Body(new float3(0f, 0.2f, 0f), canSleep: true);
            for (int step = 0; step < 600 && !body.Status.Asleep; step++)
                body.Step(1f / 60f, floor);
            Assert.That(body.Status.Asleep, Is.True);
            body.Positions[3] = new float3(float.NaN);
            ShapeMatchingStepReport report = body.Step(1f / 60f, floor);
            Assert.That(report.Reset, Is.True);
            Assert.That(report.BadParticle, Is.EqualTo(3));
        }
    }
}
