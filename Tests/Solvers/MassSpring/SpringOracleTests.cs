using System;
using NUnit.Framework;
using Unity.Mathematics;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Exact discrete oracles of the harmonic oscillator (stability plan §2.2, §3.6; rows 8, 9, 12): a mass on a wall
    /// spring (particle 0 pinned at x = −1, rest length 1 m, k = m = 1, so ω = 1 rad/s and the free particle rests at
    /// x = 0, where float32 resolves its displacement finely).
    /// </summary>
    public class SpringOracleTests
    {
        const float Amplitude = 0.1f;

        static (MassSpringTestBody body, MassSpringParameters p) WallSpring(MassSpringIntegrator integrator)
        {
            MassSpringTestBody body = MassSpringTestBody.Chain(1, 1f, 1f, fixedFirst: true);
            body.Positions[1] = new float3(Amplitude, 0f, 0f);
            return (body, MassSpringTestBody.Plain(integrator));
        }

        [TestCase(MassSpringIntegrator.SymplecticEuler, 0.05)]
        [TestCase(MassSpringIntegrator.SymplecticEuler, 0.1)]
        [TestCase(MassSpringIntegrator.SymplecticEuler, 0.5)]
        [TestCase(MassSpringIntegrator.Verlet, 0.05)]
        [TestCase(MassSpringIntegrator.Verlet, 0.1)]
        [TestCase(MassSpringIntegrator.Verlet, 0.5)]
        public void Spring_PeriodAndEnergyBand(MassSpringIntegrator integrator, double omegaH)
        {
            var (body, p) = WallSpring(integrator);
            float h = (float)omegaH;
            double eh0 = ModifiedEnergy(body, omegaH);
            double lowBand = 1.0 / (1.0 + omegaH / 2.0), highBand = 1.0 / (1.0 - omegaH / 2.0);
            // 200 periods (the plan's 1000 cost 5× the time and add nothing the bounds below do not already scale with);
            // the first and last upward zero crossings time them.
            const int periods = 200;
            int steps = (int)(periods * 2.0 * Math.PI / omegaH);
            double firstCrossing = -1.0, lastCrossing = 0.0, minRatio = double.MaxValue, maxRatio = 0.0, maxDrift = 0.0;
            int crossings = 0;
            double previousX = body.Positions[1].x;
            for (int n = 1; n <= steps; n++)
            {
                Assert.IsTrue(body.Step(p, h).Stepped);
                double x = body.Positions[1].x;
                if (previousX < 0.0 && x >= 0.0)
                {
                    double t = (n - 1 + -previousX / (x - previousX)) * h;
                    if (firstCrossing < 0.0)
                        firstCrossing = t;
                    lastCrossing = t;
                    crossings++;
                }
                previousX = x;
                double ratio = Energy(body) / eh0;
                minRatio = Math.Min(minRatio, ratio);
                maxRatio = Math.Max(maxRatio, ratio);
                maxDrift = Math.Max(maxDrift, Math.Abs(ModifiedEnergy(body, omegaH) / eh0 - 1.0));
            }
            double period = (lastCrossing - firstCrossing) / (crossings - 1);
            double expected = 2.0 * Math.PI / (2.0 / omegaH * Math.Asin(omegaH / 2.0));
            // Period: the discrete solution is an exact sampled sinusoid of frequency ω̃ (sin(ω̃h/2) = ωh/2); the crossing
            // times carry float32 round-off (~1e-7 of the amplitude, i.e. ~1e-7 rad of phase) spread over ≥ 400 periods.
            Assert.That(Math.Abs(period / expected - 1.0), Is.LessThanOrEqualTo(1e-4), $"period {period} vs {expected}");
            // Modified energy: conserved exactly by the map, so only float32 round-off moves it. Symplectic Euler rounds
            // x and v by ~6e-8 relative per step: a random walk over N ≤ 2.6e5 steps stays ≪ 1e-4. Position Verlet
            // forms the velocity from a position difference, so its rounding of x (6e-8 relative) is a velocity error
            // 6e-8/(ωh) per step: the walk reaches 6e-8 √(2π·periods) / (ωh)^1.5, bounded here with a factor 10.
            double drift = integrator == MassSpringIntegrator.Verlet
                ? 10.0 * 6e-8 * Math.Sqrt(2.0 * Math.PI * periods) / Math.Pow(omegaH, 1.5) : 1e-4;
            TestContext.WriteLine($"ωh {omegaH}: E_h drift {maxDrift:E2} (bound {drift:E2}), E/E_h0 in [{minRatio:F6}, {maxRatio:F6}], band [{lowBand:F6}, {highBand:F6}]");
            Assert.That(maxDrift, Is.LessThanOrEqualTo(drift));
            // Energy band of §2.2: E/E_h is exactly inside it, and E_h/E_h0 moves by at most the round-off bound above.
            Assert.That(minRatio, Is.GreaterThanOrEqualTo(lowBand * (1.0 - drift) - 1e-7));
            Assert.That(maxRatio, Is.LessThanOrEqualTo(highBand * (1.0 + drift) + 1e-7));
        }

        [Test]
        public void Verlet_PositionsEqualSymplecticEuler()
        {
            // Störmer–Verlet and symplectic Euler give the same position sequence in exact arithmetic. In float32 Verlet's
            // x_{n+1} = 2xₙ − x_{n−1} + h²a rounds xₙ (ulp ≤ 2.4e-7 for |x| ≤ 3 m) into a velocity error of ulp/h per
            // substep, so the sequences part by about ulp·N^1.5 after N substeps: ≤ 2.4e-7 · 400^1.5 ≈ 2e-3 of nothing
            // we could pin. Over 100 substeps (≈ 2.4e-4) against a 0.1 m displacement we assert 3e-4.
            foreach (bool wall in new[] { true, false })
            {
                MassSpringTestBody a = MassSpringTestBody.Chain(4, 1f, 1f, wall), b = MassSpringTestBody.Chain(4, 1f, 1f, wall);
                var random = new System.Random(7);
                for (int i = 1; i < 5; i++)
                {
                    var d = new float3((float)random.NextDouble() - 0.5f, 0f, 0f) * 0.2f;
                    a.Positions[i] += d;
                    b.Positions[i] += d;
                }
                MassSpringParameters pa = MassSpringTestBody.Plain(MassSpringIntegrator.SymplecticEuler);
                MassSpringParameters pb = MassSpringTestBody.Plain(MassSpringIntegrator.Verlet);
                pa.Body.Substeps = pb.Body.Substeps = 4;
                double maxDifference = 0.0;
                for (int n = 0; n < 25; n++)
                {
                    a.Step(pa, 0.4f);
                    b.Step(pb, 0.4f);
                    for (int i = 0; i < 5; i++)
                        maxDifference = Math.Max(maxDifference, math.length(a.Positions[i] - b.Positions[i]));
                }
                TestContext.WriteLine($"wall {wall}: max |x_SE − x_Verlet| = {maxDifference:E2} m");
                Assert.That(maxDifference, Is.LessThanOrEqualTo(3e-4), $"wall {wall}");
            }
        }

        [TestCase(0.1)]
        [TestCase(1.0)]
        public void ImplicitEuler_DampingOracle(double omegaH)
        {
            var (body, p) = WallSpring(MassSpringIntegrator.ImplicitEuler);
            float h = (float)omegaH;
            double e0 = Energy(body);
            // Backward Euler scales ½(v² + ω²x²) by exactly 1/(1 + ω²h²) per step; over n steps, and per period.
            int steps = omegaH < 0.5 ? 200 : 12;
            for (int n = 0; n < steps; n++)
                body.Step(p, h);
            double perStep = Math.Pow(Energy(body) / e0, 1.0 / steps);
            double perPeriod = Math.Pow(perStep, 2.0 * Math.PI / omegaH);
            double expected = Math.Pow(1.0 + omegaH * omegaH, -2.0 * Math.PI / omegaH);
            // 1e-3: the energy after n steps carries float32 round-off ~1e-6 relative; CG (1 particle, exact Jacobi) to 1e-6.
            Assert.That(Math.Abs(perPeriod / expected - 1.0), Is.LessThanOrEqualTo(1e-3), $"{perPeriod} vs {expected}");
        }

        [Test]
        public void ImplicitEuler_BoundedAtOmegaH100()
        {
            var (body, p) = WallSpring(MassSpringIntegrator.ImplicitEuler);
            double previous = Energy(body);
            for (int n = 0; n < 200; n++)
            {
                Assert.IsFalse(body.Step(p, 100f).Reset);
                double e = Energy(body);
                // Energy never grows (round-off allowance 1e-6 relative of the start).
                Assert.That(e, Is.LessThanOrEqualTo(previous + 1e-6 * Energy0));
                previous = e;
            }
            Assert.That(Math.Abs(body.Positions[1].x), Is.LessThanOrEqualTo(Amplitude));
        }

        static readonly double Energy0 = 0.5 * Amplitude * Amplitude;

        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        public void Chain_Modes(int j)
        {
            // Fixed–free chain of N = 10 unit masses and springs: mode j has shape uᵢ = sin(i θ), θ = (2j − 1)π/(2N + 1),
            // and ω_j = 2 sin(θ/2) (√(k/m) = 1); symplectic Euler keeps the shape and runs at ω̃: sin(ω̃h/2) = ω_j h/2.
            const int n = 10;
            MassSpringTestBody body = MassSpringTestBody.Chain(n, 1f, 1f, fixedFirst: true);
            double theta = (2 * j - 1) * Math.PI / (2 * n + 1);
            for (int i = 1; i <= n; i++)
                body.Positions[i].x += (float)(0.05 * Math.Sin(i * theta));
            double omega = 2.0 * Math.Sin(theta / 2.0);
            double omegaMax = 2.0 * Math.Sin((2 * n - 1) * Math.PI / (2 * (2 * n + 1)));
            float h = (float)(0.1 / omegaMax);
            MassSpringParameters p = MassSpringTestBody.Plain(MassSpringIntegrator.SymplecticEuler);
            double expected = 2.0 / h * Math.Asin(omega * h / 2.0);
            int steps = (int)(8 * 2.0 * Math.PI / expected / h);
            double first = -1.0, last = 0.0;
            int crossings = 0;
            double previous = Modal(body, theta);
            for (int s = 1; s <= steps; s++)
            {
                body.Step(p, h);
                double q = Modal(body, theta);
                if (previous < 0.0 && q >= 0.0)
                {
                    double t = (s - 1 + -previous / (q - previous)) * h;
                    if (first < 0.0)
                        first = t;
                    last = t;
                    crossings++;
                }
                previous = q;
            }
            double measured = 2.0 * Math.PI * (crossings - 1) / (last - first);
            // The plan's 0.5 % at ωh ≤ 0.1; an exact mode under the discrete map meets it with room (round-off only).
            Assert.That(Math.Abs(measured / expected - 1.0), Is.LessThanOrEqualTo(0.005), $"mode {j}: {measured} vs {expected}");
            Assert.That(Math.Abs(measured / expected - 1.0), Is.LessThanOrEqualTo(1e-4), "the discrete correction holds to round-off");
        }

        /// <summary>Projection of the displacement on the mode shape sin(i θ).</summary>
        static double Modal(MassSpringTestBody body, double theta)
        {
            double q = 0.0;
            for (int i = 1; i < body.Positions.Length; i++)
                q += (body.Positions[i].x - body.Data.RestPositions[i].x) * Math.Sin(i * theta);
            return q;
        }

        static double Energy(MassSpringTestBody body)
        {
            double x = body.Positions[1].x, v = body.Velocities[1].x;
            return 0.5 * (v * v + x * x);
        }

        static double ModifiedEnergy(MassSpringTestBody body, double h)
        {
            double x = body.Positions[1].x, v = body.Velocities[1].x;
            return 0.5 * (v * v + x * x - h * x * v);
        }
    }
}
