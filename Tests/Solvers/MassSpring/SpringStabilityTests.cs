using System;
using NUnit.Framework;
using Unity.Mathematics;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Stability bounds of the explicit integrators (stability plan §2.2, row 10) and the guard past them.</summary>
    public class SpringStabilityTests
    {
        /// <summary>Largest k h²/m: 4/(ω_max² m/k). Wall spring: 4; two free masses: 2; fixed–free chain of N: 1/sin²((2N − 1)π/(2(2N + 1))).</summary>
        static double Bound(string topology) => topology switch
        {
            "wall" => 4.0,
            "free2" => 2.0,
            _ => 1.0 / Math.Pow(Math.Sin(19.0 * Math.PI / 42.0), 2.0),
        };

        static MassSpringTestBody Make(string topology) => topology switch
        {
            "wall" => MassSpringTestBody.Chain(1, 1f, 1f, fixedFirst: true),
            "free2" => MassSpringTestBody.Chain(1, 1f, 1f, fixedFirst: false),
            _ => MassSpringTestBody.Chain(10, 1f, 1f, fixedFirst: true),
        };

        static double Perturb(MassSpringTestBody body, int seed)
        {
            var random = new System.Random(seed);
            double max = 0.0;
            for (int i = 0; i < body.Positions.Length; i++)
            {
                if (body.Data.InverseMasses[i] == 0f)
                    continue;
                float d = 1e-3f * (float)(random.NextDouble() - 0.5);
                body.Positions[i].x += d;
                max = Math.Max(max, Math.Abs(d));
            }
            return max;
        }

        /// <summary>Largest deformation: displacement from rest less the mass centre's (a free body's drift is no instability).</summary>
        static double Amplitude(MassSpringTestBody body)
        {
            float3 shift = float3.zero;
            float mass = 0f;
            bool free = true;
            for (int i = 0; i < body.Positions.Length; i++)
            {
                free &= body.Data.InverseMasses[i] != 0f;
                shift += body.Data.Masses[i] * (body.Positions[i] - body.Data.RestPositions[i]);
                mass += body.Data.Masses[i];
            }
            shift = free ? shift / mass : float3.zero;
            double max = 0.0;
            for (int i = 0; i < body.Positions.Length; i++)
                max = Math.Max(max, math.length(body.Positions[i] - body.Data.RestPositions[i] - shift));
            return max;
        }

        [TestCase("wall")]
        [TestCase("free2")]
        [TestCase("chain10")]
        public void Spring_StabilityBoundary(string topology)
        {
            double bound = Bound(topology);
            // MaxStableStep against the closed form: k h_max²/m = bound (k = m = 1), to 1e-3.
            double hMax = MassSpringStability.MaxStableStep(Make(topology).Data.AsModel());
            Assert.That(Math.Abs(hMax * hMax / bound - 1.0), Is.LessThanOrEqualTo(1e-3), $"h_max² {hMax * hMax} vs {bound}");

            foreach (MassSpringIntegrator integrator in new[] { MassSpringIntegrator.SymplecticEuler, MassSpringIntegrator.Verlet })
            {
                MassSpringParameters p = MassSpringTestBody.Plain(integrator);
                // 0.95×: bounded. Near the limit the energy band reaches 1/(1 − ωh/2) ≈ 40, ≈ 6× in amplitude: ≤ 10× the
                // perturbation, and no growth between the first and last 1000 of 10⁴ steps.
                MassSpringTestBody below = Make(topology);
                double p0 = Perturb(below, 3);
                float h = (float)Math.Sqrt(0.95 * bound);
                double early = 0.0, late = 0.0;
                for (int n = 0; n < 10000; n++)
                {
                    Assert.IsFalse(below.Step(p, h).Reset);
                    double a = Amplitude(below);
                    if (n < 1000) early = Math.Max(early, a);
                    if (n >= 9000) late = Math.Max(late, a);
                }
                Assert.That(Math.Max(early, late), Is.LessThanOrEqualTo(10.0 * p0), $"{integrator} 0.95×");
                // Modes beat and each breathes inside its energy band, so two windows' maxima differ by a bounded factor
                // (1.5 allowed); an instability would multiply it by 10³ within a few hundred steps.
                Assert.That(late, Is.LessThanOrEqualTo(1.5 * early), $"{integrator} 0.95× grows");

                // 1.05×: grows past 10³× the perturbation within 500 steps.
                MassSpringTestBody above = Make(topology);
                double q0 = Perturb(above, 3);
                h = (float)Math.Sqrt(1.05 * bound);
                double grown = 0.0;
                for (int n = 0; n < 500 && grown <= 1e3 * q0; n++)
                {
                    above.Step(p, h);
                    grown = Amplitude(above);
                }
                Assert.That(grown, Is.GreaterThan(1e3 * q0), $"{integrator} 1.05×");
                // And the inspector check flags that step.
                Assert.IsTrue(MassSpringStability.CheckStep(integrator, h, hMax).HasValue);
                Assert.IsFalse(MassSpringStability.CheckStep(integrator, Math.Sqrt(0.95 * bound), hMax).HasValue);
            }
        }

        [Test]
        public void Spring_AboveBoundIsResetByTheGuard()
        {
            // Symplectic Euler at 1.05× of the wall spring's bound with the default guard speed (500 m/s): the guard
            // catches the blow-up, resets the body to rest and says so; it never returns a non-finite state.
            MassSpringTestBody body = MassSpringTestBody.Chain(1, 1f, 1f, fixedFirst: true);
            body.Positions[1].x += 0.01f;
            MassSpringParameters p = MassSpringTestBody.Plain(MassSpringIntegrator.SymplecticEuler, maxSpeed: 500f);
            float h = (float)Math.Sqrt(1.05 * 4.0);
            bool reset = false;
            for (int n = 0; n < 200 && !reset; n++)
            {
                ParticleStepReport r = body.Step(p, h);
                reset = r.Reset;
                for (int i = 0; i < 2; i++)
                    Assert.IsTrue(math.all(math.isfinite(body.Positions[i])) && math.all(math.isfinite(body.Velocities[i])));
            }
            Assert.IsTrue(reset, "the guard reset the body");
            Assert.AreEqual(1, body.Status.ResetCount);
            Assert.That(Math.Abs(body.Velocities[1].x), Is.EqualTo(0f));
        }

        [Test]
        public void ImplicitAndXpbd_StableFarAboveTheExplicitBound()
        {
            // k h²/m = 1e4 (ωh = 100) on a fixed–free chain of 10: both unconditionally stable schemes stay bounded.
            foreach (MassSpringIntegrator integrator in new[] { MassSpringIntegrator.ImplicitEuler, MassSpringIntegrator.Xpbd })
            {
                MassSpringTestBody body = Make("chain10");
                double p0 = Perturb(body, 5);
                MassSpringParameters p = MassSpringTestBody.Plain(integrator);
                for (int n = 0; n < 300; n++)
                    Assert.IsFalse(body.Step(p, 100f).Reset, integrator.ToString());
                Assert.That(Amplitude(body), Is.LessThanOrEqualTo(2.0 * p0), integrator.ToString());
            }
        }
    }
}
