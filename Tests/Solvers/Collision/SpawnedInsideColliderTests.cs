using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// A body spawned around a collider leaves it whole, along one direction, at the depenetration speed — for every method
    /// of the study — instead of each particle leaving by its own nearest face and the body ending wrapped around the
    /// collider. Fluids (no <see cref="ContactProjection.Settings.WholeBody"/>) keep pushing each particle on its own.
    /// </summary>
    public class SpawnedInsideColliderTests
    {
        /// <summary>Edge of the jelly cube (m), 4 cells of 6 tetrahedra: 125 particles 5 cm apart.</summary>
        const float k_Size = 0.2f;
        /// <summary>The depenetration speed (m/s) of the study's bodies: every method's default (shape matching's, mass-spring's and FEM's are equal).</summary>
        static readonly float k_MaxDepenetrationSpeed = ShapeMatchingParameters.Default.Body.MaxDepenetrationSpeed;

        /// <summary>Colliders off the cube's centre by 1 cm, that hold 27 of its 125 particles.</summary>
        static ColliderShape Collider(string shape) => shape switch
        {
            "box" => ColliderShape.Box(new float3(0.01f, 0f, 0f), quaternion.identity, new float3(0.08f)),
            "sphere" => ColliderShape.Sphere(new float3(0.01f, 0f, 0f), 0.09f),
            _ => ColliderShape.Capsule(new float3(0.01f, -0.03f, 0f), new float3(0.01f, 0.03f, 0f), 0.075f),
        };

        /// <summary>Mass-weighted RMS distance of the particles from their centre of mass (m), in double.</summary>
        static double RmsRadius(IMethodBody b)
        {
            Vector3d c = BodyMeasures.Center(b.Positions, b.Masses);
            double s = 0, m = 0;
            for (int i = 0; i < b.ParticleCount; i++)
            {
                Vector3d d = (Vector3d)b.Positions[i] - c;
                s += b.Masses[i] * Vector3d.Dot(d, d);
                m += b.Masses[i];
            }
            return Math.Sqrt(s / m);
        }

        static string[] Methods()
        {
            var names = new string[MethodCatalog.Variants.Count];
            for (int k = 0; k < names.Length; k++)
                names[k] = MethodCatalog.Variants[k].Family;
            return names;
        }

        /// <summary>
        /// 2 s without gravity. A body wrapped around the collider (its inner particles pushed out on the collider's surface)
        /// has an RMS radius 7–12 % above its rest one (box and sphere with the per-particle push, every method but Neo-Hookean
        /// implicit FEM, which the guard reset instead);
        /// one that left whole is back at rest size — within 1e-4 for every method and shape here — so 3 % separates the two.
        /// The whole body moves at the depenetration speed; the shallow particles' own push-out and the elastic recoil it
        /// starts add to it (up to 1.51× the cap here for linear co-rotational implicit FEM against the box, 2.28× for quadratic
        /// Neo-Hookean implicit FEM in its first step, 1.87× for quadratic co-rotational); the per-particle push let the hybrid
        /// body reach 17–21× the cap and Neo-Hookean implicit FEM 215× (then reset). The 2.5× bound is a regression guard above
        /// those measured recoils, not a derived limit: what it separates is a capped push-out from an uncapped one.
        /// </summary>
        [Test]
        public void BodySpawnedAroundACollider_LeavesItWhole([ValueSource(nameof(Methods))] string family, [Values("box", "sphere", "capsule")] string shape)
        {
            MethodVariant v = null;
            foreach (MethodVariant candidate in MethodCatalog.Variants)
                if (candidate.Family == family)
                    v = candidate;
            TetrahedralMesh mesh = BoxTetrahedra.Create(new float3(k_Size), new int3(4), float3.zero);
            var setup = new MethodBodySetup
            {
                Mesh = mesh, Material = ElasticMaterial.Jelly, CalibrationLength = k_Size, CalibrationLoad = ShapeMatchingCalibration.Load.Compression,
            };
            IMethodBody body = v.Create(setup, v.Knobs[0], k_Size / 4);
            body.Place();
            double rest = RmsRadius(body);
            ColliderShape collider = Collider(shape);
            var colliders = new[] { collider };
            double fastest = 0;
            for (int k = 0; k < 120; k++)
            {
                body.Step(1f / 60f, float3.zero, colliders);
                foreach (float3 velocity in body.Velocities)
                    fastest = Math.Max(fastest, math.length(velocity));
            }
            Assert.AreEqual(0, body.Resets, "no reset");
            Assert.That(RmsRadius(body) / rest, Is.InRange(0.97, 1.03), "the body's size");
            Assert.That(fastest, Is.LessThanOrEqualTo(2.5 * k_MaxDepenetrationSpeed), "the depenetration speed");
            for (int i = 0; i < body.ParticleCount; i++)
                Assert.That(ParticleCollision.Penetration(collider, body.Positions[i], 0f, out _, out _), Is.False, $"particle {i} is out");
        }

        /// <summary>Particles around a sphere's centre: one body leaves along one direction, fluid particles each radially.</summary>
        [Test]
        public void WholeBody_LeavesAlongOneDirection_FluidParticlesEachOnTheirOwn()
        {
            var sphere = ColliderShape.Sphere(new float3(0f, -0.02f, 0f), 0.5f);
            var start = new[] { new float3(-0.1f, 0f, 0f), new float3(0.1f, 0f, 0f), new float3(0f, 0.1f, 0f), new float3(0f, 0f, -0.1f) };
            float h = 1f / 240f;
            foreach (bool wholeBody in new[] { true, false })
            {
                var x = (float3[])start.Clone();
                var v = new float3[4];
                var normals = new float3[4];
                var settings = new ContactProjection.Settings { Radius = 0.01f, MaxDepenetration = 0.01f, WholeBody = wholeBody };
                ContactProjection.Project(start, x, v, normals, new[] { sphere }, settings, h);
                for (int i = 0; i < 4; i++)
                {
                    float3 moved = x[i] - start[i];
                    // One body: the sphere's outward direction at the particles' centroid (0, 0.025, −0.025); fluid: each its own.
                    float3 expected = math.normalize((wholeBody ? new float3(0f, 0.025f, -0.025f) : start[i]) - sphere.Center);
                    Assert.That(math.length(math.cross(moved, expected)), Is.LessThan(1e-6f), $"whole body {wholeBody}, particle {i}: along {expected}");
                    Assert.That(math.length(moved), Is.EqualTo(0.01f).Within(1e-6f), "by the depenetration cap");
                    Assert.That(math.dot(v[i], expected) * h, Is.EqualTo(0.01f).Within(1e-6f), "at the capped speed");
                }
            }
        }

        /// <summary>A plane pushes every particle along its normal: the whole-body rule leaves it as it was.</summary>
        [Test]
        public void Plane_PushesEachParticleOnItsOwn_WholeBodyOrNot()
        {
            var floor = ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f));
            var start = new[] { new float3(0f, -0.2f, 0f), new float3(0.3f, 0.1f, 0f) };
            var results = new float3[2][];
            foreach (bool wholeBody in new[] { true, false })
            {
                var x = (float3[])start.Clone();
                var settings = new ContactProjection.Settings { Radius = 0.01f, MaxDepenetration = 0.01f, WholeBody = wholeBody };
                ContactProjection.Project(start, x, new float3[2], new float3[2], new[] { floor }, settings, 1f / 240f);
                results[wholeBody ? 0 : 1] = x;
            }
            Assert.AreEqual(results[1], results[0]);
            Assert.AreEqual(-0.19f, results[0][0].y, 1e-6f, "the deep particle rises by the cap");
            Assert.AreEqual(start[1], results[0][1], "the free particle stays");
        }
    }
}
