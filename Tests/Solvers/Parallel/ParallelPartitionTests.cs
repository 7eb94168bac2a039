using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    public class ParallelPartitionTests
    {
        // A strip of tetrahedra-like 4-corner elements sharing particles, with a high-valence hub (particle 0).
        static int[] Corners(int elements, int particles)
        {
            var rng = new System.Random(7);
            var corners = new int[elements * 4];
            for (int e = 0; e < elements; e++)
            {
                corners[e * 4] = e % 5 == 0 ? 0 : rng.Next(particles);
                for (int k = 1; k < 4; k++)
                {
                    int p;
                    bool repeat;
                    do
                    {
                        p = rng.Next(particles);
                        repeat = false;
                        for (int j = 0; j < k; j++)
                            repeat |= corners[e * 4 + j] == p;
                    } while (repeat);
                    corners[e * 4 + k] = p;
                }
            }
            return corners;
        }

        [Test]
        public void Coloring_NoTwoElementsOfAColourShareAParticle_AndEveryElementIsColouredOnce()
        {
            int[] corners = Corners(2000, 300);
            GraphColoring coloring = GraphColoring.Build(corners, 4, 300);
            var seen = new bool[2000];
            for (int c = 0; c < coloring.ColorCount; c++)
            {
                var owner = new int[300];
                for (int i = coloring.ColorOffsets[c]; i < coloring.ColorOffsets[c + 1]; i++)
                {
                    int e = coloring.Elements[i];
                    Assert.That(seen[e], Is.False, $"element {e} coloured twice");
                    seen[e] = true;
                    for (int k = 0; k < 4; k++)
                    {
                        int p = corners[e * 4 + k];
                        Assert.That(owner[p], Is.EqualTo(0), $"colour {c}: particle {p} in elements {owner[p] - 1} and {e}");
                        owner[p] = e + 1;
                    }
                }
            }
            Assert.That(Array.TrueForAll(seen, s => s), Is.True);
            // Particle 0 has 400 elements: the greedy colouring needs at least that many colours, beyond one 64-bit mask.
            Assert.That(coloring.ColorCount, Is.GreaterThanOrEqualTo(400));
        }

        [Test]
        public void Gather_GivesTheSameBits_ForAnySplitOfTheParticles()
        {
            int[] corners = Corners(5000, 1000);
            ElementIncidence incidence = ElementIncidence.Build(corners, 4, 1000);
            var perSlot = new float3[corners.Length];
            var rng = new System.Random(3);
            for (int s = 0; s < perSlot.Length; s++)
                perSlot[s] = new float3((float)rng.NextDouble() - 0.5f, (float)rng.NextDouble() * 1e3f, (float)rng.NextDouble() * 1e-3f);
            var whole = new float3[1000];
            ElementIncidence.Gather(incidence.Offsets, incidence.Slots, perSlot, 0, 1000, whole);
            foreach (int batch in new[] { 1, 7, 64, 333 })
            {
                var split = new float3[1000];
                // Batches in reverse order, as workers might take them.
                for (int start = (999 / batch) * batch; start >= 0; start -= batch)
                    ElementIncidence.Gather(incidence.Offsets, incidence.Slots, perSlot, start, Math.Min(start + batch, 1000), split);
                for (int i = 0; i < 1000; i++)
                    Assert.That(split[i].Equals(whole[i]), Is.True, $"batch {batch}, particle {i}");
            }
            // And the sum is the sum: each slot counted once, for its particle.
            var expected = new double[1000];
            for (int s = 0; s < corners.Length; s++)
                expected[corners[s]] += perSlot[s].y;
            for (int i = 0; i < 1000; i++)
                Assert.That(whole[i].y, Is.EqualTo(expected[i]).Within(1e-4 * Math.Max(1.0, Math.Abs(expected[i]))));
        }
    }
}
