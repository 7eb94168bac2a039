using System;
using NUnit.Framework;
using SoftBodyDynamics.Lavapipe;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Compute
{
    /// <summary>The integer stages (keys, scan, counting sort, compaction, emission) against the CPU: bit for bit.</summary>
    public class FluidSortKernelTests
    {
        static FluidConstants Constants(float spacing, float3 max)
        {
            FluidParameters p = FluidParameters.Default;
            p.ParticleSpacing = spacing;
            p.DomainMin = float3.zero;
            p.DomainMax = max;
            return new FluidConstants(p);
        }

        /// <summary>Random particles in the box, with a killed, an expired and a non-finite one among the first four (when there are four).</summary>
        static FluidBuffers RandomFluid(in FluidConstants c, int count, bool oneCell, uint seed)
        {
            var b = new FluidBuffers(Math.Max(count, 1), c.Grid);
            var random = new Unity.Mathematics.Random(seed);
            float3 size = c.Parameters.DomainMax - c.Parameters.DomainMin;
            for (int i = 0; i < count; i++)
            {
                b.Positions[i] = oneCell ? c.Parameters.DomainMin + 0.25f * c.Grid.CellSize : c.Parameters.DomainMin + random.NextFloat3() * size;
                b.Velocities[i] = random.NextFloat3(-1f, 1f);
                b.Ages[i] = random.NextFloat(0f, 2f);
                b.Lifetimes[i] = random.NextFloat() < 0.5f ? 0f : 3f;
                b.Attributes[i] = random.NextFloat();
                b.Ids[i] = 1000 + i;
            }
            if (count >= 4)
            {
                b.Lifetimes[0] = -1f;
                b.Ages[1] = 5f; b.Lifetimes[1] = 4f;
                b.Positions[2] = new float3(float.NaN, 0f, 0f);
                b.Velocities[3] = new float3(0f, float.PositiveInfinity, 0f);
            }
            b.Status.Count = count;
            return b;
        }

        [TestCase(0)]
        [TestCase(1)]
        [TestCase(63)]
        [TestCase(64)]
        [TestCase(65)]
        [TestCase(257)]
        [TestCase(5000)]
        public void Sort_GivesTheCpuOrderAndCountsBitForBit(int count) => AssertSortMatches(count, false);

        [TestCase(65)]
        [TestCase(700)]
        public void Sort_OneCellHoldingEverything_GivesTheCpuOrder(int count) => AssertSortMatches(count, true);

        static void AssertSortMatches(int count, bool oneCell)
        {
            FluidConstants c = Constants(0.05f, new float3(1f, 0.8f, 0.6f));
            int cells = c.Grid.CellCount;
            FluidBuffers cpu = RandomFluid(c, count, oneCell, 7u + (uint)count);
            using var g = new LavapipeFluidSolver(Lavapipe.Device, Lavapipe.FluidShader, c, Math.Max(count, 1));
            g.Upload(cpu.Particles, count);
            var counters = new FluidPassCounters();
            int live = FluidSolver.SortParticles(c, cpu.Particles, cpu.Scratch, count, false, ref counters);

            var gpu = g;
            gpu.SetConstants(FluidComputeConstants.Of(c, 0f, 0f));
            FluidComputeStep.RecordSort(ref gpu, cells, false);
            g.Flush();
            Lavapipe.AssertValid();
            FluidBuffers back = GpuState.Download(g, c, Math.Max(count, 1), cells);
            FluidPassCounters gc = g.Counters();

            Assert.That(g.Count, Is.EqualTo(live), "live count");
            Assert.That((gc.Killed, gc.Expired, gc.Invalid), Is.EqualTo((counters.Killed, counters.Expired, counters.Invalid)), "removal counters");
            Assert.That(back.CellStart.AsSpan(0, cells + 2).ToArray(), Is.EqualTo(cpu.CellStart.AsSpan(0, cells + 2).ToArray()), "cell starts");
            Assert.That(back.Order.AsSpan(0, count).ToArray(), Is.EqualTo(cpu.Order.AsSpan(0, count).ToArray()), "order");
            for (int i = 0; i < live; i++)
            {
                Assert.That(Bits(back.Positions[i]), Is.EqualTo(Bits(cpu.Positions[i])), $"position {i}");
                Assert.That(Bits(back.Velocities[i]), Is.EqualTo(Bits(cpu.Velocities[i])), $"velocity {i}");
                Assert.That((back.Ages[i], back.Lifetimes[i], back.Attributes[i], back.Ids[i]),
                    Is.EqualTo((cpu.Ages[i], cpu.Lifetimes[i], cpu.Attributes[i], cpu.Ids[i])), $"extras {i}");
            }
        }

        static (uint, uint, uint) Bits(float3 v) => (math.asuint(v.x), math.asuint(v.y), math.asuint(v.z));

        [TestCase(1)]
        [TestCase(2)]
        [TestCase(511)]
        [TestCase(512)]
        [TestCase(513)]
        [TestCase(3842)]
        [TestCase(262144)]
        [TestCase(262657)]
        public void Scan_IsTheExactInclusivePrefixSum(int elements)
        {
            // A grid of 307 200 cells, so its cell table can hold the test's elements (three scan levels).
            FluidConstants c = Constants(0.05f, new float3(4f, 4f, 2.4f));
            Assume.That(c.Grid.CellCount + 2, Is.GreaterThanOrEqualTo(elements));
            using var g = new LavapipeFluidSolver(Lavapipe.Device, Lavapipe.FluidShader, c, 1);
            Span<uint> data = g.Buffer(FluidComputeBuffer.CellStart).As<uint>();
            var random = new Unity.Mathematics.Random(12345u);
            var expected = new uint[elements];
            uint sum = 0;
            for (int i = 0; i < elements; i++)
            {
                data[i] = (uint)random.NextInt(0, 9);
                sum += data[i];
                expected[i] = sum;
            }
            var gpu = g;
            FluidComputeStep.RecordScan(ref gpu, elements);
            g.Flush();
            Lavapipe.AssertValid();
            Assert.That(g.Buffer(FluidComputeBuffer.CellStart).As<uint>().Slice(0, elements).ToArray(), Is.EqualTo(expected));
        }

        [Test]
        public void Emit_AppendsAfterTheLiveParticlesAndGrowsTheBuffersByDoubling()
        {
            FluidConstants c = Constants(0.05f, new float3(1f, 0.8f, 0.6f));
            FluidBuffers start = RandomFluid(c, 60, false, 3u);
            for (int i = 0; i < 4; i++) { start.Lifetimes[i] = 0f; start.Positions[i] = new float3(0.5f); start.Velocities[i] = float3.zero; }
            FluidBuffers spawn = RandomFluid(c, 10, false, 4u);
            for (int i = 0; i < 4; i++) { spawn.Lifetimes[i] = 0f; spawn.Positions[i] = new float3(0.4f); spawn.Velocities[i] = float3.zero; }
            using var g = new LavapipeFluidSolver(Lavapipe.Device, Lavapipe.FluidShader, c, 64);
            g.Upload(start.Particles, 60);
            g.Emit(spawn.Particles, 10);
            Lavapipe.AssertValid();
            Assert.That(g.Capacity, Is.EqualTo(128), "grown by doubling");
            Assert.That(g.Count, Is.EqualTo(70));
            FluidBuffers back = GpuState.Download(g, c, 128, c.Grid.CellCount);
            for (int i = 0; i < 60; i++)
                Assert.That((back.Positions[i], back.Ids[i]), Is.EqualTo((start.Positions[i], start.Ids[i])), $"kept {i}");
            for (int i = 0; i < 10; i++)
                Assert.That((back.Positions[60 + i], back.Velocities[60 + i], back.Ages[60 + i], back.Ids[60 + i]),
                    Is.EqualTo((spawn.Positions[i], spawn.Velocities[i], spawn.Ages[i], spawn.Ids[i])), $"spawned {i}");
        }

        [Test]
        public void Buffers_NoneLeakAfter100CreateDestroyCycles()
        {
            FluidConstants c = Constants(0.05f, new float3(1f, 0.8f, 0.6f));
            int before = Lavapipe.Device.LiveBuffers;
            for (int cycle = 0; cycle < 100; cycle++)
            {
                using var g = new LavapipeFluidSolver(Lavapipe.Device, Lavapipe.FluidShader, c, 64 + cycle);
                g.EnsureCapacity(1000);
            }
            Assert.That(Lavapipe.Device.LiveBuffers, Is.EqualTo(before));
        }
    }
}
