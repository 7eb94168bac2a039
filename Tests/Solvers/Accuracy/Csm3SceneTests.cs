using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The CSM3 scene of the method study: its 3-D float64 reference and one method measured by it.</summary>
    public class Csm3SceneTests
    {
        /// <summary>Coarse reference of the tests: 5 × 1 × 1 Q2 elements (f ~4 % above the converged 3-D value), one full cycle (1.9 s).</summary>
        const int CoarseElements = 5;
        const double CycleDuration = 1.9;

        static readonly Lazy<Csm3Result> s_Coarse = new Lazy<Csm3Result>(() =>
            Csm3SolidReference.Run(CoarseElements, 1, 1, StudyScene.Dt, CycleDuration));
        static readonly Lazy<Csm3Result> s_CoarseHalfStep = new Lazy<Csm3Result>(() =>
            Csm3SolidReference.Run(CoarseElements, 1, 1, 0.5 * StudyScene.Dt, CycleDuration, 2));

        /// <summary>
        /// The published CSM3 numbers are plane strain: bending stiffness E/(1 − ν²) per unit width. The 3-D beam with free
        /// sides bends with E (the clamp stiffens only its root), so its effective modulus lies in [E, E/(1 − ν²)]. The tip
        /// response is u = φ(q/E_eff) with φ increasing and concave (the large deflection stiffens), φ(0) = 0, hence
        /// φ(a x) ≤ a φ(x) for a ≥ 1: the 3-D mean and amplitude are 1 to 1/(1 − ν²) = 1.190 times the published ones,
        /// and the frequency (∝ √E_eff, raised by the stiffening of the larger swing) √(1 − ν²) = 0.9165 to 1 times. The
        /// coarse mesh is ~4 % too stiff, which moves it toward the plane-strain end, inside the band (measured ratios
        /// 1.082, 1.066, 0.963; the converged scene targets are 1.17, 1.14, 0.926).
        /// </summary>
        [Test]
        public void Csm3Solid_LiesBetweenPlaneStrainAndFreeSidedBeam()
        {
            Csm3Result r = s_Coarse.Value;
            double nu = Csm3Reference.PoissonRatio, band = 1 / (1 - nu * nu);
            double mean = r.UyMean / Csm3Reference.PublishedUyMean;
            double amplitude = r.UyAmplitude / Csm3Reference.PublishedUyAmplitude;
            double frequency = r.UyFrequency / Csm3Reference.PublishedUyFrequency;
            TestContext.WriteLine($"3-D/2-D: mean {mean}, amplitude {amplitude}, frequency {frequency}; {r.Seconds} s");
            Assert.IsTrue(r.Converged);
            Assert.That(mean, Is.InRange(1.0, band));
            Assert.That(amplitude, Is.InRange(1.0, band));
            Assert.That(frequency, Is.InRange(Math.Sqrt(1 - nu * nu), 1.0));
        }

        /// <summary>
        /// Halving the step from 1/60 s: a suddenly applied uniform load excites bending mode n with amplitude cₙ of the
        /// static tip deflection (Euler–Bernoulli modal expansion: c₁ = 1.013, c₂ = −0.0143, c₃ = 0.0011, c₄ = −0.0002).
        /// Newmark resolves the first mode (ωh = 0.11; period error (ωh)²/12 = 0.1 %) but not the phase of the higher ones
        /// (ω₂h = 0.68), which can move each extreme by at most 2 Σₙ≥₂ |cₙ| = 3.1 % of the sag: the mean and the amplitude
        /// change by less than that. A crossing of the mid-level moves by at most that displacement over the swing's
        /// speed ω·amplitude, so one cycle's frequency changes by at most 2·0.031/(2π) = 1.0 % (plus the 0.08 % of the first
        /// mode). Measured: 0.95 %, 0.08 %, 0.28 %.
        /// </summary>
        [Test]
        public void Csm3Solid_HalvingTheFrameStepMovesOnlyTheHigherModesShare()
        {
            Csm3Result h = s_Coarse.Value, half = s_CoarseHalfStep.Value;
            double mean = Math.Abs(half.UyMean / h.UyMean - 1);
            double amplitude = Math.Abs(half.UyAmplitude / h.UyAmplitude - 1);
            double frequency = Math.Abs(half.UyFrequency / h.UyFrequency - 1);
            TestContext.WriteLine($"changes: mean {mean}, amplitude {amplitude}, frequency {frequency}; {h.Seconds} + {half.Seconds} s");
            Assert.IsTrue(half.Converged);
            Assert.That(mean, Is.LessThan(HigherModes));
            Assert.That(amplitude, Is.LessThan(HigherModes));
            Assert.That(frequency, Is.LessThan(2 * HigherModes / (2 * Math.PI) + 0.0008));
        }

        /// <summary>2 Σₙ≥₂ |cₙ|: the largest shift of an extreme (fraction of the sag) from the higher modes' phase.</summary>
        const double HigherModes = 0.031;

        /// <summary>
        /// Mass-spring, implicit Euler at 4 substeps, default beam (35 × 2 × 2 cells), measured by the scene against the
        /// coarse reference of these tests (<see cref="CoarseElements"/> × 1 × 1 Q2 elements, one cycle: u_y = −68.81 ±
        /// 69.48 mm at 1.0593 Hz, ~4 % stiffer than the scene's converged targets, −74.40 ± 74.53 mm at 1.0182 Hz, which
        /// take ~30 s to compute). Every assertion compares the network with a reference through relations that hold for
        /// any self-consistent beam, so the coarse one serves.
        /// <list type="bullet">
        /// <item>Implicit Euler damps a mode of ω by the factor (1 + (ωh)²)^(−1/2) per substep h, a rate ω²h/2; the two
        /// cycles measured span ¾T to 2¾T, so their extremes are on average 1.75/f in, and the amplitude over the mean is
        /// at most e^(−3.5π² f h) (0.84 at the measured 1.21 Hz) of the undamped one (the reference's: 1.010). Measured 0.68
        /// against the bound 0.85.</item>
        /// <item>The mean follows the network's stiffness: static sag ∝ 1/k and f² ∝ k (same masses), so
        /// mean/mean_ref ≈ (f_ref/f)², to within the large-deflection stiffening (the converged reference's mean is 7.5 % below
        /// the linear sag qL⁴/(8EI) = 80.4 mm; the coarse one's 14 %, its mesh being ~4 to 7 % stiff): asserted within 0.1
        /// (measured 0.730 against 0.768).</item>
        /// <item><c>err</c> is below 0.75: the network is ~14 % stiff in frequency, so its sag is ~0.77 of the reference's and
        /// its amplitude a further ≤ 0.84 of that (≥ 35 % error predicted; 51 % measured: part of the swing also beats into
        /// sideways bending, the tip reaching 41 mm along z, which the mirror-asymmetric tetrahedra couple to the y swing).</item>
        /// </list>
        /// </summary>
        [Test]
        public void MassSpringImplicitEuler_SwingsStiffAndDecaying()
        {
            var scene = new Csm3Scene();
            MethodBodySetup setup = scene.Setup;
            Csm3Result reference = s_Coarse.Value;
            var targets = new Csm3Targets { UyMean = reference.UyMean, UyAmplitude = reference.UyAmplitude, UyFrequency = reference.UyFrequency };
            IReadOnlyList<Metric> metrics = scene.Measure(setup, s => new MassSpringMethodBody(s, MassSpringIntegrator.ImplicitEuler, Substeps), targets);
            TestContext.WriteLine($"reference u_y = {targets.UyMean} ± {targets.UyAmplitude} m at {targets.UyFrequency} Hz");
            var m = new Dictionary<string, double>();
            foreach (Metric metric in metrics)
            {
                m[metric.Name] = metric.Value;
                TestContext.WriteLine($"{metric.Name} = {metric.Value}");
            }
            Assert.AreEqual(0, m[StudyScene.Resets]);
            foreach (string name in new[] { StudyScene.Error, Csm3Scene.MeanValue, Csm3Scene.AmplitudeValue, Csm3Scene.FrequencyValue })
                Assert.IsTrue(double.IsFinite(m[name]), name);
            double f = m[Csm3Scene.FrequencyValue], h = StudyScene.Dt / Substeps;
            double decay = Math.Exp(-3.5 * Math.PI * Math.PI * f * h);
            Assert.That(m[Csm3Scene.AmplitudeValue] / -m[Csm3Scene.MeanValue], Is.LessThan(decay * (-targets.UyAmplitude / targets.UyMean)));
            double stiffness = targets.UyFrequency / f;
            Assert.That(m[Csm3Scene.MeanValue] / targets.UyMean, Is.EqualTo(stiffness * stiffness).Within(0.1));
            Assert.That(m[StudyScene.Error], Is.LessThan(0.75));
        }

        const int Substeps = 4;
    }
}
