using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// <see cref="FluidColliderReach"/>: a substep keeps exactly the colliders within kernel radius + v_max·h of the
    /// particles' box, and leaving the others out changes no bit of the step.
    /// </summary>
    public class FluidColliderReachTests
    {
        // A 0.24 m water block resting in a box it fills (the EffectCost scene), Δx = 2 cm, h_kernel = 4 cm.
        static FluidBuffers Water(FluidSolverKind solver, out FluidConstants c)
        {
            FluidParameters p = FluidParameters.Default;
            p.Solver = solver;
            return FluidScene.BlockInBox(p, 0.02f, new float3(0.24f, 0.5f, 0.24f), new float3(0.24f), out c);
        }

        static readonly ColliderShape s_InTheWater = ColliderShape.Sphere(new float3(0.12f, 0.1f, 0.12f), 0.03f);

        [Test]
        public void Near_KeepsWhatTheSubstepCanTouch()
        {
            FluidBuffers b = Water(FluidSolverKind.WeaklyCompressible, out FluidConstants c);
            float h = 1e-3f;
            // Particle centres span [0.01, 0.23] on every axis; the reach is 0.04 + 50 m/s × 1 ms = 0.09 m: up to y = 0.32.
            var colliders = new[]
            {
                ColliderShape.Sphere(new float3(0.12f, 0.35f, 0.12f), 0.0299f),                          // bottom at 0.3201: out
                ColliderShape.Sphere(new float3(0.12f, 0.35f, 0.12f), 0.0301f),                          // bottom at 0.3199: in
                s_InTheWater,
                ColliderShape.Box(new float3(0.12f, 0.45f, 0.12f), quaternion.identity, new float3(0.05f, 0.01f, 0.05f)), // out
                ColliderShape.Box(new float3(0.12f, 0.45f, 0.12f), quaternion.AxisAngle(new float3(1f, 0f, 0f), math.PI / 2f),
                    new float3(0.05f, 0.05f, 0.2f)),                                                     // long axis turned up: reaches 0.25, in
                ColliderShape.Capsule(new float3(0.5f, 0.1f, 0f), new float3(0.5f, 0.1f, 0.2f), 0.1f),    // x from 0.4: out
                ColliderShape.Capsule(new float3(0.5f, 0.1f, 0f), new float3(0.5f, 0.1f, 0.2f), 0.2f),    // x from 0.3: in
                ColliderShape.Plane(new float3(0f, -0.1f, 0f), new float3(0f, 1f, 0f)),                   // solid below y = -0.1: out
                ColliderShape.Plane(new float3(0f, -0.05f, 0f), new float3(0f, 1f, 0f)),                  // below y = -0.05: in
                ColliderShape.Plane(new float3(0f, 0.5f, 0f), new float3(0f, 1f, 0f)),                    // solid below 0.5: in
            };
            var near = new ColliderShape[colliders.Length];
            int n = FluidColliderReach.Near(c, colliders, new ReadOnlySpan<float3>(b.Positions, 0, b.Status.Count), h, near);
            int[] kept = { 1, 2, 4, 6, 8, 9 };
            Assert.That(n, Is.EqualTo(kept.Length));
            for (int k = 0; k < kept.Length; k++)
                Assert.That(near[k], Is.EqualTo(colliders[kept[k]]), $"kept in order: collider {kept[k]}");

            FluidBuffers pb = Water(FluidSolverKind.PositionBased, out FluidConstants pc);
            Assert.That(FluidColliderReach.Near(pc, colliders, new ReadOnlySpan<float3>(pb.Positions, 0, pb.Status.Count), h, near),
                Is.EqualTo(colliders.Length), "position-based corrections have no bound: every collider stays");
        }

        [Test]
        public void CulledStep_HasTheBitsOfTheStepWithEveryCollider()
        {
            // Far colliders only add to the list: past MaxCulled the step keeps every one, so the two runs differ only in the culling.
            ColliderShape far = ColliderShape.Box(new float3(0.12f, 0.45f, 0.12f), quaternion.identity, new float3(0.05f, 0.01f, 0.05f));
            var few = new[] { far, s_InTheWater, far };
            var many = new ColliderShape[FluidColliderReach.MaxCulled + 2];
            for (int k = 0; k < many.Length; k++)
                many[k] = far;
            many[1] = s_InTheWater;
            FluidBuffers a = Water(FluidSolverKind.WeaklyCompressible, out FluidConstants c);
            FluidBuffers b = Water(FluidSolverKind.WeaklyCompressible, out _);
            for (int f = 0; f < 20; f++)
            {
                FluidSolver.Step(c, few, 1f / 60f, a.Particles, a.Scratch, ref a.Status);
                FluidSolver.Step(c, many, 1f / 60f, b.Particles, b.Scratch, ref b.Status);
            }
            Assert.That(a.Status.Count, Is.EqualTo(b.Status.Count));
            Assert.That(new ReadOnlySpan<float3>(a.Positions, 0, a.Status.Count).ToArray(), Is.EqualTo(new ReadOnlySpan<float3>(b.Positions, 0, b.Status.Count).ToArray()));
            Assert.That(new ReadOnlySpan<float3>(a.Velocities, 0, a.Status.Count).ToArray(), Is.EqualTo(new ReadOnlySpan<float3>(b.Velocities, 0, b.Status.Count).ToArray()));
        }
    }
}
