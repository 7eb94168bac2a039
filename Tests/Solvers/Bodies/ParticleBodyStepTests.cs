using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// The step every particle body shares, with a stage that adds no force: when a body sleeps and stays awake, and the
    /// guard's rare branches (a bad last placement, a body far from the world origin, the stage's reset, waking by bad input).
    /// The test body's pivot is not its centre of mass.
    /// </summary>
    public class ParticleBodyStepTests
    {
        /// <summary>A stage with no internal force that counts the guard's resets.</summary>
        struct CountingStage : IParticleSolveStage
        {
            public int Resets;
            public quaternion ResetRotation;
            public void Solve(in ParticleBody body, in ParticleStepConstants constants, in RigidFrame frame, bool lastSubstep) { }

            public void OnReset(quaternion rotation)
            {
                Resets++;
                ResetRotation = rotation;
            }
        }

        const float k_Dt = 1f / 60f;
        const float k_SleepSpeed = 0.05f;
        const float k_SleepDelay = 0.5f;

        /// <summary>Eight particles on the corners of a 0.2 × 0.3 × 0.4 m box around (5, 2, −3): the mesh's pivot (0) is far from its centre.</summary>
        sealed class Body
        {
            public readonly float3[] Rest = new float3[8];
            public readonly float[] Masses = new float[8];
            public readonly float3[] X = new float3[8], V = new float3[8], Predicted = new float3[8], Scratch = new float3[8], Normals = new float3[8];
            public float3 RestCenter;
            public ParticleBodyStatus Status;
            public CountingStage Stage;

            public Body(float[] masses = null)
            {
                for (int i = 0; i < 8; i++)
                {
                    Rest[i] = new float3(5f, 2f, -3f) + new float3((i & 1) * 0.2f, ((i >> 1) & 1) * 0.3f, ((i >> 2) & 1) * 0.4f);
                    Masses[i] = masses != null ? masses[i] : 0.5f;
                }
                RestCenter = ShapeMatching.CenterOfMass(Rest, Masses);
            }

            public ParticleBody View => new ParticleBody(Rest, RestCenter, Masses, X, V, Predicted, Scratch, Normals);

            public void Place(float3 position, quaternion rotation, float3 velocity) => ParticleBodyStep.Place(View, position, rotation, velocity, out Status);

            public ParticleStepReport Step(float3 gravity)
            {
                ParticleStepConstants c = ParticleStepConstants.Undamped(k_Dt, 2, gravity, 0.01f, 0f, 0f, 2f, 100f, k_SleepSpeed, k_SleepDelay);
                return ParticleBodyStep.Step(ref Stage, View, c, ReadOnlySpan<ColliderShape>.Empty, ref Status);
            }
        }

        /// <summary>Steps still before a body sleeps: StillTime reaches the delay on this step (float32 sums of 1/60 s).</summary>
        static int StepsToSleep()
        {
            float t = 0f;
            int n = 0;
            while (t < k_SleepDelay)
            {
                t += k_Dt;
                n++;
            }
            return n;
        }

        [Test]
        public void PlacedBody_HasItsCentreOfMassAtThePosition_WhateverTheMeshPivot()
        {
            var b = new Body();
            var p = new float3(0.3f, 1.2f, -0.7f);
            b.Place(p, quaternion.AxisAngle(new float3(0f, 1f, 0f), 0.8f), float3.zero);
            float3 c = ShapeMatching.CenterOfMass(b.X, b.Masses);
            Assert.That(math.distance(c, p), Is.LessThan(1e-5f));
            Assert.That(math.distance(b.Status.Center, p), Is.LessThan(1e-6f));
            // A step without forces keeps the placement, and the rotation is found from the off-centre rest shape.
            b.Step(float3.zero);
            Assert.That(math.distance(b.Status.Center, p), Is.LessThan(1e-5f));
            Assert.That(math.abs(math.dot(b.Status.Rotation.value, quaternion.AxisAngle(new float3(0f, 1f, 0f), 0.8f).value)), Is.GreaterThan(1f - 1e-5f));
        }

        [Test]
        public void SlowBody_SleepsOnceStillForTheDelay_AndItsVelocityIsCleared()
        {
            var b = new Body();
            b.Place(float3.zero, quaternion.identity, new float3(0.9f * k_SleepSpeed, 0f, 0f));
            int n = StepsToSleep();
            for (int k = 1; k < n; k++)
                Assert.That(b.Step(float3.zero).FellAsleep, Is.False, $"step {k}: still less than the delay");
            Assert.That(b.Step(float3.zero).FellAsleep, Is.True);
            Assert.That(b.Status.Asleep, Is.True);
            Assert.That(b.V, Has.All.EqualTo(float3.zero));
        }

        [Test]
        public void MovingBody_StaysAwake_JustAboveTheSleepSpeed()
        {
            var b = new Body();
            b.Place(float3.zero, quaternion.identity, new float3(0f, 0f, 1.1f * k_SleepSpeed));
            for (int k = 0; k < 3 * StepsToSleep(); k++)
                Assert.That(b.Step(float3.zero).FellAsleep, Is.False);
            Assert.That(b.Status.Asleep, Is.False);
            Assert.That(b.Status.StillTime, Is.EqualTo(0f));
        }

        [Test]
        public void SleepSpeed_IsTheMassWeightedRmsSpeed()
        {
            // One light particle at 6× the sleep speed among heavy ones at rest: RMS over mass = 6·v_s·√(1/701) < v_s, asleep;
            // an RMS over particles (6·v_s/√8 > v_s) would keep it awake.
            var masses = new float[] { 100f, 100f, 100f, 100f, 100f, 100f, 100f, 1f };
            var b = new Body(masses);
            b.Place(float3.zero, quaternion.identity, float3.zero);
            int n = StepsToSleep();
            bool asleep = false;
            for (int k = 0; k < n && !asleep; k++)
            {
                b.V[7] = new float3(6f * k_SleepSpeed, 0f, 0f);
                for (int i = 0; i < 7; i++)
                    b.V[i] = float3.zero;
                asleep = b.Step(float3.zero).FellAsleep;
            }
            Assert.That(asleep, Is.True);
        }

        [Test]
        public void StillTime_StartsAgain_WhenTheBodyMoves()
        {
            var b = new Body();
            b.Place(float3.zero, quaternion.identity, float3.zero);
            int n = StepsToSleep();
            for (int k = 1; k < n; k++)
                b.Step(float3.zero);
            Assert.That(b.Status.StillTime, Is.GreaterThan(0f));
            for (int i = 0; i < 8; i++)
                b.V[i] = new float3(0f, 2f * k_SleepSpeed, 0f);
            b.Step(float3.zero);
            Assert.That(b.Status.StillTime, Is.EqualTo(0f));
            Assert.That(b.Status.Asleep, Is.False);
        }

        [Test]
        public void Guard_ResetsToTheLastGoodPlacement_AndTellsTheStageOnce()
        {
            var b = new Body();
            quaternion q = quaternion.AxisAngle(new float3(1f, 0f, 0f), 0.5f);
            var p = new float3(1f, 0.5f, 2f);
            b.Place(p, q, float3.zero);
            b.Step(float3.zero);
            b.V[3] = new float3(float.NaN, 0f, 0f);
            ParticleStepReport r = b.Step(float3.zero);
            Assert.That(r.Reset, Is.True);
            Assert.AreEqual(3, r.BadParticle);
            Assert.AreEqual(1, b.Stage.Resets);
            Assert.That(math.abs(math.dot(b.Stage.ResetRotation.value, q.value)), Is.GreaterThan(1f - 1e-5f));
            Assert.That(math.distance(ShapeMatching.CenterOfMass(b.X, b.Masses), p), Is.LessThan(1e-5f));
            Assert.That(b.V, Has.All.EqualTo(float3.zero));
        }

        [TestCase(float.NaN)]
        [TestCase(2e6f)]
        public void Guard_WithABadLastCentre_ResetsAtTheWorldOriginUnrotated(float bad)
        {
            var b = new Body();
            b.Place(new float3(1f, 2f, 3f), quaternion.AxisAngle(new float3(0f, 0f, 1f), 1f), float3.zero);
            b.Status.Center = new float3(bad, 0f, 0f);
            b.X[0] = new float3(float.PositiveInfinity, 0f, 0f);
            Assert.That(b.Step(float3.zero).Reset, Is.True);
            Assert.AreEqual(float3.zero, b.Status.Center);
            Assert.AreEqual(float3.zero, b.Status.Origin);
            Assert.AreEqual(quaternion.identity.value, b.Stage.ResetRotation.value);
            Assert.That(math.length(ShapeMatching.CenterOfMass(b.X, b.Masses)), Is.LessThan(1e-5f));
        }

        [Test]
        public void Guard_WithAnOriginBeyondTheLimit_Resets()
        {
            var b = new Body();
            b.Place(new float3(1f, 2f, 3f), quaternion.identity, float3.zero);
            b.Status.Origin = new float3(0f, 0f, -2e6f);
            ParticleStepReport r = b.Step(float3.zero);
            Assert.That(r.Reset && !r.Stepped, Is.True);
            Assert.AreEqual(float3.zero, b.Status.Origin, "reset about the last good centre, near the world origin");
        }

        [Test]
        public void Guard_FarFromTheWorldOrigin_ResetsRelativeToTheBodysOrigin()
        {
            var b = new Body();
            var p = new float3(1000.3f, 5f, -700.6f);
            b.Place(p, quaternion.identity, new float3(1f, 0f, 0f));
            Assert.AreEqual(new float3(1000f, 5f, -701f), b.Status.Origin);
            for (int k = 0; k < 30; k++)
                b.Step(float3.zero);
            float3 before = b.Status.Center;
            Assert.That(math.distance(before, p + new float3(0.5f, 0f, 0f)), Is.LessThan(1e-3f));
            b.X[5] = new float3(float.NaN);
            Assert.That(b.Step(float3.zero).Reset, Is.True);
            Assert.AreEqual(ParticleBodyStep.OriginFor(before), b.Status.Origin);
            // Positions are relative to the origin: their centre is the last good centre less the origin.
            float3 local = ShapeMatching.CenterOfMass(b.X, b.Masses);
            Assert.That(math.distance(local + b.Status.Origin, before), Is.LessThan(1e-3f));
            Assert.That(math.cmax(math.abs(local)), Is.LessThan(ParticleBodyStep.RebaseDistance));
        }

        [Test]
        public void SleepingBody_WithBadInput_WakesAndResets()
        {
            var b = new Body();
            b.Place(new float3(0f, 1f, 0f), quaternion.identity, float3.zero);
            for (int k = 0; k < StepsToSleep(); k++)
                b.Step(float3.zero);
            Assert.That(b.Status.Asleep, Is.True);
            b.X[2] = new float3(0f, float.NaN, 0f);
            ParticleStepReport r = b.Step(float3.zero);
            Assert.That(r.WokeUp && r.Reset, Is.True);
            Assert.That(b.Status.Asleep, Is.False);
            Assert.AreEqual(1, b.Status.ResetCount);
            // Back at rest where it slept, it falls asleep again after the delay.
            for (int k = 0; k < StepsToSleep(); k++)
                b.Step(float3.zero);
            Assert.That(b.Status.Asleep, Is.True);
        }
    }
}
