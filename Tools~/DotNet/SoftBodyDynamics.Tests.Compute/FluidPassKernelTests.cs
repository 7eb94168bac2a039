using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Lavapipe;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Compute
{
    /// <summary>
    /// Every kernel of a substep against its C# pass, from the same input (the CPU state uploaded before each pass).
    /// Tolerance: a pass output is a sum over at most 64 neighbour terms of at most about 30 float operations each; two
    /// evaluations that differ only in rounding (Vulkan lets the driver contract a·b + c into one FMA and allows a few ulp
    /// in division and square root) differ by at most 2·γₙ·Σ|tᵢ| with γₙ = n·u/(1 − n·u), n ≈ 94, u = 2⁻²⁴, that is
    /// 1.1e-5·Σ|tᵢ|. Σ|tᵢ| is bounded here by 8 times the field's largest value (pressure and force sums cancel by less than
    /// that in these scenes), so outputs must agree within 1e-4 of the field's scale. Neighbour lists must agree exactly.
    /// </summary>
    public class FluidPassKernelTests
    {
        const double RelativeTolerance = 1e-4;

        static FluidParameters Scene(string setting)
        {
            FluidParameters p = FluidParameters.Default;
            p.ParticleSpacing = 0.02f;
            p.DomainMin = float3.zero;
            p.DomainMax = new float3(0.4f, 0.4f, 0.16f);
            p.Gravity = new float3(0f, -9.81f, 0f);
            switch (setting)
            {
                case "WCSPH":
                    break;
                case "WCSPH viscosity flocking":
                    p.Viscosity = 0.01f;
                    p.ViscosityIterations = 3;
                    p.Cohesion = FluidCohesionModel.Flocking;
                    p.CohesionWeight = 50f;
                    p.SeparationWeight = 20f;
                    p.AlignmentRate = 5f;
                    break;
                case "WCSPH Akinci":
                    p.Cohesion = FluidCohesionModel.Akinci;
                    p.SurfaceTension = 0.1f;
                    break;
                case "WCSPH colliders":
                case "PBF colliders":
                    p.Solver = setting.StartsWith("PBF") ? FluidSolverKind.PositionBased : FluidSolverKind.WeaklyCompressible;
                    p.WallFriction = 0.3f;
                    p.DomainFriction = new float3(0.1f, 0.3f, 0.2f);
                    break;
                case "WCSPH colliders no-slip viscosity":
                    p.WallFriction = 0.3f;
                    p.WallNoSlip = 1f;
                    p.DomainNoSlip = new float3(0.5f, 1f, 0f);
                    p.Viscosity = 0.01f;
                    p.ViscosityIterations = 3;
                    break;
                case "WCSPH periodic no-slip viscosity":
                case "PBF periodic no-slip viscosity":
                    // Periodic along x and z (the block spans z, so particles meet across its faces), a no-slip floor.
                    p.Solver = setting.StartsWith("PBF") ? FluidSolverKind.PositionBased : FluidSolverKind.WeaklyCompressible;
                    p.Periodic = new bool3(true, false, true);
                    p.DomainNoSlip = new float3(0f, 1f, 0f);
                    p.Viscosity = 0.01f;
                    p.ViscosityIterations = 3;
                    break;
                case "PBF Akinci viscosity":
                    p.Solver = FluidSolverKind.PositionBased;
                    p.PressureIterations = 3;
                    p.Cohesion = FluidCohesionModel.Akinci;
                    p.SurfaceTension = 0.1f;
                    p.Viscosity = 0.01f;
                    p.ViscosityIterations = 2;
                    break;
            }
            return p;
        }

        /// <summary>A compressed, moving block in the corner, so pressures, walls and every cohesion term are active.</summary>
        static FluidBuffers Block(in FluidConstants c, int capacity)
        {
            var b = new FluidBuffers(capacity, c.Grid);
            float dx = c.Parameters.ParticleSpacing;
            FluidScene.FillBlock(b, float3.zero, new float3(0.2f, 0.24f, 0.16f), dx * 0.95f);
            var random = new Unity.Mathematics.Random(99u);
            for (int i = 0; i < b.Status.Count; i++)
            {
                b.Positions[i] += random.NextFloat3(-0.05f, 0.05f) * dx;
                b.Velocities[i] = random.NextFloat3(-0.3f, 0.3f);
            }
            return b;
        }

        [TestCase("WCSPH")]
        [TestCase("WCSPH viscosity flocking")]
        [TestCase("WCSPH Akinci")]
        [TestCase("PBF Akinci viscosity")]
        [TestCase("WCSPH colliders")]
        [TestCase("PBF colliders")]
        [TestCase("WCSPH colliders no-slip viscosity")]
        [TestCase("WCSPH periodic no-slip viscosity")]
        [TestCase("PBF periodic no-slip viscosity")]
        public void EveryPass_MatchesItsCpuPassWithinRoundOff(string setting)
        {
            var c = new FluidConstants(Scene(setting));
            ColliderShape[] colliders = setting.Contains("colliders") ? Colliders() : Array.Empty<ColliderShape>();
            int cells = c.Grid.CellCount;
            FluidBuffers cpu = Block(c, 1024);
            int capacity = cpu.Capacity;
            const float dt = 1f / 120f;
            FluidSolver.Plan plan = FluidSolver.Begin(c, dt, cpu.Particles, ref cpu.Status);
            Span<FluidPass> passes = stackalloc FluidPass[FluidSubstepPasses.MaxPasses];
            int passCount = FluidSubstepPasses.Write(c, plan.H, colliders.Length > 0, passes);
            using var g = new LavapipeFluidSolver(Lavapipe.Device, Lavapipe.FluidShader, c, capacity);
            g.SetShapes(colliders, ReadOnlySpan<FluidDrain>.Empty);
            var gpu = g;
            var constants = g.ConstantsOf(plan.H, dt);
            int count = cpu.Status.Count;
            var report = new System.Text.StringBuilder();
            // Two substeps, so the second sees neighbour lists, densities and velocities the first produced.
            for (int substep = 0; substep < 2; substep++)
            for (int q = 0; q < passCount; q++)
            {
                FluidPass pass = passes[q];
                GpuState.Upload(g, cpu, count, cells);
                gpu.SetConstants(constants);
                FluidComputeStep.RecordPass(ref gpu, c, pass);
                g.Flush();
                Lavapipe.AssertValid();
                var counters = new FluidPassCounters();
                FluidPasses.Run(pass, c, colliders, cpu.Particles, cpu.Scratch, 0, 1, ref count, plan.H, ref counters);
                FluidBuffers back = GpuState.Download(g, c, capacity, cells);
                Assert.That(back.Status.Count, Is.EqualTo(count), $"{pass}: live count");
                string where = $"{setting}, substep {substep}, {pass}";
                AssertClose(GpuState.Compare(back.Positions, cpu.Positions, count), where + ": positions", report);
                AssertClose(GpuState.Compare(back.Velocities, cpu.Velocities, count), where + ": velocities", report);
                AssertClose(GpuState.Compare(back.Ages, cpu.Ages, count), where + ": ages", report);
                AssertClose(GpuState.Compare(back.Densities, cpu.Densities, count), where + ": densities", report);
                AssertClose(GpuState.Compare(back.Pressures, cpu.Pressures, count), where + ": pressures", report);
                // The CPU sort permutes through the vector scratch (the GPU through the Out buffers): no pass reads it after a sort.
                bool sort = pass == FluidPass.Sort || pass == FluidPass.SortWithPrevious;
                if (!sort)
                {
                    AssertClose(GpuState.Compare(back.VectorsA, cpu.VectorsA, count), where + ": vectors A", report);
                    AssertClose(GpuState.Compare(back.VectorsB, cpu.VectorsB, count), where + ": vectors B", report);
                }
                if (pass == FluidPass.ViscosityAToB || pass == FluidPass.ViscosityBToA)
                {
                    float[] w = GpuState.W(g, pass == FluidPass.ViscosityAToB ? FluidComputeBuffer.VectorsB : FluidComputeBuffer.VectorsA, capacity);
                    AssertClose(GpuState.Compare(w, cpu.Floats, count), where + ": viscosity renormalization", report);
                }
                if (!sort || pass == FluidPass.SortWithPrevious)
                    AssertClose(GpuState.Compare(back.Previous, cpu.Previous, count), where + ": previous", report);
                Assert.That(back.NeighbourCounts.AsSpan(0, count).ToArray(), Is.EqualTo(cpu.NeighbourCounts.AsSpan(0, count).ToArray()), where + ": neighbour counts");
                for (int i = 0; i < count; i++)
                    Assert.That(back.Neighbours.AsSpan(i * FluidScratch.MaxNeighbours, cpu.NeighbourCounts[i]).ToArray(),
                        Is.EqualTo(cpu.Neighbours.AsSpan(i * FluidScratch.MaxNeighbours, cpu.NeighbourCounts[i]).ToArray()), where + $": neighbours of {i}");
                FluidPassCounters gc = g.Counters();
                Assert.That((gc.SpeedClamped, gc.OverCompressed, gc.NeighbourOverflow, gc.Contacts),
                    Is.EqualTo((counters.SpeedClamped, counters.OverCompressed, counters.NeighbourOverflow, counters.Contacts)), where + ": counters");
            }
            TestContext.Out.WriteLine(report.ToString());
        }

        /// <summary>One collider of each kind inside and around the block: the walls' density and push, and the contacts.</summary>
        static ColliderShape[] Colliders() => new[]
        {
            ColliderShape.Sphere(new float3(0.1f, 0.08f, 0.08f), 0.04f),
            ColliderShape.Box(new float3(0.2f, 0.02f, 0.08f), quaternion.AxisAngle(math.normalize(new float3(0.3f, 0.5f, 0.2f)), 0.6f), new float3(0.05f, 0.03f, 0.04f)),
            ColliderShape.Capsule(new float3(0.03f, 0.18f, 0.02f), new float3(0.15f, 0.2f, 0.14f), 0.02f),
            ColliderShape.Plane(new float3(0f, 0.03f, 0f), math.normalize(new float3(0.2f, 1f, 0.1f))),
        };

        [Test]
        public void Drain_MarksTheParticlesTheCpuDrainMarks()
        {
            var c = new FluidConstants(Scene("WCSPH"));
            FluidBuffers cpu = Block(c, 1024);
            int count = cpu.Status.Count;
            cpu.Lifetimes[5] = -1f;
            var drains = new[]
            {
                new FluidDrain { Shape = ColliderShape.Sphere(new float3(0.1f, 0.1f, 0.08f), 0.05f) },
                new FluidDrain { Shape = ColliderShape.Box(new float3(0.18f, 0.2f, 0.08f), quaternion.AxisAngle(math.normalize(new float3(0.4f, 0.1f, 0.7f)), 0.8f), new float3(0.03f, 0.05f, 0.02f)) },
                new FluidDrain { Shape = ColliderShape.Plane(new float3(0f, 0.02f, 0f), new float3(0f, -1f, 0f)) },
            };
            using var g = new LavapipeFluidSolver(Lavapipe.Device, Lavapipe.FluidShader, c, cpu.Capacity);
            g.Upload(cpu.Particles, count);
            g.SetShapes(ReadOnlySpan<ColliderShape>.Empty, drains);
            g.Drain();
            Lavapipe.AssertValid();
            int marked = FluidDrain.Apply(drains, cpu.Particles, count);
            FluidBuffers back = GpuState.Download(g, c, cpu.Capacity, c.Grid.CellCount);
            Assert.That(marked, Is.GreaterThan(50), "the drains cover part of the block");
            Assert.That(back.Lifetimes.AsSpan(0, count).ToArray(), Is.EqualTo(cpu.Lifetimes.AsSpan(0, count).ToArray()));
        }

        static void AssertClose((double Difference, double Scale) r, string what, System.Text.StringBuilder report)
        {
            double relative = r.Scale > 0 ? r.Difference / r.Scale : r.Difference;
            if (r.Difference > 0)
                report.AppendLine($"{what}: max |GPU − CPU| = {r.Difference:E2} ({relative:E2} of the field's scale {r.Scale:G4})");
            Assert.That(r.Difference, Is.LessThanOrEqualTo(RelativeTolerance * r.Scale), what);
        }
    }
}
