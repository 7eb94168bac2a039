using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The weakly compressible pressure gradient: its per-particle renormalization and what it differentiates.</summary>
    public class FluidPressureGradientTests
    {
        /// <summary>Σⱼ (h − r)²·r over the other particles within h of slot i, in double (the Density pass's spiky sum).</summary>
        static double SpikySum(in FluidConstants c, FluidBuffers b, int i, int live)
        {
            double h = c.Kernels.H, sum = 0;
            for (int j = 0; j < live; j++)
            {
                if (j == i)
                    continue;
                double r = math.length(c.Offset(b.Positions[i], b.Positions[j]));
                if (r < h)
                    sum += (h - r) * (h - r) * r;
            }
            return sum;
        }

        [Test]
        public void GradientRenormalization_IsOneOnTheRestLatticeInsideAndAtTheWalls()
        {
            // A 10³ rest lattice half a spacing off the six faces: inside and in the first layer off one face the lattice and
            // the walls' scale κ_T give exactly the full trace 3 (float round-off of ~30-term sums: 1e-5). Deeper layers get
            // the continuum integral's shape, which matches the missing lattice layers to a per cent.
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.2f));
            var c = new FluidConstants(p);
            FluidBuffers b = FluidTestScenes.Block(c, 1000, float3.zero, new float3(0.2f));
            var counters = new FluidPassCounters();
            int live = FluidSolver.SortParticles(c, b.Particles, b.Scratch, b.Status.Count, false, ref counters);
            FluidPasses.Density(c, default, b.Particles, b.Scratch, 0, live, ref counters);
            double worstOneWall = 0, worstSeveral = 0;
            int inside = 0, firstLayer = 0;
            for (int i = 0; i < live; i++)
            {
                float3 x = b.Positions[i];
                FluidBoundary.Sample(c, default, x, out _, out _, out float wallTrace);
                float ratio = c.GradientRenormalization((float)SpikySum(c, b, i, live), b.Densities[i], wallTrace);
                float3 toWall = math.min(x, 0.2f - x);
                int walls = (int)math.csum(math.select(float3.zero, new float3(1f), toWall < c.Kernels.H));
                if (walls == 0 || (walls == 1 && math.cmin(toWall) < p.ParticleSpacing))
                {
                    Assert.AreEqual(1.0, ratio, 1e-4, $"particle at {x}");
                    if (walls == 0) inside++; else firstLayer++;
                }
                else if (walls == 1)
                    worstOneWall = Math.Max(worstOneWall, Math.Abs(ratio - 1.0));
                else
                    worstSeveral = Math.Max(worstSeveral, Math.Abs(ratio - 1.0));
            }
            Assert.Greater(inside, 0);
            Assert.Greater(firstLayer, 0);
            // Beyond the calibrated layer the bounds are regression guards, not analysis: measured 0.5 % in the second layer
            // and 3.0 % at a corner (the walls combine by the product rule), each bound the measurement rounded up.
            Assert.That(worstOneWall, Is.LessThan(0.01), "deeper layers off one face");
            Assert.That(worstSeveral, Is.LessThan(0.035), "edges and corners");
        }

        [TestCase(2)]
        [TestCase(4)]
        public void LinearPressureOnAnotherPacking_GivesItsExactGradient(int basis)
        {
            // A body-centred (2) or face-centred (4) cubic packing 2 % closer than rest density, periodic along x and z, with
            // p = p₀ + G·y: both lattices have cubic symmetry, so Σⱼ Vᵢ·rᵢⱼ⊗∇W is its trace/3 times the identity and the
            // renormalized operator gives every particle at least 2h from the floor and the lid (whose neighbours are all
            // inside) ρᵢ·aᵢ = −G·ŷ exactly; the
            // lattice-fitted κ∇ alone is off by the packing's trace (a few per cent). The sums of ~40 terms of up to
            // 5·10⁴ Pa/(kg/m³)·(1/m) in float32 round to ~1e-5 of G.
            float dx = 0.02f, a = math.pow(basis, 1f / 3f) * dx * 0.98f;
            int nx = 6, ny = 12;
            FluidParameters p = FluidTestScenes.Water(dx, float3.zero, new float3(nx * a, ny * a, nx * a));
            p.Periodic = new bool3(true, false, true);
            p.Gravity = float3.zero;
            var c = new FluidConstants(p);
            var b = new FluidBuffers(nx * ny * nx * basis, c.Grid);
            var offsets = new[] { float3.zero, new float3(0.5f, 0.5f, 0f), new float3(0.5f, 0f, 0.5f), new float3(0f, 0.5f, 0.5f) };
            if (basis == 2)
                offsets[1] = new float3(0.5f);
            int count = 0;
            for (int z = 0; z < nx; z++)
            for (int y = 0; y < ny; y++)
            for (int x = 0; x < nx; x++)
            for (int k = 0; k < basis; k++)
            {
                b.Positions[count] = (new float3(x, y, z) + offsets[k] + 0.25f) * a;
                b.Ids[count] = count;
                count++;
            }
            b.Status.Count = count;
            var counters = new FluidPassCounters();
            int live = FluidSolver.SortParticles(c, b.Particles, b.Scratch, count, false, ref counters);
            FluidPasses.Density(c, default, b.Particles, b.Scratch, 0, live, ref counters);
            const float G = -9810f, p0 = 1000f;
            var kappa = new float[live];
            float top = ny * a;
            for (int i = 0; i < live; i++)
            {
                float rho = b.Densities[i], rc = math.max(rho, p.RestDensity);
                // Beside the floor and the lid the walls' share differs; those particles only lend their pressure.
                kappa[i] = c.TaitPressure(rho) > 0f ? b.Scratch.Pressures[i] * rc * rc / c.TaitPressure(rho) : 1f;
                b.Scratch.Pressures[i] = kappa[i] * (p0 + G * b.Positions[i].y) / (rho * rho);
            }
            var acceleration = new float3[live];
            FluidPasses.Forces(c, default, b.Particles, b.Scratch, acceleration, 0, live, 1f, true);
            int n = 0;
            double worst = 0;
            for (int i = 0; i < live; i++)
            {
                float y = b.Positions[i].y;
                if (y < 2f * c.Kernels.H || y > top - 2f * c.Kernels.H)
                    continue;
                Assert.Greater(c.TaitPressure(b.Densities[i]), 0f, "the packing is denser than rest");
                double ratio = b.Densities[i] * acceleration[i].y / -G;
                worst = Math.Max(worst, Math.Abs(ratio - 1));
                n++;
            }
            Assert.Greater(n, 100);
            Assert.That(worst, Is.LessThan(1e-4));
        }

        [Test]
        public void LinearPressureAlongAWall_GivesTheInteriorsGradient()
        {
            // A rest lattice half a spacing off two walls (x), periodic along z, with p = p₀ + G·y and no gravity: the first layer's
            // neighbours mirrored through the wall are exactly the lattice's continuation, so with the ghosts' share of the
            // pressure term (FluidPasses.MirroredPressure) it gets the interior's ρᵢ·aᵢ = −G·ŷ up to its neighbours' κⱼ: the
            // second layer's follows the continuum-shaped wall trace, 0.5 % off (the first test), and holds under half of the
            // first layer's moment, so bound 0.3 %. Without the ghosts the first layer fell 15 % short. Deeper layers carry
            // their own κᵢ's 0.5 %: bound 1 %.
            float dx = 0.02f;
            var size = new float3(0.2f, 0.4f, 0.12f);
            FluidParameters p = FluidTestScenes.Water(dx, float3.zero, size);
            p.Periodic = new bool3(false, false, true);
            p.Gravity = float3.zero;
            var c = new FluidConstants(p);
            FluidBuffers b = FluidTestScenes.Block(c, 2000, float3.zero, size);
            var counters = new FluidPassCounters();
            int live = FluidSolver.SortParticles(c, b.Particles, b.Scratch, b.Status.Count, false, ref counters);
            FluidPasses.Density(c, default, b.Particles, b.Scratch, 0, live, ref counters);
            const float G = -9810f, p0 = 1000f;
            for (int i = 0; i < live; i++)
            {
                FluidBoundary.Sample(c, default, b.Positions[i], out _, out _, out float wallTrace);
                float rho = b.Densities[i];
                float kappa = c.GradientRenormalization((float)SpikySum(c, b, i, live), rho, wallTrace);
                b.Scratch.Pressures[i] = kappa * (p0 + G * b.Positions[i].y) / (rho * rho);
            }
            var acceleration = new float3[live];
            FluidPasses.Forces(c, default, b.Particles, b.Scratch, acceleration, 0, live, 1f, true);
            double firstLayer = 0, deeper = 0;
            int n = 0;
            for (int i = 0; i < live; i++)
            {
                float3 x = b.Positions[i];
                if (x.y < 2f * c.Kernels.H || x.y > size.y - 2f * c.Kernels.H)
                    continue;
                double error = Math.Abs(b.Densities[i] * acceleration[i].y / -G - 1);
                if (math.min(x.x, size.x - x.x) < dx)
                {
                    firstLayer = Math.Max(firstLayer, error);
                    n++;
                }
                else
                    deeper = Math.Max(deeper, error);
            }
            Assert.Greater(n, 50);
            Assert.That(firstLayer, Is.LessThan(0.003), "the layer half a spacing off the wall");
            Assert.That(deeper, Is.LessThan(0.01), "deeper layers");
        }
    }
}
