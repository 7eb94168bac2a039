using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Lavapipe;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Compute
{
    /// <summary>
    /// Whole steps on the GPU against FluidSolver.Step. A fluid is chaotic: round-off differences grow, so after many
    /// steps the two runs agree only statistically. The yardstick is the CPU's own sensitivity: the same CPU run from
    /// positions moved by about one float32 ulp (1e-7 m). The GPU run must stay as close to the CPU run as that perturbed
    /// CPU run does, within a factor (the GPU's per-pass round-off, up to 1.4e-6 of a field in FluidPassKernelTests, is
    /// larger than one ulp, so it seeds the divergence a little earlier), or within one particle spacing for the front
    /// (the front is the position of one particle, resolved to about a spacing).
    /// </summary>
    public class FluidStepKernelTests
    {
        const int Frames = 200;
        const float FrameSeconds = 1f / 500f;
        /// <summary>The front reaches the far wall (6a) at about T = 3.4, frame 90; it is compared over the first 80 frames.</summary>
        const int FrontFrames = 80;

        sealed class Run
        {
            /// <summary>Bulk front (m) after each of the first <see cref="FrontFrames"/> frames (before the front reaches the far wall).</summary>
            public double[] Front = new double[FrontFrames];
            public double[] Histogram;
            public int Count, Substeps;
        }

        static readonly float s_A = (float)MartinMoyce1952.ColumnWidth, s_Dx = s_A / 10f;
        static readonly float3 s_Domain = new float3(6f * s_A, 3f * s_A, 4f * s_Dx), s_Column = new float3(s_A, 2f * s_A, 4f * s_Dx);

        /// <summary>The dam break at a/10 (as DamBreakScenario sets it up), its column jittered by up to <paramref name="jitter"/> m.</summary>
        static FluidBuffers DamBreak(FluidSolverKind solver, float jitter, out FluidConstants c)
        {
            FluidParameters p = FluidParameters.Default;
            p.Solver = solver;
            p.MaxSubsteps = FluidParameters.SubstepLimit;
            FluidBuffers b = FluidScene.BlockInBox(p, s_Dx, s_Domain, s_Column, out c);
            if (jitter > 0f)
            {
                var random = new Unity.Mathematics.Random(5u);
                for (int i = 0; i < b.Status.Count; i++)
                    b.Positions[i] += random.NextFloat3(-jitter, jitter);
            }
            return b;
        }

        /// <summary>Histogram of ρ/ρ₀ over [0.8, 1.2] in 20 bins (fractions of the particles), and the bulk front.</summary>
        static Run Measure(FluidBuffers b, in FluidConstants c, int substeps, Run run)
        {
            var h = new double[20];
            int n = b.Status.Count;
            for (int i = 0; i < n; i++)
            {
                int bin = (int)Math.Floor((b.Densities[i] / c.Parameters.RestDensity - 0.8) / 0.02);
                h[Math.Clamp(bin, 0, 19)] += 1.0 / n;
            }
            run.Histogram = h;
            run.Count = n;
            run.Substeps = substeps;
            return run;
        }

        static Run Cpu(FluidSolverKind solver, float jitter)
        {
            FluidBuffers b = DamBreak(solver, jitter, out FluidConstants c);
            int substeps = 0;
            var run = new Run();
            for (int f = 0; f < Frames; f++)
            {
                substeps += FluidSolver.Step(c, ReadOnlySpan<ColliderShape>.Empty, FrameSeconds, b.Particles, b.Scratch, ref b.Status).Substeps;
                if (f < FrontFrames)
                    run.Front[f] = FluidScene.BulkFront(b, c.Parameters.ParticleSpacing, 4);
            }
            return Measure(b, c, substeps, run);
        }

        static Run Gpu(LavapipeDevice device, LavapipeComputeShader shader, FluidSolverKind solver)
        {
            FluidBuffers b = DamBreak(solver, 0f, out FluidConstants c);
            using var g = new LavapipeFluidSolver(device, shader, c, b.Capacity);
            g.Upload(b.Particles, b.Status.Count);
            int substeps = 0;
            var run = new Run();
            FluidBuffers back = null;
            for (int f = 0; f < Frames; f++)
            {
                substeps += g.Step(FrameSeconds, ref b.Status).Substeps;
                if (f < FrontFrames)
                {
                    back = GpuState.Download(g, c, b.Capacity, c.Grid.CellCount);
                    run.Front[f] = FluidScene.BulkFront(back, c.Parameters.ParticleSpacing, 4);
                }
            }
            back = GpuState.Download(g, c, b.Capacity, c.Grid.CellCount);
            return Measure(back, c, substeps, run);
        }

        static double MaxDifference(double[] a, double[] b)
        {
            double d = 0;
            for (int i = 0; i < a.Length; i++)
                d = Math.Max(d, Math.Abs(a[i] - b[i]));
            return d;
        }

        static double L1(double[] a, double[] b)
        {
            double s = 0;
            for (int i = 0; i < a.Length; i++)
                s += Math.Abs(a[i] - b[i]);
            return s;
        }

        /// <summary>The periodic channel with no-slip faces at W/<paramref name="layers"/> (honey, c₀ = 1 m/s), at rest.</summary>
        static FluidBuffers Channel(int layers, out FluidConstants c)
        {
            FluidParameters p = FluidParameters.Default;
            p.SpeedOfSound = 10f * PoiseuilleScenario.PeakSpeed;
            p = PoiseuilleScenario.Channel(p, layers);
            c = new FluidConstants(p);
            var b = new FluidBuffers(PoiseuilleScenario.PeriodicLayers * PoiseuilleScenario.PeriodicLayers * layers, c.Grid);
            FluidScene.FillBlock(b, p.DomainMin, p.DomainMax, p.ParticleSpacing);
            return b;
        }

        /// <summary>
        /// Every layer's mean speed of the GPU run against the CPU run's. The channel is laminar: its viscous solve contracts
        /// differences instead of growing them, so the GPU's per-pass round-off (≤ 1.4e-6 of a field) stays far below a
        /// thousandth of u_max in every layer, while the flow itself is 3 % from the analytic profile and the periodic faces
        /// and no-slip walls, if missing, would change it by tens of per cent.
        /// </summary>
        static void AssertFlowsLikeTheCpu(FluidBuffers cpu, LavapipeFluidSolver g, in FluidConstants c, int layers, string what)
        {
            FluidBuffers gpu = GpuState.Download(g, c, cpu.Capacity, c.Grid.CellCount);
            Assert.AreEqual(cpu.Status.Count, gpu.Status.Count, what);
            var (u, _) = PoiseuilleScenario.MeanProfile(cpu, layers);
            var (v, _) = PoiseuilleScenario.MeanProfile(gpu, layers);
            for (int k = 0; k < layers; k++)
            {
                // Half the analytic mean speed at the layer's centre, 4·u_max·s(1 − s): a flow has started.
                double s = (k + 0.5) / layers;
                Assert.That(u[k], Is.GreaterThan(0.5 * 4 * s * (1 - s) * PoiseuilleScenario.PeakSpeed), $"{what}: layer {k} flows");
                Assert.AreEqual(u[k], v[k], 1e-3 * PoiseuilleScenario.PeakSpeed, $"{what}: layer {k}");
            }
        }

        [Test]
        public void PoiseuilleChannel_FlowsLikeTheCpu()
        {
            // W/5: 320 particles, 1 s.
            const int layers = 5, frames = 60;
            FluidBuffers cpu = Channel(layers, out FluidConstants c);
            FluidBuffers start = Channel(layers, out _);
            using var g = new LavapipeFluidSolver(Lavapipe.Device, Lavapipe.FluidShader, c, cpu.Capacity);
            g.Upload(start.Particles, start.Status.Count);
            for (int f = 0; f < frames; f++)
            {
                FluidSolver.Step(c, ReadOnlySpan<ColliderShape>.Empty, 1f / 60f, cpu.Particles, cpu.Scratch, ref cpu.Status);
                g.Step(1f / 60f, ref start.Status);
            }
            AssertFlowsLikeTheCpu(cpu, g, c, layers, "W/5");
        }

        [Test]
        public void TwoFluidsOnOneShader_StepAlternately_EachLikeItsCpuTwin()
        {
            // Bindings live on the shader, as on a Unity ComputeShader asset: two fluids of different sizes share one and
            // step in turn; each must bind its own buffers, or its kernels run on the other fluid's particles.
            const int frames = 60;
            int[] layers = { 5, 10 };
            var cpu = new FluidBuffers[2];
            var constants = new FluidConstants[2];
            var gpu = new LavapipeFluidSolver[2];
            var status = new FluidStatus[2];
            try
            {
                for (int i = 0; i < 2; i++)
                {
                    cpu[i] = Channel(layers[i], out constants[i]);
                    FluidBuffers start = Channel(layers[i], out _);
                    gpu[i] = new LavapipeFluidSolver(Lavapipe.Device, Lavapipe.FluidShader, constants[i], cpu[i].Capacity);
                    gpu[i].Upload(start.Particles, start.Status.Count);
                    status[i] = start.Status;
                }
                for (int f = 0; f < frames; f++)
                    for (int i = 0; i < 2; i++)
                    {
                        FluidSolver.Step(constants[i], ReadOnlySpan<ColliderShape>.Empty, 1f / 60f, cpu[i].Particles, cpu[i].Scratch, ref cpu[i].Status);
                        gpu[i].Step(1f / 60f, ref status[i]);
                    }
                for (int i = 0; i < 2; i++)
                    AssertFlowsLikeTheCpu(cpu[i], gpu[i], constants[i], layers[i], $"W/{layers[i]}");
            }
            finally
            {
                foreach (LavapipeFluidSolver g in gpu)
                    g?.Dispose();
            }
        }

        [TestCase(FluidSolverKind.WeaklyCompressible)]
        [TestCase(FluidSolverKind.PositionBased)]
        public void DamBreak200Frames_IsStatisticallyTheCpuRun(FluidSolverKind solver)
        {
            float dx = s_Dx;
            Run cpu = Cpu(solver, 0f);
            Run perturbed = Cpu(solver, 1e-7f);
            Run gpu = Gpu(Lavapipe.Device, Lavapipe.FluidShader, solver);
            Lavapipe.AssertValid();
            double frontGpu = MaxDifference(gpu.Front, cpu.Front), frontPerturbed = MaxDifference(perturbed.Front, cpu.Front);
            double histGpu = L1(gpu.Histogram, cpu.Histogram), histPerturbed = L1(perturbed.Histogram, cpu.Histogram);
            TestContext.Out.WriteLine($"{solver}, {cpu.Count} particles, {Frames} frames of {FrameSeconds} s: substeps CPU {cpu.Substeps}, GPU {gpu.Substeps}");
            TestContext.Out.WriteLine($"front over the first {FrontFrames} frames, largest |Δ| to the CPU run (m): GPU {frontGpu:E2}, CPU perturbed by 1e-7 m {frontPerturbed:E2}; spacing {dx:F5}; CPU front at frame {FrontFrames}: {cpu.Front[FrontFrames - 1]:F4}");
            TestContext.Out.WriteLine($"density histogram L1 distance to the CPU run: GPU {histGpu:F4}, CPU perturbed {histPerturbed:F4}");
            Assert.That(gpu.Count, Is.EqualTo(cpu.Count), "no particle lost or gained");
            Assert.That(frontGpu, Is.LessThanOrEqualTo(Math.Max(3 * frontPerturbed, dx)), "front position");
            Assert.That(histGpu, Is.LessThanOrEqualTo(Math.Max(3 * histPerturbed, 0.05)), "density histogram");
            Assert.That(Math.Abs(gpu.Substeps - cpu.Substeps), Is.LessThanOrEqualTo(Math.Max(3 * Math.Abs(perturbed.Substeps - cpu.Substeps), 0.05 * cpu.Substeps)),
                "substeps (they follow the fastest particle, one extreme of a chaotic flow: 5 % of the total is allowed)");
        }

        /// <summary>
        /// Position-based, a deep column at rest (40 layers): the GPU measures its depth along gravity in BeginStep and plans the
        /// depth rule's substeps as the CPU does (more than the one substep the CFL limit alone asks for at rest).
        /// </summary>
        [Test]
        public void DeepPositionBasedColumn_GetsTheCpusDepthSubsteps()
        {
            FluidParameters p = FluidParameters.Default;
            p.Solver = FluidSolverKind.PositionBased;
            float3 domain = new float3(0.12f, 1.2f, 0.12f), column = new float3(0.12f, 0.8f, 0.12f);
            FluidBuffers cpu = FluidScene.BlockInBox(p, 0.02f, domain, column, out FluidConstants c);
            FluidBuffers start = FluidScene.BlockInBox(p, 0.02f, domain, column, out _);
            float depth = FluidSolver.Depth(c, cpu.Positions.AsSpan(0, cpu.Status.Count));
            Assert.That(depth, Is.EqualTo(0.8f).Within(1e-5f), "the column's extent plus one spacing");
            Assert.That(FluidSolver.Substeps(c, 0f, 0f, 1f / 60f).x, Is.EqualTo(1), "the CFL limit alone");
            FluidStepReport expected = FluidSolver.Step(c, ReadOnlySpan<ColliderShape>.Empty, 1f / 60f, cpu.Particles, cpu.Scratch, ref cpu.Status);
            Assert.That(expected.Substeps, Is.GreaterThan(1));
            using var g = new LavapipeFluidSolver(Lavapipe.Device, Lavapipe.FluidShader, c, start.Capacity);
            g.Upload(start.Particles, start.Status.Count);
            FluidStepReport r = g.Step(1f / 60f, ref start.Status);
            Lavapipe.AssertValid();
            Assert.That(r.Substeps, Is.EqualTo(expected.Substeps));
        }

        /// <summary>
        /// A 1 s step of a resting block, capped: the GPU plans it as the CPU does (the cap's substeps of the CFL length, so
        /// it simulates less than dt), ages every particle by the simulated time, and keeps the fluid below the
        /// over-compression bound.
        /// </summary>
        [Test]
        public void HugeStep_RunsInSlowMotionLikeTheCpu()
        {
            FluidParameters p = FluidParameters.Default;
            FluidBuffers cpu = FluidScene.BlockInBox(p, 0.02f, new float3(0.2f, 0.4f, 0.2f), new float3(0.2f, 0.2f, 0.2f), out FluidConstants c);
            FluidBuffers start = FluidScene.BlockInBox(p, 0.02f, new float3(0.2f, 0.4f, 0.2f), new float3(0.2f, 0.2f, 0.2f), out _);
            FluidStepReport expected = FluidSolver.Step(c, ReadOnlySpan<ColliderShape>.Empty, 1f, cpu.Particles, cpu.Scratch, ref cpu.Status);
            Assert.That(expected.Substeps, Is.LessThan(expected.SubstepsWanted), "the step must be capped");
            using var g = new LavapipeFluidSolver(Lavapipe.Device, Lavapipe.FluidShader, c, start.Capacity);
            g.Upload(start.Particles, start.Status.Count);
            FluidStepReport r = g.Step(1f, ref start.Status);
            Lavapipe.AssertValid();
            Assert.That(r.Substeps, Is.EqualTo(expected.Substeps));
            Assert.That(r.SubstepsWanted, Is.EqualTo(expected.SubstepsWanted));
            Assert.That(r.SimulatedTime, Is.EqualTo(expected.SimulatedTime));
            Assert.That(start.Status.Time, Is.EqualTo(cpu.Status.Time));
            Assert.That(r.MaxDensityRatio, Is.LessThanOrEqualTo(p.MaxDensityRatio));
            FluidBuffers back = GpuState.Download(g, c, start.Capacity, c.Grid.CellCount);
            for (int i = 0; i < back.Status.Count; i++)
                Assert.That(back.Ages[i], Is.EqualTo(expected.SimulatedTime), $"particle {i}");
        }

        [TestCase(0)]
        [TestCase(1)]
        [TestCase(65)]
        public void Step_OddCounts_KeepEveryParticleAndStayFinite(int count)
        {
            DamBreak(FluidSolverKind.WeaklyCompressible, 0f, out FluidConstants c);
            var b = new FluidBuffers(Math.Max(count, 1), c.Grid);
            var random = new Unity.Mathematics.Random(11u);
            for (int i = 0; i < count; i++)
            {
                b.Positions[i] = random.NextFloat3(new float3(0.1f), new float3(0.2f, 0.2f, 0.02f));
                b.Ids[i] = i;
            }
            b.Status.Count = count;
            using var g = new LavapipeFluidSolver(Lavapipe.Device, Lavapipe.FluidShader, c, Math.Max(count, 1));
            g.Upload(b.Particles, count);
            for (int f = 0; f < 5; f++)
                g.Step(1f / 60f, ref b.Status);
            Lavapipe.AssertValid();
            FluidBuffers back = GpuState.Download(g, c, Math.Max(count, 1), c.Grid.CellCount);
            Assert.That(back.Status.Count, Is.EqualTo(count));
            for (int i = 0; i < count; i++)
                Assert.That(math.all(math.isfinite(back.Positions[i])) && math.all(back.Positions[i] >= c.Parameters.DomainMin)
                    && math.all(back.Positions[i] <= c.Parameters.DomainMax), Is.True, $"particle {i} at {back.Positions[i]}");
        }
    }
}
