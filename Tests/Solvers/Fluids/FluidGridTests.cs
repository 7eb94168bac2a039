using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The grid, the counting sort with removal, the neighbour rows and the rest lattice.</summary>
    public class FluidGridTests
    {
        static FluidBuffers RandomParticles(in FluidConstants c, int n, int seed)
        {
            var random = new System.Random(seed);
            var b = new FluidBuffers(n, c.Grid);
            float3 size = c.Parameters.DomainMax - c.Parameters.DomainMin;
            for (int i = 0; i < n; i++)
            {
                b.Positions[i] = c.Parameters.DomainMin + new float3((float)random.NextDouble(), (float)random.NextDouble(), (float)random.NextDouble()) * size;
                b.Ids[i] = i;
            }
            b.Status.Count = n;
            return b;
        }

        [Test]
        public void Sort_IsStableByCellAndDropsRemovedParticles()
        {
            var c = new FluidConstants(FluidTestScenes.Water(0.02f, float3.zero, new float3(0.3f)));
            FluidBuffers b = RandomParticles(c, 2000, 1);
            b.Lifetimes[10] = -1f;                      // marked by a drain
            b.Lifetimes[11] = 0.5f; b.Ages[11] = 0.5f;  // expired
            b.Positions[12] = new float3(float.NaN);    // invalid
            b.Velocities[13] = new float3(float.PositiveInfinity, 0f, 0f);
            var counters = new FluidPassCounters();
            int live = FluidSolver.SortParticles(c, b.Particles, b.Scratch, 2000, false, ref counters);
            Assert.AreEqual(1996, live);
            Assert.AreEqual(1, counters.Killed);
            Assert.AreEqual(1, counters.Expired);
            Assert.AreEqual(2, counters.Invalid);
            for (int k = 1; k < live; k++)
            {
                int previous = c.Grid.Key(b.Positions[k - 1]), current = c.Grid.Key(b.Positions[k]);
                Assert.That(current, Is.GreaterThanOrEqualTo(previous), "keys ascend");
                if (current == previous)
                    Assert.That(b.Ids[k], Is.GreaterThan(b.Ids[k - 1]), "stable within a cell");
            }
            foreach (int gone in new[] { 10, 11, 12, 13 })
                Assert.AreEqual(-1, Array.IndexOf(b.Ids, gone, 0, live));
        }

        [Test]
        public void NeighbourRows_FindExactlyTheBruteForceNeighbours()
        {
            var c = new FluidConstants(FluidTestScenes.Water(0.02f, new float3(-0.1f), new float3(0.2f, 0.15f, 0.25f)));
            FluidBuffers b = RandomParticles(c, 3000, 2);
            var counters = new FluidPassCounters();
            int live = FluidSolver.SortParticles(c, b.Particles, b.Scratch, 3000, false, ref counters);
            FluidPasses.Density(c, default, b.Particles, b.Scratch, 0, live, ref counters);
            Assert.AreEqual(0, counters.NeighbourOverflow);
            float h2 = c.Kernels.H2;
            for (int i = 0; i < live; i += 7)
            {
                int brute = 0;
                for (int j = 0; j < live; j++)
                    if (j != i && math.lengthsq(b.Positions[i] - b.Positions[j]) < h2)
                        brute++;
                Assert.AreEqual(brute, b.NeighbourCounts[i], $"particle {i}");
                for (int n = 0; n < b.NeighbourCounts[i]; n++)
                    Assert.That(math.lengthsq(b.Positions[i] - b.Positions[b.Neighbours[i * FluidScratch.MaxNeighbours + n]]), Is.LessThan(h2));
            }
        }

        [Test]
        public void RestLattice_IsAtRestDensityInsideAndAtTheWalls()
        {
            // A lattice filling the box: interior particles sum to ρ₀ by the choice of mass; particles half a spacing off
            // one wall get ρ₀ through the calibrated wall integral. Float32 sums of ~30 terms: 1e-5 relative.
            var c = new FluidConstants(FluidTestScenes.Water(0.02f, float3.zero, new float3(0.2f, 0.4f, 0.2f)));
            FluidBuffers b = FluidTestScenes.Block(c, 4000, float3.zero, new float3(0.2f, 0.2f, 0.2f));
            var counters = new FluidPassCounters();
            int live = FluidSolver.SortParticles(c, b.Particles, b.Scratch, b.Status.Count, false, ref counters);
            FluidPasses.Density(c, default, b.Particles, b.Scratch, 0, live, ref counters);
            float h = c.Kernels.H;
            int interior = 0, wall = 0;
            for (int i = 0; i < live; i++)
            {
                float3 x = b.Positions[i];
                bool inside = math.all(x > h) && x.x < 0.2f - h && x.z < 0.2f - h && x.y < 0.2f - h;
                // Half a spacing above the floor, a kernel away from every other face.
                bool onFloor = x.y < 0.011f && x.x > h && x.x < 0.2f - h && x.z > h && x.z < 0.2f - h;
                if (inside) { interior++; Assert.That(b.Densities[i], Is.EqualTo(1000f).Within(1e-2f)); }
                if (onFloor) { wall++; Assert.That(b.Densities[i], Is.EqualTo(1000f).Within(1e-2f)); }
            }
            Assert.That(interior, Is.GreaterThan(0));
            Assert.That(wall, Is.GreaterThan(0));
        }
    }
}
