using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The weakly compressible pressure gradient: its per-particle renormalization and what it differentiates.</summary>
    public class FluidPressureGradientTests
    {
        [TestCase(1.0f)]
        [TestCase(0.99f)]
        public void LatticeInABox_ReadsTheInteriorsDensityAndRenormalizationAtEveryWall(float scale)
        {
            // A cubic lattice of spacing a (the rest spacing, or 1 % closer) half a spacing off the six faces of a box ten
            // spacings wide: the walls' ghosts are the lattice's continuation, so every particle, in a face's first layer, on
            // an edge or in a corner, reads the density and the gradient trace of the infinite lattice: the same bits up to the
            // float32 round-off of sums of 30–200 terms in another order (1e-5 relative). On the rest lattice that density is
            // ρ₀ (its pressure is 0, so κᵢ shows only on the closer lattice).
            float dx = 0.02f, a = scale * dx;
            int n = 10;
            FluidParameters p = FluidTestScenes.Water(dx, float3.zero, new float3(n * a));
            var c = new FluidConstants(p);
            var b = new FluidBuffers(n * n * n, c.Grid);
            int count = 0;
            for (int z = 0; z < n; z++)
            for (int y = 0; y < n; y++)
            for (int x = 0; x < n; x++)
            {
                b.Positions[count] = (new float3(x, y, z) + 0.5f) * a;
                b.Ids[count] = count;
                count++;
            }
            b.Status.Count = count;
            int live = SortAndDensity(c, b);
            int centre = -1;
            for (int i = 0; i < live; i++)
                if (math.all(math.abs(b.Positions[i] - 0.5f * n * a) < a))
                    centre = i;
            float rho = b.Densities[centre];
            bool compressed = scale < 1f;
            float kappa = compressed ? Renormalization(c, b, centre) : 1f;
            int corners = 0;
            for (int i = 0; i < live; i++)
            {
                float3 x = b.Positions[i];
                Assert.AreEqual(rho, b.Densities[i], 1e-5f * rho, $"density at {x}");
                if (compressed)
                    Assert.AreEqual(kappa, Renormalization(c, b, i), 1e-5f, $"renormalization at {x}");
                if (math.all(math.min(x, n * a - x) < a))
                    corners++;
            }
            Assert.AreEqual(8, corners);
            if (compressed)
                Assert.Greater(rho, p.RestDensity * 1.02f, "1 % closer in each direction is 3 % denser");
            else
                Assert.AreEqual(p.RestDensity, rho, 1e-5f * rho);
        }

        [Test]
        public void LatticeAroundABoxCollider_ReadsTheInteriorsDensityAtItsEdges()
        {
            // A square bar through a periodic z, its faces half a spacing off a lattice that fills the rest of a box: beside a
            // convex edge the closest point is on the edge and the mirror plane is diagonal; its images of the sources in the
            // edge's quadrant are the lattice's sites inside the bar, and those of the sources beside the faces would land
            // where fluid is. Keeping only the images inside the bar, every particle reads the infinite lattice's density,
            // ρ₀, to the float32 round-off of sums in another order (1e-5 relative); counting the others too makes the
            // particles diagonal to the edges 26 % denser. The bar stands 5 spacings (> 2h) off the domain's faces.
            float dx = 0.02f;
            int n = 14, nz = 6, lo = 5, hi = 9;
            FluidParameters p = FluidTestScenes.Water(dx, float3.zero, new float3(n * dx, n * dx, nz * dx));
            p.Periodic = new bool3(false, false, true);
            var c = new FluidConstants(p);
            var bar = new[] { ColliderShape.Box(new float3(0.5f * (lo + hi) * dx, 0.5f * (lo + hi) * dx, 0.5f * nz * dx), quaternion.identity,
                new float3(0.5f * (hi - lo) * dx, 0.5f * (hi - lo) * dx, nz * dx)) };
            var b = new FluidBuffers(n * n * nz, c.Grid);
            int count = 0;
            for (int z = 0; z < nz; z++)
            for (int y = 0; y < n; y++)
            for (int x = 0; x < n; x++)
            {
                if (x >= lo && x < hi && y >= lo && y < hi)
                    continue;
                b.Positions[count] = (new float3(x, y, z) + 0.5f) * dx;
                b.Ids[count] = count;
                count++;
            }
            b.Status.Count = count;
            var counters = new FluidPassCounters();
            int live = FluidSolver.SortParticles(c, b.Particles, b.Scratch, count, false, ref counters);
            FluidPasses.Density(c, bar, b.Particles, b.Scratch, 0, live, ref counters);
            int edges = 0;
            for (int i = 0; i < live; i++)
            {
                float3 x = b.Positions[i];
                Assert.AreEqual(p.RestDensity, b.Densities[i], 1e-5f * p.RestDensity, $"density at {x}");
                float fromX = math.abs(x.x - bar[0].Center.x) - bar[0].HalfExtents.x, fromY = math.abs(x.y - bar[0].Center.y) - bar[0].HalfExtents.y;
                if (fromX > 0f && fromX < dx && fromY > 0f && fromY < dx)
                    edges++;
            }
            Assert.AreEqual(4 * nz, edges, "a particle diagonal to each edge in every layer");
        }

        /// <summary>Sorts the block in <paramref name="b"/> (its Status.Count particles) and runs the Density pass; returns the live count.</summary>
        static int SortAndDensity(in FluidConstants c, FluidBuffers b)
        {
            var counters = new FluidPassCounters();
            int live = FluidSolver.SortParticles(c, b.Particles, b.Scratch, b.Status.Count, false, ref counters);
            FluidPasses.Density(c, default, b.Particles, b.Scratch, 0, live, ref counters);
            return live;
        }

        /// <summary>The Forces pass's accelerations (from rest, one second: aᵢ) of the <paramref name="live"/> particles, with the pressures the test stored.</summary>
        static float3[] Accelerations(in FluidConstants c, FluidBuffers b, int live)
        {
            var acceleration = new float3[live];
            FluidPasses.Forces(c, default, b.Particles, b.Scratch, acceleration, 0, live, 1f, true);
            return acceleration;
        }

        /// <summary>κᵢ of slot i from the Density pass's stored κᵢ·pᵢ/ρᵢ² (ρ above rest density, so pᵢ &gt; 0).</summary>
        static float Renormalization(in FluidConstants c, FluidBuffers b, int i)
        {
            float rho = b.Densities[i];
            return b.Scratch.Pressures[i] * rho * rho / c.TaitPressure(rho);
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
            int live = SortAndDensity(c, b);
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
            float3[] acceleration = Accelerations(c, b, live);
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
        public void LinearPressureAlongTheWalls_GivesTheInteriorsGradientUpToTheEdges()
        {
            // A rest lattice half a spacing off four side walls (x and z), p = p₀ + G·y and no gravity: the neighbours mirrored
            // through a wall, and through two at an edge, continue the lattice and carry the pressure at their own height, so
            // every particle at least 2h from the floor and the lid (whose mirrors reflect the pressure) gets the interior's
            // ρᵢ·aᵢ = −G·ŷ, κᵢ = 1 on the rest lattice. The pair terms carry pᵢ + pⱼ ≤ 10⁴ Pa while their sum is G·Δx per
            // spacing: float32 round-off ε·N·p/(G·Δx) with N ≤ 90 terms (an edge's images) is about 3e-4 of G: bound 5e-4.
            // The previous release's half-space walls left the first layer 15 % short (its own test's reading).
            float dx = 0.02f;
            var size = new float3(0.2f, 0.4f, 0.12f);
            FluidParameters p = FluidTestScenes.Water(dx, float3.zero, size);
            p.Gravity = float3.zero;
            var c = new FluidConstants(p);
            FluidBuffers b = FluidTestScenes.Block(c, 2000, float3.zero, size);
            int live = SortAndDensity(c, b);
            // Positive everywhere, as the solver's pressures are (a ghost's pressure is clamped at 0).
            const float G = -9810f, p0 = 5000f;
            for (int i = 0; i < live; i++)
            {
                float rho = b.Densities[i];
                b.Scratch.Pressures[i] = (p0 + G * b.Positions[i].y) / (rho * rho);
            }
            float3[] acceleration = Accelerations(c, b, live);
            double worst = 0;
            int edges = 0;
            for (int i = 0; i < live; i++)
            {
                float3 x = b.Positions[i];
                if (x.y < 2f * c.Kernels.H || x.y > size.y - 2f * c.Kernels.H)
                    continue;
                worst = Math.Max(worst, math.length(b.Densities[i] * acceleration[i] / -G - new float3(0f, 1f, 0f)));
                if (math.min(x.x, size.x - x.x) < dx && math.min(x.z, size.z - x.z) < dx)
                    edges++;
            }
            Assert.Greater(edges, 20);
            TestContext.Out.WriteLine($"worst |ρa/G − ŷ| {worst:E2}");
            Assert.That(worst, Is.LessThan(5e-4));
        }

        [Test]
        public void HydrostaticPressure_BalancesGravityDownToTheFloor()
        {
            // A rest lattice on the floor, periodic along x and z, with the hydrostatic p = ρ₀g(H − y) and gravity: the floor's
            // ghosts carry their sources' pressure extrapolated to their own depth, pⱼ + ρⱼ·g·(x_g − xⱼ), so the pressure
            // beyond the floor continues the line and every particle at least 2h below the free top, the floor's first
            // layers included, is at rest: float32 round-off ε·N·p/(ρ₀g·Δx) with p ≤ ρ₀gH and N ≤ 60 terms is about 7e-5 of g,
            // bound 2e-4. Ghosts with their sources' pressure alone (a mirror) would leave the first layer short of support by
            // the missing layers' ρg·Δy.
            float dx = 0.02f, top = 0.4f;
            var size = new float3(0.12f, 0.6f, 0.12f);
            FluidParameters p = FluidTestScenes.Water(dx, float3.zero, size);
            p.Periodic = new bool3(true, false, true);
            var c = new FluidConstants(p);
            FluidBuffers b = FluidTestScenes.Block(c, 2000, float3.zero, new float3(size.x, top, size.z));
            int live = SortAndDensity(c, b);
            float g = -p.Gravity.y, rho0 = p.RestDensity;
            for (int i = 0; i < live; i++)
                b.Scratch.Pressures[i] = rho0 * g * (top - b.Positions[i].y) / (rho0 * rho0);
            float3[] acceleration = Accelerations(c, b, live);
            double worst = 0;
            int floor = 0;
            for (int i = 0; i < live; i++)
            {
                float y = b.Positions[i].y;
                if (y > top - 2f * c.Kernels.H)
                    continue;
                Assert.AreEqual(rho0, b.Densities[i], 1e-5f * rho0, "the lattice and its ghosts are at rest density");
                worst = Math.Max(worst, math.length(acceleration[i]) / g);
                if (y < dx)
                    floor++;
            }
            Assert.Greater(floor, 30);
            TestContext.Out.WriteLine($"worst |a|/g {worst:E2}");
            Assert.That(worst, Is.LessThan(2e-4));
        }
    }
}
