using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// XPBD's static answer against the exact one: a chain of springs hanging under gravity. With λ reset every substep and one
    /// Gauss–Seidel sweep, a substep moves each particle by Δx = −w C/(Σw + α̃) with α̃ = 1/(k h²) (Macklin et al. 2016, eq. 18
    /// with λ₀ = 0). For one spring the rest state of that map is exactly the static extension mg/k at any h; for a chain the
    /// sweep's coupling leaves an error that shrinks with the substep h — the property that makes XPBD's accuracy a function of
    /// its cost. The chain is short and near the origin (10 springs of 1 cm) so that the per-substep gravity displacement h²g
    /// stays many float32 ulps of the positions at every substep count tested (at 64 substeps of 1/60 s, h²g = 6.7e-7 m
    /// against ulp(0.1 m) = 7.5e-9 m); on a 10 m chain the same h²g is below one ulp and round-off, not the method, sets the sag.
    /// </summary>
    public class XpbdAccuracyTests
    {
        const float K = 100f, M = 1e-3f, G = 9.81f, Rest = 0.01f;

        /// <summary>Exact static tip displacement of a fixed–free chain: spring e carries the weight of the (n − e) particles below it.</summary>
        static double ExactTip(int springs)
        {
            double tip = 0;
            for (int e = 0; e < springs; e++)
                tip += (springs - e) * M * G / K;
            return tip;
        }

        /// <summary>
        /// The fixed–free chain from the origin. Dashpot c = 2√(k m) per spring (ζ = 1 for one spring): the chain's first mode
        /// decays in ~0.3 s.
        /// </summary>
        static MassSpringTestBody Chain(int springs) =>
            MassSpringTestBody.Chain(springs, K, M, fixedFirst: true, damping: 2f * (float)Math.Sqrt(K * M), restLength: Rest, start: 0f);

        /// <summary>Tip displacement, the mean over the last second of 10 s of 1/60 s steps at <paramref name="substeps"/>.</summary>
        static double XpbdTip(int springs, int substeps)
        {
            MassSpringTestBody body = Chain(springs);
            MassSpringParameters p = MassSpringTestBody.Plain(MassSpringIntegrator.Xpbd);
            p.Body.Substeps = substeps;
            p.Body.Acceleration = new float3(G, 0f, 0f);
            const int steps = 600, average = 60;
            double sum = 0;
            for (int s = 0; s < steps; s++)
            {
                Assert.IsFalse(body.Step(p, 1f / 60f).Reset);
                if (s >= steps - average)
                    sum += body.Positions[springs].x - body.Data.RestPositions[springs].x;
            }
            return sum / average;
        }

        [Test]
        public void SingleSpring_StaticExtensionIsExactAtAnySubstepCount()
        {
            // The rest state of one substep solves d (w + α̃) = (d + h²g) α̃, i.e. d = m g / k, whatever h. Left: float32
            // round-off of the 1 cm positions (~1e-9 m) against the 0.1 mm extension, 1e-5 relative, and the decay's leftover.
            foreach (int substeps in new[] { 1, 4, 32 })
                Assert.That(XpbdTip(1, substeps) / ExactTip(1) - 1.0, Is.EqualTo(0).Within(1e-3), $"{substeps} substeps");
        }

        [Test]
        public void Chain_StaticSagErrorFallsWithSubsteps()
        {
            // Ten springs, k h²/m from 28 (1 substep of 1/60 s) to 0.007 (64 substeps). The error must fall at every 4×
            // refinement of the substep, and by at least 2× each time (an order of at least 1/2 in h).
            const int springs = 10;
            double exact = ExactTip(springs);
            int[] substeps = { 1, 4, 16, 64 };
            var error = new double[substeps.Length];
            for (int i = 0; i < substeps.Length; i++)
                error[i] = Math.Abs(XpbdTip(springs, substeps[i]) / exact - 1.0);
            TestContext.WriteLine($"XPBD chain sag error at 1 / 4 / 16 / 64 substeps: {error[0]:E2} / {error[1]:E2} / {error[2]:E2} / {error[3]:E2}");
            for (int i = 1; i < substeps.Length; i++)
                Assert.That(error[i], Is.LessThan(error[i - 1] / 2), $"{substeps[i]} substeps");
        }
    }
}
