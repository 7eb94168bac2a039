using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The standing gravity wave: its analytic start, its frequency fit and the fluid's convergence to it.</summary>
    public class FluidStandingWaveTests
    {
        [Test]
        public void ModeVelocity_IsDivergenceFreeAndRaisesTheSurfaceAsLinearTheory()
        {
            // ∇·∇φ = 0. Central differences of step e = 1 mm leave a truncation of about (ek)²/6 = 4e-5 of k·|v| and the float32
            // velocities' round-off ε·|v|/e, about 1e-5 of it: both well inside 1e-3. At the surface v_y = η_t = A·ω·cos(kx);
            // at the walls u = 0 and on the floor v_y = 0.
            double k = StandingWaveScenario.Wavenumber, w = StandingWaveScenario.AngularFrequency;
            float e = 1e-3f, d = StandingWaveScenario.Depth, l = StandingWaveScenario.Length;
            double scale = StandingWaveScenario.Amplitude * w;
            foreach (float x in new[] { 0.03f, 0.1f, 0.17f })
                foreach (float y in new[] { 0.02f, 0.05f, 0.09f })
                {
                    float3 p = new float3(x, y, 0f);
                    double div = (StandingWaveScenario.ModeVelocity(p + new float3(e, 0, 0)).x - StandingWaveScenario.ModeVelocity(p - new float3(e, 0, 0)).x
                        + StandingWaveScenario.ModeVelocity(p + new float3(0, e, 0)).y - StandingWaveScenario.ModeVelocity(p - new float3(0, e, 0)).y) / (2 * e);
                    Assert.That(Math.Abs(div), Is.LessThan(1e-3 * k * scale), $"divergence at ({x}, {y})");
                    Assert.That(StandingWaveScenario.ModeVelocity(new float3(x, d, 0f)).y, Is.EqualTo(scale * Math.Cos(k * x)).Within(1e-6 * scale));
                }
            Assert.That(StandingWaveScenario.ModeVelocity(new float3(0f, 0.05f, 0f)).x, Is.EqualTo(0f).Within(1e-7 * scale));
            Assert.That(StandingWaveScenario.ModeVelocity(new float3(l, 0.05f, 0f)).x, Is.EqualTo(0f).Within(1e-6 * scale));
            Assert.That(StandingWaveScenario.ModeVelocity(new float3(0.05f, 0f, 0f)).y, Is.EqualTo(0f));
        }

        [Test]
        public void FitFrequency_RecoversADampedSineUnderNoise()
        {
            // 3 periods sampled at 60 Hz, γ/ω = 0.1, an offset and ±10 % uniform noise: the least-squares ω of N = 96 samples
            // has a standard error of about σ_noise/(A·ω·T·√(N/12)) relative, ~2e-3 here; 1 % is five of those.
            double omega = 11.7, damping = 1.17, amplitude = 1.2e-3;
            int n = 97;
            var t = new double[n];
            var y = new double[n];
            var random = new System.Random(7);
            for (int i = 0; i < n; i++)
            {
                t[i] = i / 60.0;
                y[i] = 0.1 + Math.Exp(-damping * t[i]) * amplitude * Math.Sin(omega * t[i] + 0.3) + 0.1 * amplitude * (2 * random.NextDouble() - 1);
            }
            var fit = DampedSineFit.Fit(t, y, omega * 1.2);
            Assert.That(fit.omega / omega - 1, Is.EqualTo(0).Within(0.01));
            Assert.That(fit.damping / damping - 1, Is.EqualTo(0).Within(0.2));
            Assert.That(fit.amplitude / amplitude - 1, Is.EqualTo(0).Within(0.05));
        }

        [Test]
        public void StandingWave_FrequencyErrorFallsWithResolution()
        {
            // The weakly compressible solver at its defaults: the frequency error falls from d/5 to d/10. At d/10 a boundary
            // misplaced by half a spacing at each wall and at the floor moves ω by about 4 % (∂lnω/∂lnL = −0.64 with
            // δL/L = 5 %, ∂lnω/∂lnd = 0.14 with δd/d = 5 %), so 10 % bounds it with room for the rest of the discretization.
            FluidParameters p = FluidParameters.Default;
            Assert.That(p.Solver, Is.EqualTo(FluidSolverKind.WeaklyCompressible));
            var coarse = new StandingWaveScenario(5, p, "test");
            var fine = new StandingWaveScenario(10, p, "test");
            coarse.Setup();
            fine.Setup();
            TestContext.WriteLine($"frequency error d/5 {coarse.FrequencyError:P2}, d/10 {fine.FrequencyError:P2}");
            Assert.That(fine.FrequencyError, Is.LessThan(coarse.FrequencyError));
            Assert.That(fine.FrequencyError, Is.LessThan(0.1));
        }
    }
}
