using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Taps and drains: schedule, exact counts, no overlap, accounting, validation.</summary>
    public class FluidTapTests
    {
        const float k_Spacing = 0.02f;

        static FluidConstants Fluid(float3 min, float3 max) => new FluidConstants(FluidTestScenes.Water(k_Spacing, min, max));

        /// <summary>A tap pointing down (flow along −y) at <paramref name="position"/>.</summary>
        static FluidTapSettings DownwardTap(float3 position)
        {
            FluidTapSettings s = FluidTapSettings.Default;
            s.Position = position;
            s.Rotation = quaternion.AxisAngle(new float3(1f, 0f, 0f), math.PI / 2f);
            return s;
        }

        [Test]
        public void VolumeFlow_ConvertsWithTheParticleVolume()
        {
            FluidTapSettings s = FluidTapSettings.Default;
            s.RateMode = FluidTapRateMode.LitresPerSecond;
            s.VolumeFlow = 0.1f;
            // 0.1 L/s = 1e-4 m³/s over (0.02 m)³ = 8e-6 m³ per particle = 12.5 particles/s.
            Assert.That(s.ParticlesPerSecond(k_Spacing), Is.EqualTo(12.5f).Within(1e-5f));
        }

        [Test]
        public void Schedule_BurstsPulsesDurationLoopingAndDelayAreExact()
        {
            FluidTapSettings s = FluidTapSettings.Default;
            s.Rate = 0f;
            var bursts = new[] { new FluidTapBurst { Time = 0.5f, Count = 10, Cycles = 3, Interval = 0.25f } };
            Assert.AreEqual(0, FluidTapSchedule.BurstDue(s, bursts, 0.49));
            Assert.AreEqual(10, FluidTapSchedule.BurstDue(s, bursts, 0.5));
            Assert.AreEqual(10, FluidTapSchedule.BurstDue(s, bursts, 0.74));
            Assert.AreEqual(20, FluidTapSchedule.BurstDue(s, bursts, 0.75));
            Assert.AreEqual(30, FluidTapSchedule.BurstDue(s, bursts, 100.0));

            s.Rate = 100f;
            s.PulsePeriod = 0.5f;
            s.PulseDutyCycle = 0.3f;
            // Open 30 % of 10 s.
            Assert.That(FluidTapSchedule.SteadyDue(s, k_Spacing, 10.0), Is.EqualTo(300.0).Within(1e-3));

            s = FluidTapSettings.Default;
            s.Rate = 50f;
            s.StartDelay = 1f;
            s.Duration = 2f;
            Assert.AreEqual(0.0, FluidTapSchedule.SteadyDue(s, k_Spacing, 0.5));
            Assert.That(FluidTapSchedule.SteadyDue(s, k_Spacing, 10.0), Is.EqualTo(100.0).Within(1e-3), "stops after its duration");
            s.Looping = true;
            Assert.That(FluidTapSchedule.SteadyDue(s, k_Spacing, 10.0), Is.EqualTo(450.0).Within(1e-3), "4.5 loops of 2 s");
            Assert.AreEqual(4 * 10 + 10, FluidTapSchedule.BurstDue(s, new[] { new FluidTapBurst { Time = 0.2f, Count = 10, Cycles = 1 } }, 10.0),
                "a burst per loop: four whole loops and the fifth begun");
        }

        [Test]
        public void Emit_SpawnsExactlyWhatIsDueWhenThereIsRoom()
        {
            // A burst-only sphere tap in open space: each cycle's particles appear in the frame its time falls in.
            var c = Fluid(new float3(-1f), new float3(1f));
            var b = new FluidBuffers(500, c.Grid);
            FluidTapSettings s = FluidTapSettings.Default;
            s.Shape = FluidTapShape.Sphere;
            s.Radius = 0.1f;
            s.Rate = 0f;
            s.Speed = 0f;
            var bursts = new[] { new FluidTapBurst { Time = 0.1f, Count = 40, Cycles = 2, Interval = 0.5f } };
            var state = new FluidTapState();
            var spawnedAt = new List<(int frame, int count)>();
            for (int f = 1; f <= 60; f++)
            {
                FluidEmitReport r = FluidTapEmitter.Emit(s, bursts, ref state, 1f / 60f, c, 0, b.Particles, b.Scratch, ref b.Status);
                if (r.Spawned > 0)
                    spawnedAt.Add((f, r.Spawned));
                // Move the particles away so the second cycle has room (no solver step: only the emitter is under test).
                for (int i = 0; i < b.Status.Count; i++)
                    b.Positions[i].y -= 0.01f;
            }
            Assert.AreEqual(2, spawnedAt.Count);
            Assert.AreEqual((6, 40), spawnedAt[0], "t = 0.1 s falls in frame 6 (0.0833, 0.1]");
            Assert.AreEqual((36, 40), spawnedAt[1], "t = 0.6 s falls in frame 36");
            Assert.AreEqual(80, b.Status.Count);
        }

        [Test]
        public void Spawns_NeverOverlapAndABlockedTapHoldsBack()
        {
            // A disc tap pouring 2000 particles/s (more than its 21-point lattice can place per spacing of travel) into a
            // box, the solver running: every new particle is at least 0.9 Δx from every other particle when it appears.
            var c = Fluid(new float3(-0.2f, 0f, -0.2f), new float3(0.2f, 0.5f, 0.2f));
            var b = new FluidBuffers(3000, c.Grid);
            FluidTapSettings s = DownwardTap(new float3(0f, 0.4f, 0f));
            s.Radius = 0.05f;
            s.Rate = 2000f;
            var state = new FluidTapState();
            int heldBack = 0;
            float minDistance = float.PositiveInfinity;
            for (int f = 0; f < 40; f++)
            {
                int before = b.Status.Count;
                FluidEmitReport r = FluidTapEmitter.Emit(s, default, ref state, 1f / 60f, c, 0, b.Particles, b.Scratch, ref b.Status);
                heldBack = Math.Max(heldBack, r.HeldBack);
                for (int i = before; i < b.Status.Count; i++)
                for (int j = 0; j < b.Status.Count; j++)
                    if (j != i)
                        minDistance = math.min(minDistance, math.length(b.Positions[i] - b.Positions[j]));
                FluidTestScenes.Step(c, b, 1f / 60f);
            }
            TestContext.WriteLine($"closest spawn {minDistance / k_Spacing:F3} Δx, most held back {heldBack}, alive {b.Status.Count}");
            Assert.That(minDistance, Is.GreaterThanOrEqualTo(FluidTapEmitter.MinSpawnDistance * k_Spacing * (1f - 1e-5f)));
            Assert.That(heldBack, Is.GreaterThan(0), "2000/s is more than the disc can place: the excess waits");
        }

        [Test]
        public void Count_IsSpawnedMinusKilledMinusExpired()
        {
            // Tap with random lifetimes, a drain on the floor, the solver in the loop, 3 s: the identity holds every frame,
            // and each removal path was exercised.
            var c = Fluid(new float3(-0.2f, 0f, -0.2f), new float3(0.2f, 0.5f, 0.2f));
            var b = new FluidBuffers(2000, c.Grid);
            FluidTapSettings s = DownwardTap(new float3(0f, 0.4f, 0f));
            s.Rate = 300f;
            s.Lifetime = 0.6f;
            s.LifetimeRandom = 0.3f;
            s.Speed = 0.5f;
            var taps = new[] { new FluidTapInstance { Settings = s } };
            var drains = new[] { new FluidDrain { Shape = ColliderShape.Box(new float3(0.15f, 0f, 0f), quaternion.identity, new float3(0.05f, 0.05f, 0.2f)) } };
            for (int f = 0; f < 180; f++)
            {
                FluidFrame.Advance(c, default, drains, taps, default, 0, 1f / 60f, b.Particles, b.Scratch, ref b.Status);
                FluidStatus st = b.Status;
                Assert.AreEqual(st.Spawned - st.Killed - st.Expired - st.Invalid, st.Count, $"frame {f}");
            }
            Assert.That(b.Status.Expired, Is.GreaterThan(0));
            Assert.That(b.Status.Spawned, Is.GreaterThan(500));
            Assert.AreEqual(0, b.Status.Invalid);
            TestContext.WriteLine($"spawned {b.Status.Spawned}, killed {b.Status.Killed}, expired {b.Status.Expired}, alive {b.Status.Count}");
        }

        [Test]
        public void Drain_RemovesEveryParticleInside()
        {
            var c = Fluid(float3.zero, new float3(0.2f, 0.4f, 0.2f));
            FluidBuffers b = FluidTestScenes.Block(c, 1000, float3.zero, new float3(0.2f, 0.1f, 0.2f));
            int n = b.Status.Count;
            var drain = new FluidDrain { Shape = ColliderShape.Sphere(new float3(0.1f, 0f, 0.1f), 0.05f) };
            int inside = 0;
            for (int i = 0; i < n; i++)
                inside += math.length(b.Positions[i] - drain.Shape.Center) < 0.05f ? 1 : 0;
            Assert.AreEqual(inside, FluidDrain.Apply(new[] { drain }, b.Particles, n));
            FluidStepReport r = FluidTestScenes.Step(c, b, 1f / 60f);
            Assert.AreEqual(inside, r.Killed);
            Assert.AreEqual(n - inside, b.Status.Count);
        }

        [Test]
        public void MaxAlive_AndBudget_CapTheCount()
        {
            var c = Fluid(new float3(-1f), new float3(1f));
            var b = new FluidBuffers(400, c.Grid);
            FluidTapSettings s = FluidTapSettings.Default;
            s.Shape = FluidTapShape.Box;
            s.HalfExtents = new float3(0.1f);
            s.Rate = 100000f;
            s.MaxAlive = 150;
            var state = new FluidTapState();
            FluidTapEmitter.Emit(s, default, ref state, 1f / 60f, c, 0, b.Particles, b.Scratch, ref b.Status);
            Assert.AreEqual(150, b.Status.Count);
            s.MaxAlive = 0;
            FluidEmitReport r = FluidTapEmitter.Emit(s, default, ref state, 1f / 60f, c, 200, b.Particles, b.Scratch, ref b.Status);
            Assert.AreEqual(200, b.Status.Count);
            Assert.IsTrue(r.OverBudget);
        }

        [Test]
        public void Directions_AndSpeeds_StayInTheirRanges()
        {
            var c = Fluid(new float3(-1f), new float3(1f));
            var b = new FluidBuffers(2000, c.Grid);
            FluidTapSettings s = FluidTapSettings.Default;
            s.Shape = FluidTapShape.Sphere;
            s.Radius = 0.15f;
            s.Rotation = quaternion.AxisAngle(new float3(0f, 1f, 0f), 0.7f);
            s.ConeAngle = 30f;
            s.Speed = 2f;
            s.SpeedRandom = 0.5f;
            s.Rate = 100000f;
            var state = new FluidTapState();
            FluidTapEmitter.Emit(s, default, ref state, 1f / 60f, c, 0, b.Particles, b.Scratch, ref b.Status);
            Assert.That(b.Status.Count, Is.GreaterThan(500));
            float3 axis = math.rotate(s.Rotation, new float3(0f, 0f, 1f));
            float smallestCos = 1f;
            for (int i = 0; i < b.Status.Count; i++)
            {
                float speed = math.length(b.Velocities[i]);
                Assert.That(speed, Is.InRange(1.5f - 1e-5f, 2.5f + 1e-5f));
                smallestCos = math.min(smallestCos, math.dot(b.Velocities[i] / speed, axis));
            }
            // Float32 rotation and normalisation: 1e-5 on the cosine.
            Assert.That(smallestCos, Is.GreaterThanOrEqualTo(math.cos(30f * math.PI / 180f) - 1e-5f));
            Assert.That(smallestCos, Is.LessThan(math.cos(25f * math.PI / 180f)), "the cone is filled, not just its axis");
        }

        [Test]
        public void Emit_IsDeterministic()
        {
            var c = Fluid(new float3(-0.2f, 0f, -0.2f), new float3(0.2f, 0.5f, 0.2f));
            FluidBuffers Run()
            {
                var b = new FluidBuffers(1000, c.Grid);
                FluidTapSettings s = DownwardTap(new float3(0f, 0.4f, 0f));
                s.ConeAngle = 10f;
                s.SpeedRandom = 0.2f;
                var taps = new[] { new FluidTapInstance { Settings = s } };
                for (int f = 0; f < 30; f++)
                    FluidFrame.Advance(c, default, default, taps, default, 0, 1f / 60f, b.Particles, b.Scratch, ref b.Status);
                return b;
            }
            FluidBuffers a = Run(), d = Run();
            Assert.AreEqual(a.Status.Count, d.Status.Count);
            CollectionAssert.AreEqual(a.Positions, d.Positions);
            CollectionAssert.AreEqual(a.Ids, d.Ids);
        }

        [Test]
        public void Prewarm_StartsWithTheFlowEstablished()
        {
            var c = Fluid(new float3(-0.2f, 0f, -0.2f), new float3(0.2f, 0.5f, 0.2f));
            var b = new FluidBuffers(1000, c.Grid);
            FluidTapSettings s = DownwardTap(new float3(0f, 0.4f, 0f));
            s.Rate = 100f;
            s.Prewarm = 0.5f;
            var taps = new[] { new FluidTapInstance { Settings = s } };
            int frames = FluidFrame.Prewarm(c, default, default, taps, default, 0, 1f / 60f, b.Particles, b.Scratch, ref b.Status);
            Assert.AreEqual(30, frames);
            // 100/s for 0.5 s: 50 particles, give or take the fractional one still owed.
            Assert.That(b.Status.Count, Is.InRange(49, 50));
            Assert.That(taps[0].State.Time, Is.EqualTo(0.5).Within(1e-6));
        }

        [Test]
        public void Validation_ReportsBadSettingsAndOverBudget()
        {
            var issues = new List<ValidationIssue>();
            FluidTapSettings s = FluidTapSettings.Default;
            s.Lifetime = 10f;
            s.Rate = 500f;
            Assert.IsFalse(FluidValidation.ValidateTap(s, default, k_Spacing, 1000, issues));
            Assert.AreEqual((IssueCode)FluidEmissionIssueCode.TapOverBudget, issues[0].Code, "500/s × 10 s = 5000 > 1000");
            issues.Clear();
            s.Lifetime = 0f;
            Assert.IsFalse(FluidValidation.ValidateTap(s, default, k_Spacing, 1000, issues), "forever-living particles from an endless tap");
            issues.Clear();
            s.Lifetime = 1f;
            s.ConeAngle = 180f;
            s.PulseDutyCycle = 0f;
            s.Speed = float.NaN;
            Assert.IsFalse(FluidValidation.ValidateTap(s, new[] { new FluidTapBurst { Cycles = 0 } }, k_Spacing, 1000, issues));
            var codes = issues.ConvertAll(i => i.Code);
            CollectionAssert.IsSupersetOf(codes, new IssueCode[] { FluidEmissionIssueCode.TapConeInvalid, FluidEmissionIssueCode.TapPulseInvalid,
                FluidEmissionIssueCode.TapSpeedInvalid, FluidEmissionIssueCode.TapBurstInvalid });
            issues.Clear();
            FluidParameters p = FluidParameters.Default;
            Assert.IsTrue(FluidValidation.Validate(p, 1000, issues));
            p.ParticleSpacing = -1f;
            p.SpeedOfSound = 1e5f;
            Assert.IsFalse(FluidValidation.Validate(p, 0, issues));
            codes = issues.ConvertAll(i => i.Code);
            CollectionAssert.IsSupersetOf(codes, new IssueCode[] { FluidIssueCode.SpacingInvalid, FluidIssueCode.SpeedOfSoundInvalid, FluidIssueCode.BudgetInvalid });
        }

        [Test]
        public void PositionBasedDomainTooDeepForTheCap_IsAWarning()
        {
            // The depth rule for a full default domain (1 m) at 4 iterations asks for h ≤ Δx·√(0.01·4 / (0.23·g·1 m)) ≈ 2.7 ms,
            // 7 substeps per 1/60 s frame: a cap of 4 warns, the default cap of 32 does not.
            FluidParameters p = FluidParameters.Default;
            p.Solver = FluidSolverKind.PositionBased;
            var issues = new List<ValidationIssue>();
            Assert.IsTrue(FluidValidation.Validate(p, 1000, issues));
            Assert.IsEmpty(issues);
            p.MaxSubsteps = 4;
            Assert.IsTrue(FluidValidation.Validate(p, 1000, issues), "a warning, not an error");
            Assert.AreEqual(1, issues.Count);
            Assert.AreEqual((IssueCode)FluidIssueCode.SubstepCapTooLow, issues[0].Code);
            StringAssert.Contains("7 substeps", issues[0].Message);
        }
    }
}
