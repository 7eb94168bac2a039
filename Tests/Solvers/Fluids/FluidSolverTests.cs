using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Behaviour of the fluid step: conservation, implicit viscosity, rest, hard cases, determinism, colliders.</summary>
    public class FluidSolverTests
    {
        static readonly float3 s_Box = new float3(0.2f, 0.4f, 0.2f);

        static double3x Momentum(FluidBuffers b)
        {
            var m = new double3x();
            for (int i = 0; i < b.Status.Count; i++)
            {
                m.X += b.Velocities[i].x;
                m.Y += b.Velocities[i].y;
                m.Z += b.Velocities[i].z;
                m.Scale += math.length(b.Velocities[i]);
            }
            return m;
        }

        struct double3x { public double X, Y, Z, Scale; }

        [TestCase(FluidSolverKind.WeaklyCompressible)]
        [TestCase(FluidSolverKind.PositionBased)]
        public void FreeBlob_ConservesLinearMomentum(FluidSolverKind solver)
        {
            // No gravity, walls a metre away, random velocities: pressure, artificial viscosity and the position-based
            // corrections act in equal and opposite pairs, and the implicit viscosity's symmetric weights conserve momentum
            // once converged (it is switched off here). Float32 pair sums of ~30 terms per particle over 100 substeps:
            // |ΔP| ≤ 1e-4 of Σ|v| (round-off 1.2e-7 per operation, a few thousand operations per particle, random signs).
            FluidParameters p = FreeBlob(solver);
            p.ViscosityIterations = 0;
            AssertMomentumKept(p);
        }

        [TestCase(FluidSolverKind.WeaklyCompressible)]
        [TestCase(FluidSolverKind.PositionBased)]
        public void FreeBlob_ConvergedViscosity_ConservesLinearMomentum(FluidSolverKind solver)
        {
            // The blob above with the implicit viscosity on and converged: ν = 0.01 m²/s at Δx = 2 cm contracts a Jacobi
            // iteration by a/(1 + a) ≤ 0.61, so 50 iterations leave ~1e-11 of the first. The renormalized weights
            // (sᵢ + sⱼ)/2·wᵢⱼ stay symmetric, so the converged solve exchanges momentum in equal and opposite pairs: the same
            // round-off bound (a per-particle row scale sᵢ·wᵢⱼ would drift by ~1e-3).
            FluidParameters p = FreeBlob(solver);
            p.Viscosity = 0.01f;
            p.ViscosityIterations = FluidParameters.MaxViscosityIterations;
            AssertMomentumKept(p);
        }

        /// <summary>Water at Δx = 2 cm without gravity in a 2 m box, solved by <paramref name="solver"/>.</summary>
        static FluidParameters FreeBlob(FluidSolverKind solver)
        {
            FluidParameters p = FluidTestScenes.Water(0.02f, new float3(-1f), new float3(1f));
            p.Gravity = float3.zero;
            p.Solver = solver;
            return p;
        }

        /// <summary>A 0.2 m block of 1000 particles at random velocities, 10 frames: |ΔP| within 1e-4 of Σ|v|.</summary>
        static void AssertMomentumKept(FluidParameters p)
        {
            var c = new FluidConstants(p);
            FluidBuffers b = FluidTestScenes.Block(c, 1000, new float3(-0.1f), new float3(0.1f));
            var random = new System.Random(3);
            for (int i = 0; i < b.Status.Count; i++)
                b.Velocities[i] = new float3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f);
            double3x before = Momentum(b);
            for (int f = 0; f < 10; f++)
                FluidTestScenes.Step(c, b, 1f / 60f);
            double3x after = Momentum(b);
            Assert.AreEqual(1000, b.Status.Count);
            double drift = Math.Sqrt(Math.Pow(after.X - before.X, 2) + Math.Pow(after.Y - before.Y, 2) + Math.Pow(after.Z - before.Z, 2));
            Assert.That(drift, Is.LessThan(1e-4 * before.Scale));
        }

        [Test]
        public void ImplicitViscosity_IsBoundedForAnyViscosity()
        {
            // ν = 1000 m²/s (a million times honey): each Jacobi iterate is a weighted average of v⁰ and the neighbours,
            // so no speed may exceed the largest initial one (plus one substep of gravity, here zero).
            FluidParameters p = FluidTestScenes.Water(0.02f, new float3(-1f), new float3(1f));
            p.Gravity = float3.zero;
            p.Viscosity = 1000f;
            p.ViscosityIterations = 10;
            p.ArtificialViscosity = 0f;
            p.SpeedOfSound = 1f;
            var c = new FluidConstants(p);
            FluidBuffers b = FluidTestScenes.Block(c, 1000, new float3(-0.1f), new float3(0.1f));
            var random = new System.Random(4);
            float vmax = 0f;
            for (int i = 0; i < b.Status.Count; i++)
            {
                b.Velocities[i] = new float3((float)random.NextDouble() - 0.5f, 0f, 0f);
                vmax = math.max(vmax, math.length(b.Velocities[i]));
            }
            for (int f = 0; f < 5; f++)
            {
                FluidStepReport r = FluidTestScenes.Step(c, b, 1f / 60f);
                Assert.AreEqual(0, r.Invalid);
            }
            float after = 0f;
            for (int i = 0; i < b.Status.Count; i++)
                after = math.max(after, math.length(b.Velocities[i]));
            // Pressure forces (c₀ = 1 m/s, a lattice at rest density) add at most a few mm/s.
            Assert.That(after, Is.LessThan(vmax + 0.01f));
            Assert.That(after, Is.LessThan(0.1f * vmax), "a very viscous blob moves nearly rigidly: the random shear is gone");
        }

        /// <summary>0.1 × 0.2 × 0.1 m of water at Δx = 2 cm settled for 2 s: (kinetic energy per mass, top, mean bulk density error).</summary>
        static (double kinetic, float top, double densityError, int count) SettledColumn(FluidSolverKind solver, int iterations,
            float artificialPressure = -1f)
        {
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.1f, 0.4f, 0.1f));
            p.Solver = solver;
            p.PressureIterations = iterations;
            if (artificialPressure >= 0f)
                p.ArtificialPressure = artificialPressure;
            p.SpeedOfSound = 10f * math.sqrt(2f * 9.81f * 0.2f);
            var c = new FluidConstants(p);
            FluidBuffers b = FluidTestScenes.Block(c, 250, float3.zero, new float3(0.1f, 0.2f, 0.1f));
            for (int f = 0; f < 120; f++)
                FluidTestScenes.Step(c, b, 1f / 60f);
            double ke = 0, density = 0;
            int bulk = 0;
            float top = 0f;
            for (int i = 0; i < b.Status.Count; i++)
            {
                ke += 0.5 * math.lengthsq(b.Velocities[i]);
                top = math.max(top, b.Positions[i].y);
                Assert.That(math.all(b.Positions[i] >= p.DomainMin) && math.all(b.Positions[i] <= p.DomainMax));
                if (b.NeighbourCounts[i] < 15)
                    continue;
                density += Math.Abs(b.Densities[i] / 1000.0 - 1.0);
                bulk++;
            }
            return (ke / b.Status.Count, top, density / Math.Max(1, bulk), b.Status.Count);
        }

        [TestCase(FluidSolverKind.WeaklyCompressible)]
        [TestCase(FluidSolverKind.PositionBased)]
        public void HydrostaticColumn_StaysAtRest(FluidSolverKind solver)
        {
            var (kinetic, top, densityError, count) = SettledColumn(solver, 4);
            TestContext.WriteLine($"{solver}: kinetic {kinetic:E2} J/kg, top {top:F4} m, density error {densityError:P2}");
            Assert.AreEqual(250, count);
            // At rest: kinetic energy per mass ≪ g·Δx = 0.2 J/kg (a particle bouncing one spacing high).
            Assert.That(kinetic, Is.LessThan(0.01 * 9.81 * 0.02));
            Assert.That(top, Is.LessThan(0.2f + 0.02f), "the surface stays where it was, within a spacing");
            // Weakly compressible with c₀ = 10·√(2gH) = 19.8 m/s: the Tait law holds the floor at
            // ρ/ρ₀ ≈ 1 + gH/c₀² = 1.005, so the mean bulk density error is below 1 %.
            if (solver == FluidSolverKind.WeaklyCompressible)
                Assert.That(densityError, Is.LessThan(0.01));
        }

        [Test]
        public void ArtificialViscosity_IsOnlyWhatThePhysicalViscosityLacks()
        {
            // α' = α·max(0, 1 − ν/ν_α), ν_α = α·h·c₀/10 = 0.05 × 0.04 m × 10 m/s / 10 = 2e-3 m²/s at Δx = 2 cm: water keeps
            // nearly all of α, oil 95.6 % of it, a fluid at ν_α or above none (float32 round-off of a few operations: 1e-6).
            foreach (var (kind, expected) in new[] { (FluidPresetKind.Water, 0.05 * (1 - 1e-6 / 2e-3)), (FluidPresetKind.Oil, 0.05 * (1 - 8.8e-5 / 2e-3)),
                         (FluidPresetKind.Honey, 0.0), (FluidPresetKind.Slime, 0.0), (FluidPresetKind.Lava, 0.0) })
            {
                FluidParameters p = FluidPresets.Get(kind).Parameters;
                p.ParticleSpacing = 0.02f;
                Assert.That(new FluidConstants(p).EffectiveArtificialViscosity, Is.EqualTo(expected).Within(1e-6), kind.ToString());
            }
            FluidParameters atThreshold = FluidTestScenes.Water(0.02f, float3.zero, new float3(1f));
            atThreshold.Viscosity = 2e-3f;
            Assert.That(new FluidConstants(atThreshold).EffectiveArtificialViscosity, Is.LessThan(1e-6f));
        }

        [Test]
        public void HoneyColumn_RestsOnItsOwnViscosity()
        {
            // The honey preset's ν = 7e-3 m²/s is 3.5 times the artificial viscosity's 2e-3, so it runs with none: the 0.4 m
            // column of DeepColumnAtDefaults still rests to 1e-5 J/kg over its fourth second (measured 2.1e-6).
            FluidParameters p = FluidPresets.Get(FluidPresetKind.Honey).Parameters;
            p.ParticleSpacing = 0.02f;
            p.DomainMin = float3.zero;
            p.DomainMax = new float3(0.12f, 0.6f, 0.12f);
            var c = new FluidConstants(p);
            Assert.That(c.EffectiveArtificialViscosity, Is.EqualTo(0f));
            FluidBuffers b = FluidTestScenes.Block(c, 720, float3.zero, new float3(0.12f, 0.4f, 0.12f));
            Assert.That(MeanKineticEnergyOverFourthSecond(c, b), Is.LessThan(1e-5));
        }

        /// <summary>Runs 4 s of 1/60 s frames; the mean kinetic energy per mass (J/kg) of five samples over the fourth second.</summary>
        static double MeanKineticEnergyOverFourthSecond(in FluidConstants c, FluidBuffers b)
        {
            double mean = 0;
            for (int f = 1; f <= 240; f++)
            {
                FluidTestScenes.Step(c, b, 1f / 60f);
                if (f < 180 || f % 15 != 0)
                    continue;
                double ke = 0;
                for (int i = 0; i < b.Status.Count; i++)
                    ke += 0.5 * math.lengthsq(b.Velocities[i]);
                ke /= b.Status.Count;
                TestContext.WriteLine($"kinetic energy at {f / 60.0:0.00} s: {ke:E2} J/kg");
                mean += ke / 5;
            }
            return mean;
        }

        [Test]
        public void DeepColumnAtDefaults_RestsOverItsFourthSecond()
        {
            // 0.12 × 0.4 × 0.12 m released on a lattice at ρ₀ (720 particles, defaults: c₀ = 10 m/s, Δx = 2 cm). Gravity
            // compresses it by gH/c₀² ≈ 4 % at the floor, which starts the vertical acoustic mode (period 4H/c₀ = 0.16 s);
            // a shear viscosity of α·h·c₀/10 damps that mode at νk² ≈ 0.03/s, so only the bulk viscosity can bring the
            // kinetic energy under 1e-5 J/kg (the column's g·Δx·1e-4 J/kg, 0.4 mm/s RMS): without it 2.8e-3 J/kg at 3 s. What
            // is left at 3 s is the particles' last rearrangement, 0.6–26·10⁻⁶ J/kg at one instant as the viscosity changes
            // by 2 %, so the mean over the fourth second (five samples) is what is pinned.
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.12f, 0.6f, 0.12f));
            Assert.That(p.SpeedOfSound, Is.EqualTo(FluidParameters.Default.SpeedOfSound));
            Assert.That(p.BulkViscosity, Is.EqualTo(FluidParameters.Default.BulkViscosity));
            var c = new FluidConstants(p);
            FluidBuffers b = FluidTestScenes.Block(c, 720, float3.zero, new float3(0.12f, 0.4f, 0.12f));
            Assert.AreEqual(720, b.Status.Count);
            Assert.That(MeanKineticEnergyOverFourthSecond(c, b), Is.LessThan(1e-5));
        }

        /// <summary>
        /// 0.12 × 0.8 × 0.12 m at Δx = 2 cm (40 layers, 1440 particles), position-based at 4 iterations, 4 s of 1/60 s
        /// frames: (highest kinetic energy per mass, its mean over the fourth second, highest particle, bulk density error).
        /// The kinetic energy at one instant after 3 s moves by ×5–×20 with any small change of the setup (the particles'
        /// last rearrangements), so the mean over a second is what the tests read.
        /// </summary>
        static (double highest, double last, float top, double density) FortyLayerColumn(float xsphRate)
        {
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.12f, 1.2f, 0.12f));
            p.Solver = FluidSolverKind.PositionBased;
            p.XsphRate = xsphRate;
            Assert.That(p.PressureIterations, Is.EqualTo(FluidParameters.Default.PressureIterations));
            var c = new FluidConstants(p);
            FluidBuffers b = FluidTestScenes.Block(c, 1440, float3.zero, new float3(0.12f, 0.8f, 0.12f));
            Assert.AreEqual(1440, b.Status.Count);
            double highest = 0, kinetic = 0;
            float top = 0f;
            for (int f = 1; f <= 240; f++)
            {
                FluidTestScenes.Step(c, b, 1f / 60f);
                double ke = 0;
                for (int i = 0; i < b.Status.Count; i++)
                {
                    ke += 0.5 * math.lengthsq(b.Velocities[i]);
                    top = math.max(top, b.Positions[i].y);
                }
                ke /= b.Status.Count;
                highest = math.max(highest, ke);
                if (f > 180)
                    kinetic += ke / 60;
            }
            Assert.AreEqual(1440, b.Status.Count);
            double density = 0;
            int bulk = 0;
            for (int i = 0; i < b.Status.Count; i++)
                if (b.NeighbourCounts[i] >= 15)
                {
                    density += Math.Abs(b.Densities[i] / 1000.0 - 1.0);
                    bulk++;
                }
            density /= bulk;
            TestContext.WriteLine($"XSPH {xsphRate}/s: highest kinetic energy {highest:E2} J/kg, mean over the fourth second {kinetic:E2} J/kg, top {top:F3} m, bulk density error {density:P2}");
            return (highest, kinetic, top, density);
        }

        [Test]
        public void Depth_IsTheExtentAlongGravityInsideTheBox()
        {
            // Two particles 0.3 m apart vertically: depth 0.3 + Δx. A stray one at y = 1e20 counts as on the lid (1 m), a NaN one
            // not at all; the weakly compressible solver plans no depth.
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(1f));
            p.Solver = FluidSolverKind.PositionBased;
            var c = new FluidConstants(p);
            var x = new[] { new float3(0.5f, 0.1f, 0.5f), new float3(0.5f, 0.4f, 0.5f), new float3(float.NaN) };
            Assert.That(FluidSolver.Depth(c, x), Is.EqualTo(0.32f).Within(1e-6f));
            x[2] = new float3(0.5f, 1e20f, 0.5f);
            Assert.That(FluidSolver.Depth(c, x), Is.EqualTo(0.92f).Within(1e-6f));
            p.Solver = FluidSolverKind.WeaklyCompressible;
            Assert.That(FluidSolver.Depth(new FluidConstants(p), x), Is.EqualTo(0f));
        }

        [Test]
        public void PositionBasedDepthRule_HoldsAFortyLayerColumnWithoutSmoothing()
        {
            // One substep per frame lets gravity press the column by g·h² = 2.7 mm a substep while 4 Jacobi iterations lift
            // only the bottom layers: the column collapses and splashes to the lid (4–11 J/kg). The depth rule plans the
            // substeps for the column's height so that the density error ε ≈ 0.23·g·h²·D/(Δx²·iterations) stays near 1 %.
            var (highest, last, top, density) = FortyLayerColumn(FluidParameters.Default.XsphRate);
            // No collapse: less kinetic energy than a 1 cm free fall (g·0.01 m ≈ 0.1 J/kg), no particle more than five
            // layers above the start (the released lattice rises by about one; the splash reaches the lid), and at rest
            // after 3 s: ≪ g·Δx = 0.2 J/kg, like the 10-layer column.
            Assert.That(highest, Is.LessThan(0.1));
            Assert.That(top, Is.LessThan(0.8f + 5 * 0.02f));
            Assert.That(last, Is.LessThan(0.01 * 9.81 * 0.02));
            Assert.That(density, Is.LessThan(0.02));
        }

        [Test]
        public void PositionBasedDefaults_ComeToRestWithin3Seconds()
        {
            // The residual of 4 Jacobi iterations keeps the surface layers moving (it becomes a velocity of its size over h);
            // the solver's default XSPH smoothing (Macklin & Müller 2013's eq. 17 as a rate) damps that relative motion, so
            // the 40-layer column is at rest to 1e-5 J/kg (0.4 mm/s RMS) over the fourth second, and the density stays
            // within 2 %.
            var (_, last, _, density) = FortyLayerColumn(FluidParameters.Default.XsphRate);
            Assert.That(last, Is.LessThan(1e-5));
            Assert.That(density, Is.LessThan(0.02));
        }

        [Test]
        public void PositionBased_DensityErrorFallsWithIterations()
        {
            // Jacobi iterations of the density constraint converge: four times the iterations must leave a clearly
            // smaller error (the settled column). Without the artificial pressure, whose repulsion is part of what the
            // iterations solve and so sets a floor of its own.
            double e4 = SettledColumn(FluidSolverKind.PositionBased, 4, 0f).densityError;
            double e16 = SettledColumn(FluidSolverKind.PositionBased, 16, 0f).densityError;
            TestContext.WriteLine($"density error: 4 iterations {e4:P2}, 16 iterations {e16:P2}");
            Assert.That(e16, Is.LessThan(0.7 * e4));
        }

        [Test]
        public void IsolatedParticle_FallsFreely()
        {
            // One particle far from every wall: no neighbour, no wall term, so each substep is exact symplectic Euler
            // under gravity: after n substeps of h, v = −g·n·h and y = y₀ − g·h²·n(n+1)/2 (float32, 1e-5 relative).
            FluidParameters p = FluidTestScenes.Water(0.02f, new float3(-1f), new float3(1f, 3f, 1f));
            var c = new FluidConstants(p);
            var b = new FluidBuffers(1, c.Grid);
            b.Positions[0] = new float3(0f, 2f, 0f);
            b.Status.Count = 1;
            int substeps = 0;
            for (int f = 0; f < 20; f++)
                substeps += FluidTestScenes.Step(c, b, 1f / 60f).Substeps;
            Assert.AreEqual(1, b.Status.Count);
            Assert.AreEqual(c.Mass * c.Kernels.Poly6(0f), b.Densities[0], 1e-6f * b.Densities[0], "density = m·W(0)");
            float expected = 20f / 60f * -9.81f;
            Assert.That(b.Velocities[0].y, Is.EqualTo(expected).Within(1e-4f * math.abs(expected)));
            Assert.That(b.Positions[0].y, Is.LessThan(2f - 0.5f * 9.81f * (20f / 60f) * (20f / 60f) * 0.99f));
            Assert.That(substeps, Is.GreaterThanOrEqualTo(20));
        }

        [Test]
        public void EveryParticleAtOnePoint_SeparatesAndStaysFinite()
        {
            // 200 particles at one point: the spiky gradient has no direction at r = 0, so the pair direction comes
            // from the ids. After 1 s they must have spread (mean distance from the centre > a spacing), stay finite and
            // in the domain, with the overload reported.
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.4f));
            var c = new FluidConstants(p);
            var b = new FluidBuffers(200, c.Grid);
            for (int i = 0; i < 200; i++)
            {
                b.Positions[i] = new float3(0.2f);
                b.Ids[i] = i;
            }
            b.Status.Count = 200;
            FluidStepReport first = FluidTestScenes.Step(c, b, 1f / 60f);
            Assert.That(first.NeighbourOverflow, Is.GreaterThan(0), "199 neighbours each: more than the list holds, and reported");
            Assert.That(first.OverCompressed, Is.GreaterThan(0));
            for (int f = 0; f < 59; f++)
                FluidTestScenes.Step(c, b, 1f / 60f);
            Assert.AreEqual(200, b.Status.Count);
            double spread = 0;
            for (int i = 0; i < 200; i++)
            {
                Assert.That(math.all(math.isfinite(b.Positions[i])) && math.all(math.isfinite(b.Velocities[i])));
                Assert.That(math.all(b.Positions[i] >= p.DomainMin) && math.all(b.Positions[i] <= p.DomainMax));
                spread += math.length(b.Positions[i] - new float3(0.2f, b.Positions[i].y, 0.2f));
            }
            Assert.That(spread / 200, Is.GreaterThan(0.02));
        }

        [Test]
        public void NaNInjected_RemovesOnlyThatParticleAndReportsIt()
        {
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.2f, 0.4f, 0.2f));
            var c = new FluidConstants(p);
            FluidBuffers b = FluidTestScenes.Block(c, 500, float3.zero, new float3(0.2f, 0.1f, 0.2f));
            int n = b.Status.Count;
            FluidTestScenes.Step(c, b, 1f / 60f);
            b.Velocities[17] = new float3(float.NaN, 0f, 0f);
            FluidStepReport r = FluidTestScenes.Step(c, b, 1f / 60f);
            Assert.AreEqual(1, r.Invalid);
            Assert.AreEqual(n - 1, r.Count);
            Assert.AreEqual(1, b.Status.Invalid);
            for (int f = 0; f < 30; f++)
                Assert.AreEqual(0, FluidTestScenes.Step(c, b, 1f / 60f).Invalid, "no spread to the neighbours");
            Assert.AreEqual(n - 1, b.Status.Count);
        }

        [Test]
        public void MinSubsteps_RaiseTheSubstepsUpToTheCap_AndShortenH()
        {
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.2f, 0.4f, 0.2f));
            int cfl = FluidSolver.Substeps(new FluidConstants(p), 0f, 0f, 1f / 60f).x;
            Assert.That(cfl, Is.LessThan(p.MaxSubsteps - 1), "the CFL limit alone leaves room below the cap");
            p.MinSubsteps = cfl + 2;
            Assert.That(FluidSolver.Substeps(new FluidConstants(p), 0f, 0f, 1f / 60f), Is.EqualTo(new int2(cfl + 2, cfl + 2)));
            p.MinSubsteps = cfl - 1;
            Assert.That(FluidSolver.Substeps(new FluidConstants(p), 0f, 0f, 1f / 60f), Is.EqualTo(new int2(cfl, cfl)), "below the CFL count: no effect");
            p.MinSubsteps = p.MaxSubsteps + 10;
            Assert.That(FluidSolver.Substeps(new FluidConstants(p), 0f, 0f, 1f / 60f), Is.EqualTo(new int2(p.MaxSubsteps, p.MaxSubsteps)),
                "capped, with h = dt / cap: the step still simulates the whole dt");
            var issues = new List<ValidationIssue>();
            Assert.That(FluidValidation.Validate(p, 1000, issues), Is.True);
            Assert.That(issues.Exists(i => i.Code == FluidIssueCode.SubstepCapTooLow && i.Message.Contains("fewest substeps")), string.Join("\n", issues));
        }

        [Test]
        public void InfiniteVelocity_DoesNotSetTheSubsteps()
        {
            // The particle with an infinite velocity is removed by the first sort; the substeps must come from the others
            // (a resting block: as many as at rest, far below the cap).
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.2f, 0.4f, 0.2f));
            var c = new FluidConstants(p);
            FluidBuffers b = FluidTestScenes.Block(c, 500, float3.zero, new float3(0.2f, 0.1f, 0.2f));
            int atRest = FluidSolver.Substeps(c, 0f, 0f, 1f / 60f).y;
            b.Velocities[3] = new float3(float.PositiveInfinity, 0f, 0f);
            FluidStepReport r = FluidTestScenes.Step(c, b, 1f / 60f);
            Assert.AreEqual(1, r.Invalid);
            Assert.AreEqual(atRest, r.Substeps);
        }

        /// <summary>
        /// A 1 s step of a resting block asks for far more substeps than the cap. The step runs the cap's substeps at the CFL
        /// length h = dt / wanted, so it simulates MaxSubsteps · h &lt; dt (slow motion, reported, in the status's time) and the
        /// fluid stays what it is: below the solver's own over-compression bound <see cref="FluidParameters.MaxDensityRatio"/>
        /// (1.5 ρ₀) in every step, with no over-compressed particle-substep. Stretching the capped substeps to dt compressed it
        /// to 14 ρ₀ in the first step.
        /// </summary>
        [Test]
        public void HugeStep_RunsInSlowMotion_AndKeepsTheFluid()
        {
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.2f, 0.4f, 0.2f));
            var c = new FluidConstants(p);
            FluidBuffers b = FluidTestScenes.Block(c, 500, float3.zero, new float3(0.2f, 0.2f, 0.2f));
            double time = 0;
            for (int f = 0; f < 6; f++)
            {
                FluidStepReport r = FluidTestScenes.Step(c, b, 1f);
                Assert.AreEqual(p.MaxSubsteps, r.Substeps);
                Assert.That(r.SubstepsWanted, Is.GreaterThan(r.Substeps));
                Assert.That(r.MaxDensityRatio, Is.LessThanOrEqualTo(p.MaxDensityRatio), $"step {f}");
                Assert.AreEqual(0, r.OverCompressed, $"step {f}");
                Assert.That(r.SimulatedTime, Is.EqualTo(r.Substeps * (1.0 / r.SubstepsWanted)).Within(1e-6));
                time += r.SimulatedTime;
            }
            Assert.That(b.Status.Time, Is.EqualTo(time).Within(1e-5));
            for (int i = 0; i < b.Status.Count; i++)
            {
                Assert.That(math.all(math.isfinite(b.Positions[i])));
                Assert.That(math.all(b.Positions[i] >= p.DomainMin) && math.all(b.Positions[i] <= p.DomainMax));
                Assert.That(math.length(b.Velocities[i]), Is.LessThanOrEqualTo(p.MaxSpeed * 1.0001f));
            }
        }

        /// <summary>
        /// One particle resting on the domain floor, sliding at 1 m/s. Each substep gravity carries it g·h² into the floor
        /// and the clamp cancels up to μ × that depth of its sliding, so its speed falls by μ·g·h per substep: Coulomb
        /// friction, v(t) = v₀ − μgt until it stops (within one substep's μgh). Free slip (μ = 0) keeps v₀; so does a floor
        /// whose own μ.y is 0 while the faces normal to x and z grip (the friction is per axis), and collider friction.
        /// </summary>
        [TestCase(FluidSolverKind.WeaklyCompressible, 0f, 0f)]
        [TestCase(FluidSolverKind.WeaklyCompressible, 0.5f, 0f)]
        [TestCase(FluidSolverKind.WeaklyCompressible, 0f, 0.5f)]
        [TestCase(FluidSolverKind.PositionBased, 0f, 0f)]
        [TestCase(FluidSolverKind.PositionBased, 0.5f, 0f)]
        [TestCase(FluidSolverKind.PositionBased, 0f, 0.5f)]
        public void DomainFloor_SlowsASlidingParticleAtMuG(FluidSolverKind solver, float mu, float otherFaces)
        {
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(2f, 0.4f, 0.4f));
            p.Solver = solver;
            p.DomainFriction = new float3(otherFaces, mu, otherFaces);
            p.WallFriction = otherFaces;
            var c = new FluidConstants(p);
            var b = new FluidBuffers(1, c.Grid);
            b.Positions[0] = new float3(0.2f, c.WallDistance, 0.2f);
            b.Velocities[0] = new float3(1f, 0f, 0f);
            b.Status = new FluidStatus { Count = 1, NextId = 1, Spawned = 1 };
            double t = 0, largestSubstep = 0;
            for (int f = 0; f < 6; f++)
            {
                FluidStepReport r = FluidTestScenes.Step(c, b, 1f / 60f);
                t += r.SimulatedTime;
                largestSubstep = Math.Max(largestSubstep, r.SimulatedTime / r.Substeps);
            }
            double expected = Math.Max(0.0, 1.0 - mu * 9.81 * t);
            Assert.That(b.Velocities[0].x, Is.EqualTo(expected).Within(mu * 9.81 * largestSubstep + 1e-5));
            Assert.That(b.Positions[0].y, Is.EqualTo(c.WallDistance).Within(1e-6));
        }

        /// <summary>An uncapped step simulates exactly its dt.</summary>
        [Test]
        public void UncappedStep_SimulatesItsWholeStep()
        {
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.2f, 0.4f, 0.2f));
            var c = new FluidConstants(p);
            FluidBuffers b = FluidTestScenes.Block(c, 500, float3.zero, new float3(0.2f, 0.2f, 0.2f));
            FluidStepReport r = FluidTestScenes.Step(c, b, 1f / 60f);
            Assert.AreEqual(r.SubstepsWanted, r.Substeps);
            Assert.AreEqual(1f / 60f, r.SimulatedTime);
            Assert.AreEqual(1f / 60f, b.Status.Time);
        }

        [Test]
        public void Step_HasTheSameBitsTwiceAndForAnyBatchSplit()
        {
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.2f, 0.4f, 0.2f));
            p.ViscosityIterations = 2;
            var c = new FluidConstants(p);
            var (a, b) = FluidTestScenes.Twins(c, 600, float3.zero, new float3(0.2f, 0.2f, 0.1f));
            for (int f = 0; f < 10; f++)
            {
                FluidTestScenes.Step(c, a, 1f / 60f);
                FluidTestScenes.Step(c, b, 1f / 60f);
            }
            CollectionAssert.AreEqual(a.Positions, b.Positions);
            // The next 10 frames with every pass split into 7 batches (as the ECS job chain splits it), against one batch.
            for (int f = 0; f < 10; f++)
            {
                FluidSolver.Step(c, default, 1f / 60f, a.Particles, a.Scratch, ref a.Status);
                FluidSolver.Step(c, default, 1f / 60f, b.Particles, b.Scratch, ref b.Status, 7);
            }
            Assert.AreEqual(a.Status.Count, b.Status.Count);
            for (int i = 0; i < a.Status.Count; i++)
            {
                Assert.AreEqual(a.Ids[i], b.Ids[i]);
                Assert.AreEqual(a.Positions[i], b.Positions[i], $"slot {i}");
                Assert.AreEqual(a.Velocities[i], b.Velocities[i], $"slot {i}");
            }
        }

        [TestCase(FluidSolverKind.PositionBased, FluidCohesionModel.Akinci)]
        [TestCase(FluidSolverKind.WeaklyCompressible, FluidCohesionModel.Flocking)]
        public void BatchSplit_LeavesTheBitsUnchanged_WithCollidersAndCohesion(FluidSolverKind solver, FluidCohesionModel cohesion)
        {
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.3f, 0.4f, 0.3f));
            p.Solver = solver;
            p.Cohesion = cohesion;
            p.CohesionWeight = 30f;
            p.AlignmentRate = 2f;
            p.SurfaceTension = 0.1f;
            p.ViscosityIterations = 3;
            var c = new FluidConstants(p);
            var colliders = new[] { ColliderShape.Sphere(new float3(0.15f, 0.05f, 0.15f), 0.05f) };
            var (a, b) = FluidTestScenes.Twins(c, 800, new float3(0.05f, 0.15f, 0.05f), new float3(0.25f, 0.3f, 0.2f));
            for (int f = 0; f < 15; f++)
            {
                FluidSolver.Step(c, colliders, 1f / 60f, a.Particles, a.Scratch, ref a.Status, 1);
                FluidSolver.Step(c, colliders, 1f / 60f, b.Particles, b.Scratch, ref b.Status, 5);
            }
            Assert.AreEqual(a.Status.Count, b.Status.Count);
            CollectionAssert.AreEqual(a.Positions, b.Positions);
            CollectionAssert.AreEqual(a.Velocities, b.Velocities);
        }

        [Test]
        public void ZeroCohesionWeights_RunNoCohesionPass()
        {
            // Flocking with every weight 0 must give the bits of no cohesion at all (the pass is skipped, not run with zeros).
            FluidParameters p = FluidTestScenes.Water(0.02f, float3.zero, new float3(0.2f, 0.4f, 0.2f));
            FluidParameters q = p;
            q.Cohesion = FluidCohesionModel.Flocking;
            var cp = new FluidConstants(p);
            var cq = new FluidConstants(q);
            FluidBuffers a = FluidTestScenes.Block(cp, 500, float3.zero, new float3(0.2f, 0.1f, 0.2f));
            FluidBuffers b = FluidTestScenes.Block(cq, 500, float3.zero, new float3(0.2f, 0.1f, 0.2f));
            for (int f = 0; f < 10; f++)
            {
                FluidTestScenes.Step(cp, a, 1f / 60f);
                FluidTestScenes.Step(cq, b, 1f / 60f);
            }
            CollectionAssert.AreEqual(a.Positions, b.Positions);
            var passes = new FluidPass[FluidSubstepPasses.MaxPasses];
            int n = FluidSubstepPasses.Write(cq, 1f / 600f, false, passes);
            Assert.IsFalse(Array.IndexOf(passes, FluidPass.Alignment, 0, n) >= 0 || Array.IndexOf(passes, FluidPass.SurfaceNormals, 0, n) >= 0);
        }

        [Test]
        public void Colliders_AreNotPenetrated()
        {
            // A block falls onto a sphere, a capsule and a tilted box above the domain floor: after every frame no particle
            // centre is deeper than the wall distance (Δx/2) inside a collider, within float32 round-off of the projection.
            FluidParameters p = FluidTestScenes.Water(0.02f, new float3(-0.3f, 0f, -0.3f), new float3(0.3f, 0.8f, 0.3f));
            var c = new FluidConstants(p);
            var colliders = new[]
            {
                ColliderShape.Sphere(new float3(-0.1f, 0.15f, 0f), 0.08f),
                ColliderShape.Capsule(new float3(0.05f, 0.12f, -0.2f), new float3(0.05f, 0.12f, 0.2f), 0.04f),
                ColliderShape.Box(new float3(0.18f, 0.1f, 0f), quaternion.AxisAngle(new float3(0f, 0f, 1f), 0.4f), new float3(0.06f, 0.02f, 0.2f)),
            };
            FluidBuffers b = FluidTestScenes.Block(c, 2000, new float3(-0.2f, 0.35f, -0.1f), new float3(0.2f, 0.5f, 0.1f));
            int n = b.Status.Count;
            double closest = double.PositiveInfinity;
            for (int f = 0; f < 45; f++)
            {
                FluidTestScenes.Step(c, b, 1f / 60f, colliders);
                for (int i = 0; i < b.Status.Count; i++)
                foreach (ColliderShape shape in colliders)
                    closest = Math.Min(closest, ColliderDistance.SignedDistance(shape, b.Positions[i]));
            }
            TestContext.WriteLine($"closest particle centre to a collider surface: {closest * 1000:F3} mm (wall distance {c.WallDistance * 1000:F1} mm)");
            // The projection leaves every centre at the wall distance; float32 positions near 0.2 m round to 15 nm.
            Assert.That(closest, Is.GreaterThan(c.WallDistance - 1e-5));
            Assert.AreEqual(n, b.Status.Count);
        }
    }
}
