using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// The Jelly and Sphere sample without Unity: the same bodies (1 m cubes and a 1 m sphere built from
    /// meshes by <see cref="SoftBodyBuilder"/> with interior particles every 0.2 m and 0.5 m clusters,
    /// Jelly and Rubber preset values), the same drop heights (4–7 m, up to 11.7 m/s at impact), the
    /// same staircase of boxes and the floor plane, stepped at 60 Hz with the default 4 substeps.
    /// Contacts are resolved last in each substep, so at the end of every step no particle may be
    /// inside a collider beyond round-off (1e-5 m): no tunnelling, at any of the sample's speeds. The overlap is
    /// measured independently of the solver's contact code, by a float64 signed distance (<see cref="ColliderDistance"/>).
    /// </summary>
    public class JellyAndSphereSceneTests
    {
        const float k_Tolerance = 1e-5f;

        static ShapeMatchingParameters Jelly() => ShapeMatchingMaterial.Jelly.ApplyTo(ShapeMatchingParameters.Default);

        static ShapeMatchingParameters Rubber() => ShapeMatchingMaterial.Rubber.ApplyTo(ShapeMatchingParameters.Default);

        static ShapeMatchingModelData Build(float3[] vertices, int[] triangles, float mass)
        {
            var settings = SoftBodyBuildSettings.Default;
            settings.AddInteriorParticles = true;
            settings.InteriorSpacing = 0.2f;
            settings.ClusterSize = 0.5f;
            settings.TotalMass = mass;
            SoftBodyBuildResult result = SoftBodyBuilder.Build(vertices, triangles, settings);
            Assert.That(result.Succeeded, Is.True, string.Join("\n", result.Issues.ConvertAll(i => i.Message)));
            return result.Model;
        }

        static ColliderShape[] Colliders()
        {
            var list = new List<ColliderShape> { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            float[] x = { 0f, 1.5f, 3f, 4.5f }, height = { 2f, 1.5f, 1f, 0.5f };
            for (int i = 0; i < x.Length; i++)
                list.Add(ColliderShape.Box(new float3(x[i], 0.5f * height[i], 0f), quaternion.identity, new float3(0.75f, 0.5f * height[i], 1.5f)));
            return list.ToArray();
        }

        [Test]
        public void SampleBodies_NeverTunnelAndCubesComeToRest()
        {
            TestMeshes.UnityCube(out float3[] cubeVertices, out int[] cubeTriangles);
            TestMeshes.UvSphere(12, 24, out float3[] sphereVertices, out int[] sphereTriangles);
            for (int i = 0; i < sphereVertices.Length; i++)
                sphereVertices[i] *= 0.5f;
            ShapeMatchingModelData cube = Build(cubeVertices, cubeTriangles, 1f);
            ShapeMatchingModelData sphere = Build(sphereVertices, sphereTriangles, 0.5f);
            var bodies = new[]
            {
                new ShapeMatchingInstance(cube, Jelly(), new float3(0.6f, 4f, -0.7f), quaternion.identity),
                new ShapeMatchingInstance(cube, Jelly(), new float3(2.1f, 5.5f, 0.6f), quaternion.AxisAngle(math.normalize(new float3(1f, 2f, 0f)), 0.4f)),
                new ShapeMatchingInstance(cube, Jelly(), new float3(-0.2f, 7f, 0.2f), quaternion.AxisAngle(math.normalize(new float3(1f, 2f, 1f)), 0.6f)),
                new ShapeMatchingInstance(sphere, Rubber(), new float3(3.6f, 6f, -0.5f), quaternion.identity),
            };
            ColliderShape[] colliders = Colliders();
            float radius = ShapeMatchingParameters.Default.Body.ParticleRadius;
            for (int step = 0; step < 1800; step++)
            {
                foreach (ShapeMatchingInstance body in bodies)
                {
                    ShapeMatchingStepReport report = body.Step(1f / 60f, colliders);
                    Assert.That(report.Reset, Is.False, $"step {step}");
                    // The deepest overlap of the step, asserted once per body and step (one assertion per particle and collider
                    // cost more than the simulation).
                    double deepest = 0;
                    int deepestCollider = 0;
                    foreach (float3 x in body.Positions)
                        for (int c = 0; c < colliders.Length; c++)
                        {
                            double overlap = ColliderDistance.Overlap(colliders[c], x, radius);
                            if (overlap > deepest)
                            {
                                deepest = overlap;
                                deepestCollider = c;
                            }
                        }
                    Assert.That(deepest, Is.LessThanOrEqualTo(k_Tolerance), $"step {step}, {colliders[deepestCollider].Type} at {colliders[deepestCollider].Center}");
                }
            }
            for (int b = 0; b < bodies.Length; b++)
            {
                // The jelly cubes come to rest and sleep within 30 s; the sphere rolls on (no rolling resistance).
                if (b < 3)
                    Assert.That(bodies[b].Status.Asleep, Is.True, $"cube {b} sleeps within 30 s");
                var view = bodies[b].Model.AsModel();
                // At rest under gravity a soft body sags; it must still be close to its shape (< 10% of its size).
                Assert.That(BodyMeasures.ShapeError(bodies[b].Positions, view) / BodyMeasures.RestSize(view), Is.LessThan(0.1));
            }
        }
    }
}
