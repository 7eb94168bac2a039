using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// A body spawned deep inside a collider leaves it at a bounded speed instead of being shot out (a push of the
    /// whole overlap in one substep is overlap / h: 0.27 m at h = 1/240 s is 65 m/s). A 1 kg, 0.4 m lattice body
    /// (linear, 9 Hz, ζ = 0.13, β = 0.5, no gravity) starts with up to 0.27 m of overlap inside a sphere or a rotated
    /// box, placed so that every overlapping particle leaves through the same side.
    /// <para>Speed bound. A contact moves a particle out by at most <see cref="ParticleBodySettings.MaxDepenetrationSpeed"/>
    /// v_d per second, and the body's goals move with its centre and rotation. Relative to its goal a particle therefore
    /// starts its free oscillation with a speed of at most v_d and a displacement of at most the overlap d₀ it had to
    /// leave (the push displaces it relative to the rest of the body by no more than that). The pull conserves
    /// ½v² + ½ω²δ² of that oscillation (damping only lowers it), so the relative speed stays below √(v_d² + ω²d₀²),
    /// and the goal itself moves at most at v_d: |v| ≤ v_d + √(v_d² + ω²d₀²). Energy, particle by particle: the contact
    /// leaves particle i with at most v_d relative to a goal moving at most at v_d (kinetic ≤ ½mᵢ(2v_d)²), and the elastic
    /// energy it can store by pushing it out of its own overlap dᵢ relative to its goal is ½mᵢω²dᵢ²; the kinetic energy of
    /// the body stays below the sum, ½M(2v_d)² + ½ω²Σmᵢdᵢ² (about 36 J at v_d = 1 m/s for the box; a push of the whole
    /// overlap in one substep gives kilojoules).</para>
    /// <para>End state after 2 s: no particle overlaps the collider (an independent float64 distance,
    /// <see cref="ColliderDistance"/>, within 1e-5 m, the round-off of one projection at 3 m coordinates). The body is
    /// whole again: the wobble of the exit has decayed by e^{−ζω·1.7 s} ≈ 4e-6, and what is left is the centrifugal
    /// stretch of the spin the push leaves (up to about 2 rad/s off the rotated box): a particle r = 0.35 m from the
    /// axis needs the pull (1 − β)ω²δ = Ω²r, δ ≈ 1 mm for one cluster. The RMS distance from the rest shape is asserted
    /// below 1 % of the size (4 mm), room for overlapping clusters, which are softer than one; a torn or folded body is
    /// off by tens of percent. The volume ratio must agree with that shape error: a linear fit whose rest-shape residual
    /// has RMS e has ‖F − R‖ ≤ e / σ_min (σ_min the smallest RMS radius of the rest shape along an axis), so
    /// |det F − 1| ≤ (1 + e/σ_min)³ − 1.</para>
    /// </summary>
    public class ShapeMatchingDepenetrationTests
    {
        public enum Spawn { InsideSphere, InsideRotatedBox }

        [Test]
        public void BodySpawnedInsideCollider_LeavesAtBoundedSpeedAndRecovers(
            [Values] Spawn spawn,
            [Values(1f, 4f)] float maxDepenetrationSpeed,
            [Values(1f / 30f, 1f / 120f)] float dt,
            [Values(5, 3)] int clusterSize)
        {
            var model = LatticeBody.Create(new int3(5, 5, 5), 0.1f, clusterSize, 1f);
            var p = ShapeMatchingParameters.Default;
            p.Body.Acceleration = float3.zero;
            p.Body.SleepSpeed = 0f;
            p.Body.MaxDepenetrationSpeed = maxDepenetrationSpeed;
            quaternion rotation = quaternion.AxisAngle(math.normalize(new float3(1f, 0.5f, 2f)), 0.4f);
            var center = new float3(1f, 2f, 3f);
            ColliderShape collider;
            float3 start;
            if (spawn == Spawn.InsideSphere)
            {
                // Sphere of radius 0.3 m whose centre lies 0.25 m off the body's centre: all of the body is on one side of it.
                collider = ColliderShape.Sphere(center, 0.3f);
                start = center + math.normalize(new float3(1f, 0.3f, -0.2f)) * 0.25f;
            }
            else
            {
                // A 0.6 m thick rotated slab holding the lower three layers of the body (0.05 to 0.25 m into it), at least
                // 0.3 m from its other faces: the top face is the nearest for all of them.
                collider = ColliderShape.Box(center, rotation, new float3(0.6f, 0.3f, 0.5f));
                start = center + math.rotate(rotation, new float3(0.05f, 0.25f, 0f));
            }
            var colliders = new[] { collider };
            var body = new ShapeMatchingInstance(model, p, start, rotation);
            float radius = p.Body.ParticleRadius;
            double d0 = 0, overlapMoment = 0;
            for (int i = 0; i < body.Positions.Length; i++)
            {
                double d = ColliderDistance.Overlap(collider, body.Positions[i], radius);
                d0 = Math.Max(d0, d);
                overlapMoment += model.Masses[i] * d * d;
            }
            Assert.That(d0, Is.GreaterThan(0.2), "the body starts deep inside");

            double omega = p.AngularFrequency;
            double vd = maxDepenetrationSpeed;
            double speedBound = vd + Math.Sqrt(vd * vd + omega * omega * d0 * d0);
            double mass = 0;
            foreach (float m in model.Masses)
                mass += m;
            double energyBound = 0.5 * mass * (2.0 * vd) * (2.0 * vd) + 0.5 * omega * omega * overlapMoment;
            int steps = (int)math.round(2f / dt);
            double worstSpeed = 0, worstEnergy = 0;
            for (int step = 0; step < steps; step++)
            {
                Assert.That(body.Step(dt, colliders).Reset, Is.False, $"step {step}");
                double energy = 0;
                for (int i = 0; i < body.Positions.Length; i++)
                {
                    double speed = math.length(body.Velocities[i]);
                    worstSpeed = Math.Max(worstSpeed, speed);
                    energy += 0.5 * model.Masses[i] * speed * speed;
                }
                worstEnergy = Math.Max(worstEnergy, energy);
            }
            Assert.That(worstSpeed, Is.LessThanOrEqualTo(speedBound), "largest particle speed (m/s)");
            Assert.That(worstEnergy, Is.LessThanOrEqualTo(energyBound), "largest kinetic energy (J)");
            foreach (float3 x in body.Positions)
                Assert.That(ColliderDistance.Overlap(collider, x, radius), Is.LessThanOrEqualTo(1e-5), "ends outside the collider");

            var view = model.AsModel();
            double size = BodyMeasures.RestSize(view);
            double shapeError = BodyMeasures.ShapeError(body.Positions, view);
            Assert.That(shapeError / size, Is.LessThanOrEqualTo(0.01), "RMS distance from the rest shape / size");
            double sigmaMin = math.sqrt(0.02f); // RMS of {−0.2, −0.1, 0, 0.1, 0.2} m along each axis
            double volumeBound = Math.Pow(1.0 + shapeError / sigmaMin, 3) - 1.0;
            Assert.That(Math.Abs(BodyMeasures.VolumeRatio(body.Positions, view) - 1.0), Is.LessThanOrEqualTo(volumeBound), "volume ratio");
        }
    }
}
