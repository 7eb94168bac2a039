using System;
using NUnit.Framework;
using SoftBodyDynamics.Lavapipe;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Compute
{
    /// <summary>
    /// Whole frames with a tap, colliders and a drain: the GPU frame (drain kernel, tap spawns staged by
    /// FluidComputeEmission and appended by Emit, the step with the Collide pass) against FluidFrame.Advance. As in
    /// FluidStepKernelTests the yardstick is the CPU's own sensitivity, here to moving the tap by 1e-6 m (which two seconds
    /// do not fully decorrelate), with floors for statistics of a few hundred particles: 2√N for counts (removals are
    /// discrete events of a chaotic flow) and, for the mean height, three standard errors of the difference of the two
    /// means, computed from the runs' own spread of heights.
    /// </summary>
    public class FluidFrameKernelTests
    {
        const int Frames = 120;
        const float Frame = 1f / 60f;

        sealed class Outcome
        {
            public long Alive, Spawned, Killed, Expired, HeldBack;
            public double MeanHeight, HeightStandardError;
        }

        static FluidConstants Constants()
        {
            FluidParameters p = FluidParameters.Default;
            p.ParticleSpacing = 0.02f;
            p.DomainMin = new float3(-0.2f, 0f, -0.2f);
            p.DomainMax = new float3(0.2f, 0.5f, 0.2f);
            p.Gravity = new float3(0f, -9.81f, 0f);
            p.WallFriction = 0.2f;
            p.DomainFriction = new float3(0.2f);
            return new FluidConstants(p);
        }

        static FluidTapInstance[] Taps(float offset)
        {
            FluidTapSettings s = FluidTapSettings.Default;
            s.Position = new float3(offset, 0.42f, 0f);
            s.Rotation = quaternion.AxisAngle(new float3(1f, 0f, 0f), math.PI / 2f);
            s.Radius = 0.04f;
            s.Rate = 300f;
            s.Speed = 0.5f;
            s.Lifetime = 1.5f;
            s.LifetimeRandom = 0.3f;
            return new[] { new FluidTapInstance { Settings = s } };
        }

        static readonly ColliderShape[] s_Colliders =
        {
            ColliderShape.Sphere(new float3(0f, 0.2f, 0f), 0.06f),
            ColliderShape.Box(new float3(-0.1f, 0.05f, 0f), quaternion.AxisAngle(new float3(0f, 0f, 1f), 0.4f), new float3(0.05f, 0.02f, 0.1f)),
        };

        static readonly FluidDrain[] s_Drains = { new FluidDrain { Shape = ColliderShape.Box(new float3(0.17f, 0f, 0f), quaternion.identity, new float3(0.03f, 0.05f, 0.2f)) } };

        static Outcome Finish(FluidBuffers b, in FluidStatus status, int heldBack)
        {
            int n = status.Count;
            double height = 0, square = 0;
            for (int i = 0; i < n; i++)
            {
                height += b.Positions[i].y;
                square += (double)b.Positions[i].y * b.Positions[i].y;
            }
            double mean = n > 0 ? height / n : 0;
            double variance = n > 1 ? Math.Max(0, (square - n * mean * mean) / (n - 1)) : 0;
            return new Outcome
            {
                Alive = n, Spawned = status.Spawned, Killed = status.Killed, Expired = status.Expired, HeldBack = heldBack,
                MeanHeight = mean, HeightStandardError = n > 0 ? Math.Sqrt(variance / n) : 0,
            };
        }

        static Outcome Cpu(in FluidConstants c, float offset)
        {
            var b = new FluidBuffers(4000, c.Grid);
            FluidTapInstance[] taps = Taps(offset);
            int heldBack = 0;
            for (int f = 0; f < Frames; f++)
                heldBack += FluidFrame.Advance(c, s_Colliders, s_Drains, taps, default, 0, Frame, b.Particles, b.Scratch, ref b.Status).HeldBack;
            return Finish(b, b.Status, heldBack);
        }

        static Outcome Gpu(in FluidConstants c)
        {
            var staging = new FluidBuffers(4000, c.Grid);
            FluidTapInstance[] taps = Taps(0f);
            var status = new FluidStatus();
            int heldBack = 0;
            using var g = new LavapipeFluidSolver(Lavapipe.Device, Lavapipe.FluidShader, c, 4000);
            g.SetShapes(s_Colliders, s_Drains);
            g.Upload(staging.Particles, 0);
            for (int f = 0; f < Frames; f++)
            {
                g.Drain();
                FluidFrameReport r = FluidComputeEmission.Stage(c, taps, default, 4000 - g.Count, Frame, staging.Particles, staging.Scratch, ref status, out int spawned);
                heldBack += r.HeldBack;
                g.Emit(staging.Particles, spawned);
                g.Step(Frame, ref status);
            }
            FluidBuffers back = GpuState.Download(g, c, g.Capacity, c.Grid.CellCount);
            return Finish(back, status, heldBack);
        }

        [Test]
        public void TapOntoCollidersWithADrain_IsStatisticallyTheCpuFrame()
        {
            FluidConstants c = Constants();
            Outcome cpu = Cpu(c, 0f), perturbed = Cpu(c, 1e-6f), gpu = Gpu(c);
            Lavapipe.AssertValid();
            foreach (var (name, o) in new[] { ("CPU", cpu), ("CPU, tap moved 1e-6 m", perturbed), ("GPU", gpu) })
                TestContext.Out.WriteLine($"{name}: alive {o.Alive}, spawned {o.Spawned}, killed {o.Killed}, expired {o.Expired}, held back {o.HeldBack}, mean height {o.MeanHeight:F4} m");
            Assert.That(cpu.Killed, Is.GreaterThan(0), "the drain took particles");
            Assert.That(cpu.Expired, Is.GreaterThan(0), "lifetimes ran out");
            Assert.That(gpu.Spawned, Is.EqualTo(cpu.Spawned).Within(cpu.HeldBack + gpu.HeldBack), "the tap's schedule");
            AssertCount("alive", gpu.Alive, cpu.Alive, perturbed.Alive);
            AssertCount("killed", gpu.Killed, cpu.Killed, perturbed.Killed);
            AssertCount("expired", gpu.Expired, cpu.Expired, perturbed.Expired);
            // Two independent samples of a chaotic flow: their means differ by less than 3 standard errors of the difference.
            double heightFloor = 3 * Math.Sqrt(gpu.HeightStandardError * gpu.HeightStandardError + cpu.HeightStandardError * cpu.HeightStandardError);
            TestContext.Out.WriteLine($"mean heights: |GPU − CPU| {Math.Abs(gpu.MeanHeight - cpu.MeanHeight) * 1e3:F2} mm, 3 standard errors of the difference {heightFloor * 1e3:F2} mm");
            Assert.That(Math.Abs(gpu.MeanHeight - cpu.MeanHeight),
                Is.LessThanOrEqualTo(Math.Max(3 * Math.Abs(perturbed.MeanHeight - cpu.MeanHeight), heightFloor)), "mean height");
            Assert.That(gpu.Alive, Is.EqualTo(gpu.Spawned - gpu.Killed - gpu.Expired), "the GPU's count identity (no invalid particle)");
        }

        static void AssertCount(string what, long gpu, long cpu, long perturbed) =>
            Assert.That(Math.Abs(gpu - cpu), Is.LessThanOrEqualTo(Math.Max(3 * Math.Abs(perturbed - cpu), 2 * Math.Sqrt(Math.Max(cpu, 1)))), what);
    }
}
