using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Periodic axes, no-slip faces and the viscosity operator they rely on.</summary>
    public class FluidBoundaryModelTests
    {
        static FluidConstants Periodic(bool3 periodic, float3 max)
        {
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, max);
            p.Periodic = periodic;
            return new FluidConstants(p);
        }

        static FluidBuffers Random(in FluidConstants c, int count, uint seed)
        {
            var b = new FluidBuffers(count, c.Grid);
            var random = new Unity.Mathematics.Random(seed);
            float3 lo = c.Parameters.DomainMin, hi = c.Parameters.DomainMax;
            for (int i = 0; i < count; i++)
            {
                b.Positions[i] = lo + random.NextFloat3() * (hi - lo);
                b.Ids[i] = i;
            }
            b.Status.Count = count;
            return b;
        }

        [TestCase(true, false, false)]
        [TestCase(false, true, true)]
        [TestCase(true, true, true)]
        public void PeriodicNeighbours_AreExactlyTheNearestImagesWithinH(bool px, bool py, bool pz)
        {
            // Extents that are not whole cells (h/2 = 2 cm), so the last cell of each axis is partial.
            FluidConstants c = Periodic(new bool3(px, py, pz), new float3(0.137f, 0.151f, 0.129f));
            Assert.IsTrue(c.IsPeriodic);
            FluidBuffers b = Random(c, 300, 7);
            var counters = new FluidPassCounters();
            int live = FluidSolver.SortParticles(c, b.Particles, b.Scratch, 300, false, ref counters);
            FluidPasses.Density(c, default, b.Particles, b.Scratch, 0, live, ref counters);
            Assert.AreEqual(0, counters.NeighbourOverflow);
            float h2 = c.Kernels.H2;
            float3 extent = c.Parameters.DomainMax - c.Parameters.DomainMin;
            for (int i = 0; i < live; i++)
            {
                int brute = 0;
                for (int j = 0; j < live; j++)
                {
                    float3 d = b.Positions[i] - b.Positions[j];
                    // Every image within one period, in double: the nearest is the one that counts.
                    double best = double.MaxValue;
                    for (int ix = px ? -1 : 0; ix <= (px ? 1 : 0); ix++)
                    for (int iy = py ? -1 : 0; iy <= (py ? 1 : 0); iy++)
                    for (int iz = pz ? -1 : 0; iz <= (pz ? 1 : 0); iz++)
                    {
                        double dx = d.x + ix * extent.x, dy = d.y + iy * extent.y, dz = d.z + iz * extent.z;
                        best = Math.Min(best, dx * dx + dy * dy + dz * dz);
                    }
                    if (j != i && best < h2)
                        brute++;
                }
                Assert.AreEqual(brute, b.NeighbourCounts[i], $"particle {i} at {b.Positions[i]}");
            }
        }

        [Test]
        public void PeriodicAxis_ShorterThanThreeKernelRadii_IsNotPeriodic()
        {
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.11f, 0.2f, 0.2f));
            p.Periodic = new bool3(true, false, false);
            Assert.IsFalse(new FluidConstants(p).IsPeriodic, "0.11 m < 3h = 0.12 m");
            p.DomainMax.x = 0.12f;
            Assert.IsTrue(new FluidConstants(p).IsPeriodic);
        }

        [TestCase(FluidSolverKind.WeaklyCompressible)]
        [TestCase(FluidSolverKind.PositionBased)]
        public void ParticleThroughAPeriodicFace_EntersOppositeWithItsVelocity(FluidSolverKind solver)
        {
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.2f, 0.2f, 0.2f));
            p.Solver = solver;
            p.Gravity = float3.zero;
            p.Periodic = new bool3(true, false, false);
            var c = new FluidConstants(p);
            var b = new FluidBuffers(1, c.Grid);
            b.Positions[0] = new float3(0.195f, 0.1f, 0.1f);
            b.Velocities[0] = new float3(1f, 0f, 0f);
            b.Status.Count = 1;
            FluidTestScenes.Step(c, b, 1f / 60f);
            // A lone particle coasts: 1/60 m along x, wrapped by one period (float32 round-off of positions near 0.2 m).
            Assert.AreEqual(0.195f + 1f / 60f - 0.2f, b.Positions[0].x, 1e-5f);
            Assert.AreEqual(1f, b.Velocities[0].x, 1e-4f, "the position-based velocity is the motion, not the jump across the box");
        }

        /// <summary>
        /// <paramref name="iterations"/> Jacobi iterations of the implicit viscosity from v⁰ = the velocities, as a substep runs
        /// them (the scale cleared, ping-ponging A and B); returns the last iterate.
        /// </summary>
        static float3[] Viscosity(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidBuffers b, int iterations, float h)
        {
            int live = b.Status.Count;
            var counters = new FluidPassCounters();
            int count = live;
            FluidPasses.Run(FluidPass.CopyVelocitiesToA, c, colliders, b.Particles, b.Scratch, 0, 1, ref count, h, ref counters);
            for (int it = 0; it < iterations; it++)
                FluidPasses.Run((it & 1) == 0 ? FluidPass.ViscosityAToB : FluidPass.ViscosityBToA, c, colliders, b.Particles, b.Scratch, 0, 1, ref count, h, ref counters);
            return ((iterations & 1) == 1 ? b.VectorsB : b.VectorsA).AsSpan(0, live).ToArray();
        }

        [Test]
        public void NoSlipCollider_IsTheNoSlipFaceAtItsPlane()
        {
            // One boundary model: two Jacobi iterations (the first weighs pairs by sᵢ, the second by (sᵢ + sⱼ)/2) of a block
            // sliding along a no-slip plane collider on the floor give every particle the velocity a no-slip floor face does, up
            // to the float32 round-off of d = h − (h − d) (1e-5 relative); both hold the sliding block back, and colliders are
            // free slip by default. The densities are the floor face's for all (a collider would add its own wall density).
            FluidParameters face = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.4f, 0.4f, 0.4f));
            face.Gravity = float3.zero;
            face.Viscosity = 1e-2f;
            face.DomainNoSlip = new float3(0f, 1f, 0f);
            FluidParameters collider = face;
            collider.DomainNoSlip = float3.zero;
            collider.WallNoSlip = 1f;
            FluidParameters free = collider;
            free.WallNoSlip = 0f;
            var cf = new FluidConstants(face);
            FluidBuffers b = FluidTestScenes.Block(cf, 4000, float3.zero, new float3(0.4f, 0.1f, 0.4f));
            var counters = new FluidPassCounters();
            b.Status.Count = FluidSolver.SortParticles(cf, b.Particles, b.Scratch, b.Status.Count, false, ref counters);
            FluidPasses.Density(cf, default, b.Particles, b.Scratch, 0, b.Status.Count, ref counters);
            for (int i = 0; i < b.Status.Count; i++)
                b.Velocities[i] = new float3(1f, 0f, 0f);
            var plane = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            const float h = 1e-3f;
            float3[] onFace = Viscosity(cf, default, b, 2, h);
            float3[] onCollider = Viscosity(new FluidConstants(collider), plane, b, 2, h);
            float3[] onFreeSlip = Viscosity(new FluidConstants(free), plane, b, 2, h);
            int held = 0;
            for (int i = 0; i < b.Status.Count; i++)
            {
                Assert.AreEqual(onFace[i].x, onCollider[i].x, 1e-5f, $"particle at {b.Positions[i]}");
                Assert.AreEqual(1f, onFreeSlip[i].x, 1e-6f, "a uniform velocity without a no-slip wall stays");
                if (onFace[i].x < 0.999f)
                    held++;
            }
            Assert.Greater(held, 0, "the no-slip floor holds the first layers back");
        }

        [Test]
        public void ViscosityOnTheRestLattice_DifferentiatesAQuadraticFieldExactly()
        {
            // v = (y², 0, 0) has ∇²v = (2, 0, 0), and a Jacobi iteration from v gives vᵢ + hν·(∇²v)ᵢ/(1 + aᵢ), aᵢ = hν·Σw the
            // particle's own weight. aᵢ is read from the same pass on v⁰ = 0 with neighbours at 1 (it returns aᵢ/(1 + aᵢ)). On the rest
            // lattice the odd terms cancel and the lattice-corrected operator (κ_ν) sums Σw·Δy² to exactly 2: float32 round-off
            // of ~250-term sums and of the ~4e-4 velocities leaves 1e-3 of the 2e-6 increment.
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.3f, 0.3f, 0.3f));
            p.Viscosity = 1e-3f;
            p.Gravity = float3.zero;
            var c = new FluidConstants(p);
            FluidBuffers b = FluidTestScenes.Block(c, 4000, float3.zero, new float3(0.3f, 0.3f, 0.3f));
            var counters = new FluidPassCounters();
            int live = FluidSolver.SortParticles(c, b.Particles, b.Scratch, b.Status.Count, false, ref counters);
            FluidPasses.Density(c, default, b.Particles, b.Scratch, 0, live, ref counters);
            // Each call is a substep's first iteration (the renormalization computed afresh: 1 on the rest lattice).
            b.Scratch.Floats.Clear();
            const float step = 1e-3f;
            var weight = new float[live];
            for (int i = 0; i < live; i++)
            {
                b.Velocities[i] = float3.zero;
                b.Scratch.VectorsA[i] = new float3(1f, 0f, 0f);
            }
            FluidPasses.ViscosityIteration(c, default, b.Particles, b.Scratch, b.Scratch.VectorsA, b.Scratch.VectorsB, 0, live, step);
            for (int i = 0; i < live; i++)
                weight[i] = b.Scratch.VectorsB[i].x / (1f - b.Scratch.VectorsB[i].x);
            for (int i = 0; i < live; i++)
            {
                float y = b.Positions[i].y - 0.15f;
                b.Velocities[i] = new float3(y * y, 0f, 0f);
                b.Scratch.VectorsA[i] = b.Velocities[i];
            }
            b.Scratch.Floats.Clear();
            FluidPasses.ViscosityIteration(c, default, b.Particles, b.Scratch, b.Scratch.VectorsA, b.Scratch.VectorsB, 0, live, step);
            int checkedCount = 0;
            double expected = 2.0 * step * p.Viscosity;
            for (int i = 0; i < live; i++)
            {
                float3 x = b.Positions[i];
                if (math.any(math.abs(x - 0.15f) > 0.02f))
                    continue;
                checkedCount++;
                double increment = (double)b.Scratch.VectorsB[i].x - b.Velocities[i].x;
                Assert.AreEqual(expected, increment * (1 + weight[i]), 1e-3 * expected, $"particle at {x}");
            }
            Assert.Greater(checkedCount, 0);
        }

        [Test]
        public void PoiseuilleFlow_ConvergedViscosity_ConvergesToTheAnalyticProfile()
        {
            // At the default viscosity iterations (which the step raises until the solve converges) the profile error falls at
            // least first order from W/5 to W/10 and reaches the 1 % of u_max the package promises for a bought resolution (a
            // fluid at rest in a free-slip channel would be 67 %).
            FluidParameters p = FluidParameters.Default;
            p.SpeedOfSound = 10f * PoiseuilleScenario.PeakSpeed;
            var coarse = new PoiseuilleScenario(5, p, "test");
            var fine = new PoiseuilleScenario(10, p, "test");
            coarse.Setup();
            fine.Setup();
            Assert.Less(fine.ProfileError, 0.5 * coarse.ProfileError, "first order or better");
            Assert.Less(fine.ProfileError, 0.01);
        }

        [Test]
        public void ViscosityIterations_RiseWithTheSubstepUntilTheSolveConverges()
        {
            // (a/(1 + a))ⁿ ≤ 0.01 with a = 15·hν·κ_ν/h²: honey at W/20 of the channel (Δx = 5 mm) and 3.6 ms substeps has a ≈ 3.9,
            // n = 20; water at the defaults keeps the iterations it asks for; no viscosity, no pass.
            FluidParameters q = FluidParameters.Default;
            q = PoiseuilleScenario.Channel(q, 20);
            var c = new FluidConstants(q);
            float h = 3.6e-3f;
            float a = 15f * h * q.Viscosity * c.ViscosityCorrection / (c.Kernels.H * c.Kernels.H);
            int expected = (int)Math.Ceiling(Math.Log(0.01) / Math.Log(a / (1.0 + a)));
            Assert.AreEqual(expected, FluidSolver.ViscosityIterations(c, h));
            Assert.Greater(expected, q.ViscosityIterations);
            Assert.That(Math.Pow(a / (1.0 + a), expected), Is.LessThanOrEqualTo(0.01));
            Assert.That(Math.Pow(a / (1.0 + a), expected - 1), Is.GreaterThan(0.01));
            var water = new FluidConstants(FluidParameters.Default);
            Assert.AreEqual(FluidParameters.Default.ViscosityIterations, FluidSolver.ViscosityIterations(water, 1f / 600f));
            FluidParameters none = FluidParameters.Default;
            none.Viscosity = 0f;
            Assert.AreEqual(0, FluidSolver.ViscosityIterations(new FluidConstants(none), 1f / 600f));
            q.SpeedOfSound = 0.01f;
            Assert.AreEqual(FluidParameters.MaxViscosityIterations, FluidSolver.ViscosityIterations(new FluidConstants(q), 1f));
        }

        [TestCase(-0.1f, 0f)]
        [TestCase(0f, 1.5f)]
        [TestCase(float.NaN, 0f)]
        public void WallShareOutsideZeroToOne_IsABakeWarningAndClamped(float noSlip, float friction)
        {
            var issues = new System.Collections.Generic.List<ValidationIssue>();
            FluidParameters p = FluidParameters.Default;
            Assert.IsTrue(FluidValidation.Validate(p, 1000, issues));
            Assert.IsFalse(issues.Exists(i => i.Code == FluidIssueCode.WallShareOutOfRange), "defaults");
            p.DomainNoSlip = new float3(0f, noSlip, 0f);
            p.WallFriction = friction;
            Assert.IsTrue(FluidValidation.Validate(p, 1000, issues), "a warning, not an error");
            Assert.IsTrue(issues.Exists(i => i.Code == FluidIssueCode.WallShareOutOfRange));
            FluidParameters s = p.Sanitized();
            Assert.That(s.DomainNoSlip.y, Is.InRange(0f, 1f));
            Assert.That(s.WallFriction, Is.InRange(0f, 1f));
        }

        [Test]
        public void ShortPeriodicAxisAndUnconvergedViscosity_AreBakeWarnings()
        {
            var issues = new System.Collections.Generic.List<ValidationIssue>();
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.1f, 0.5f, 0.5f));
            p.Periodic = new bool3(true, false, false);
            Assert.IsTrue(FluidValidation.Validate(p, 1000, issues));
            Assert.IsTrue(issues.Exists(i => i.Code == FluidIssueCode.PeriodicAxisTooShort));

            // The Poiseuille channel at W/40 with c₀ = 0.3 m/s: substeps of 6.7 ms, a = 15·hν·κ_ν/h² ≈ 29, 134 iterations for 1 %,
            // past the 50 a substep may run. At c₀ = 1 m/s (2 ms, a ≈ 8.6) 42 iterations do, and the step runs them.
            issues.Clear();
            FluidParameters q = FluidParameters.Default;
            q.SpeedOfSound = 0.3f;
            q = PoiseuilleScenario.Channel(q, 40);
            Assert.IsTrue(FluidValidation.Validate(q, 10000, issues));
            Assert.IsTrue(issues.Exists(i => i.Code == FluidIssueCode.ViscosityUnresolved));
            issues.Clear();
            q.SpeedOfSound = 10f * PoiseuilleScenario.PeakSpeed;
            Assert.IsTrue(FluidValidation.Validate(q, 10000, issues));
            Assert.IsFalse(issues.Exists(i => i.Code == FluidIssueCode.ViscosityUnresolved));
            foreach (FluidPresetKind kind in new[] { FluidPresetKind.Water, FluidPresetKind.Honey, FluidPresetKind.Oil, FluidPresetKind.Slime, FluidPresetKind.Lava })
            {
                issues.Clear();
                Assert.IsTrue(FluidValidation.Validate(FluidPresets.Get(kind).Parameters, 1000, issues));
                Assert.IsFalse(issues.Exists(i => i.Code == FluidIssueCode.ViscosityUnresolved), $"{kind} at its defaults");
            }
        }
    }
}
