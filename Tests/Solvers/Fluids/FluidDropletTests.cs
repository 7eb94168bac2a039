using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The droplet's two surface tensions (FluidAccuracyDroplet): the virial pressure, the frequency fit, and the drop itself.</summary>
    public class FluidDropletTests
    {
        static FluidParameters Akinci(float tension)
        {
            FluidParameters p = FluidParameters.Default;
            p.SpeedOfSound = 5f;
            p.ViscosityIterations = 1;
            p.Cohesion = FluidCohesionModel.Akinci;
            p.SurfaceTension = tension;
            return p;
        }

        [Test]
        public void Virial_OfACompressedLatticeBall_IsTheTaitPressureAndTheCohesionLatticeSum()
        {
            // A lattice ball at rest squeezed to 0.995Δx: every particle deeper than 1.5h has a full, uniform neighbourhood
            // (the region R_g − 2.5h keeps its neighbours' neighbourhoods full too, so their normals vanish).
            // Pressure: xᵢⱼ·Fᵢⱼ = −m²·C·κ∇·2p̃·(h − r)²·r with p̃ = κp/ρ², and κ = 3/t, t = κ∇·m·(−C)·Σ(h − r)²·r/ρ the gradient
            // trace, so ½Σⱼ xᵢⱼ·Fᵢⱼ = 3p·m/ρ and P = Σ/(3Σ m/ρ) = p exactly. Cohesion: Fᵢⱼ = −γ·m·(ρ₀/ρ)·m·C(r)·r̂, so
            // P = −γ·m·ρ₀·Σⱼ C(rⱼ)·rⱼ/6 over the lattice offsets. Both hold to the float sums' round-off (seen: 2·10⁻⁷ and
            // 1·10⁻⁷): 10⁻⁵. A missing ½, 3 or cohesion term is off by a factor.
            const float spacing = 0.005f, squeeze = 0.995f;
            var c = new FluidConstants(DropletOscillationScenario.Scene(Akinci(0.2f), spacing));
            FluidBuffers b = DropletOscillationScenario.Ball(c, spacing);
            for (int i = 0; i < b.Status.Count; i++)
                b.Positions[i] *= squeeze;
            DropletStress s = DropletOscillationScenario.Measure(c, b, 2.5f);
            Assert.That(s.Interior, Is.GreaterThan(400));
            Assert.That(s.EosPressure, Is.GreaterThan(100.0));
            Assert.That(s.PressureVirial, Is.EqualTo(s.EosPressure).Within(1e-5 * s.EosPressure));

            SphKernels k = c.Kernels;
            double sum = 0;
            int n = (int)math.ceil(k.H / (squeeze * spacing));
            for (int z = -n; z <= n; z++)
            for (int y = -n; y <= n; y++)
            for (int x = -n; x <= n; x++)
            {
                float r = math.length(new float3(x, y, z)) * squeeze * spacing;
                sum += k.Cohesion(r) * r;
            }
            double expected = -0.2 * c.Mass * c.Parameters.RestDensity * sum / 6;
            Assert.That(expected, Is.LessThan(-10.0));
            Assert.That(s.CohesionVirial, Is.EqualTo(expected).Within(1e-5 * Math.Abs(expected)));
            Assert.That(s.KineticPressure, Is.EqualTo(0.0));
        }

        [Test]
        public void FitFrequency_RecoversADampedSine()
        {
            // y = 0.3 + 2e^(−0.5t)·sin(7t + 0.4) sampled at 60 Hz over three periods, guessed 15 % low: the model is exact,
            // so the fit's ω and γ are limited only by the golden-section tolerance (step/2⁴ · 0.618⁶⁰).
            const int count = 163;
            var t = new double[count];
            var y = new double[count];
            for (int i = 0; i < count; i++)
            {
                t[i] = i / 60.0;
                y[i] = 0.3 + 2 * Math.Exp(-0.5 * t[i]) * Math.Sin(7 * t[i] + 0.4);
            }
            var fit = DampedSineFit.Fit(t, y, 6.0);
            Assert.That(fit.omega, Is.EqualTo(7.0).Within(1e-4));
            Assert.That(fit.damping, Is.EqualTo(0.5).Within(1e-4));
            Assert.That(fit.amplitude, Is.EqualTo(2.0).Within(1e-3));
            Assert.That(fit.residual, Is.LessThan(1e-4));
        }

        [Test]
        public void Droplet_AkinciTension_TheCohesiveVirialBringsThePressureToTheFrequency()
        {
            // γ = 0.2, Δx = 1 cm, R = 5 cm (the drop), settled 3 s. The EOS pressure alone leaves out the cohesion's
            // own tension, a term of the same order as the pressure (the Akinci pair force attracts interior pairs too), so
            // σ from it is far above the frequency's; the mechanical (virial) pressure is the one Laplace's law holds for,
            // so σ from it is closer to the frequency's by a wide margin (seen: 3.30, 1.29 and 1.54 N/m). How close is not
            // pinned: the ratio moves by 0.15–0.36 with changes the drop cannot feel (fluids.md). The bulk's volume within
            // 1 %: c₀ = 5 m/s compresses it by p/(ρ₀c₀²) = 0.5 % at the Tait p ≈ 135 Pa.
            var drop = new DropletOscillationScenario(0.01f, Akinci(0.2f), "γ = 0.2");
            drop.Setup();
            DropletStress s = drop.Stress;
            double sigmaF = drop.FrequencyTension;
            Assert.That(sigmaF / s.EosTension, Is.LessThan(0.5));
            Assert.That(Math.Abs(Math.Log(sigmaF / s.PressureTension)), Is.LessThan(0.5 * Math.Abs(Math.Log(sigmaF / s.EosTension))));
            Assert.That(Math.Abs(s.VolumeChange(FluidParameters.Default.RestDensity)), Is.LessThan(0.01));
        }
    }
}
