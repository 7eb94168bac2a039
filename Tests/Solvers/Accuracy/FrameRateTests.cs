using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// The same preset rests alike at 30, 60 and 120 Hz (the frame-rate suite's body: 6³ particles, 0.5 m, overlapping
    /// 4³ clusters, resting on a floor under gravity, default substep phase limit 0.5 rad).
    /// <para>Tolerances, derived in <see cref="RestingSag"/> and <see cref="AccuracyTolerances"/>: at rest a substep of h
    /// behaves like the continuous model with ω² replaced by α/h², so a small sag is sag(0)·(ωh)²/α, which grows with ωh
    /// from 1 to at most B = (0.5)²/α(0.5, ζ) − 1 (Jelly 0.089, Rubber 0.154, Clay 0.137). Two frame rates can therefore
    /// differ by at most B (plus sag/size of it for a sag that is not small, and each run's float32 dead band
    /// ulp·ζω/(g·h)), and an elastic preset's ratio must be the rule's, (ωh₁)²/α₁ ÷ (ωh₂)²/α₂, to within
    /// (sag/size)·|pred₁ − pred₂| and the dead bands. Plastic Clay flows and only has to meet the bound.</para>
    /// </summary>
    public class FrameRateTests
    {
        static readonly float[] s_Rates = { 30f, 60f, 120f };

        [TestCase("Jelly", 1)]
        [TestCase("Jelly", 4)]
        [TestCase("Rubber", 1)]
        [TestCase("Rubber", 4)]
        [TestCase("Clay (elastic)", 1)]
        [TestCase("Clay (elastic)", 4)]
        [TestCase("Clay", 1)]
        public void RestingSag_AgreesAcrossFrameRates(string preset, int requestedSubsteps)
        {
            FrameRateStudy study = FrameRateStudy.For(preset);
            string failure = CheckAcrossRates(study, (rate, n) => study.WithSubsteps(n), requestedSubsteps,
                study.Material.Frequency, study.Material.DampingRatio, !study.Material.Plasticity.Enabled);
            Assert.That(failure, Is.Null);
        }

        /// <summary>
        /// The check can fail: the old per-frame stiffness (α = 0.2 per step, damping 1/s, 4 substeps, converted to the oscillator it
        /// was at each frame rate by <see cref="LegacyStiffness"/>) sags by different amounts at 30, 60 and 120 Hz, beyond the bound of
        /// the material it was at 60 Hz.
        /// </summary>
        [Test]
        public void PerFrameStiffness_FailsTheSagCheck()
        {
            FrameRateStudy study = FrameRateStudy.For("Rubber");
            Assert.That(LegacyStiffness.ToFrequency(0.2f, 1f, 4, 1f / 60f, out float f60, out float zeta60), Is.True);
            string failure = CheckAcrossRates(study, (rate, n) =>
            {
                ShapeMatchingParameters p = study.WithSubsteps(n);
                LegacyStiffness.ToFrequency(0.2f, 1f, n, 1f / rate, out p.Frequency, out p.DampingRatio);
                p.MaxSubstepPhase = 1000f; // the old solver took exactly the requested substeps
                return p;
            }, 4, f60, zeta60, true);
            TestContext.WriteLine(failure);
            Assert.That(failure, Is.Not.Null);
        }

        /// <summary>Runs the preset at every rate; null when every pair meets the tolerances, else what failed.</summary>
        static string CheckAcrossRates(FrameRateStudy study, Func<float, int, ShapeMatchingParameters> parametersAt, int requested,
            double frequency, double zeta, bool elastic)
        {
            double omega = 2 * Math.PI * frequency;
            double extent = RestingSag.MaxExtent(study.Model);
            double bound = AccuracyTolerances.SagBound(zeta, ShapeMatchingParameters.Default.MaxSubstepPhase);
            var sag = new List<double>();
            var h = new List<double>();
            foreach (float rate in s_Rates)
            {
                RestingSagResult r = RestingSag.Run(study.Model, parametersAt(rate, requested), 1f / rate);
                if (r.Resets != 0)
                    return $"{rate} Hz: NaN-guard reset";
                sag.Add(r.Deflection);
                h.Add(1.0 / rate / r.Substeps);
                TestContext.WriteLine($"{study.Preset}, {rate} Hz, {r.Substeps} substeps (ωh = {omega * h[h.Count - 1]:F3}): sag {r.Deflection * 1e3:F4} mm, " +
                                      $"settled to {r.Unsettled / r.Deflection:E1}, plastic updates {r.PlasticUpdates}");
            }
            for (int a = 0; a < sag.Count; a++)
            for (int b = a + 1; b < sag.Count; b++)
            {
                double sagOverSize = Math.Max(sag[a], sag[b]) / FrameRateStudy.BodySize;
                double deadBands = AccuracyTolerances.RestingDeadBand(extent, zeta, omega, RestingSag.Gravity, h[a])
                                   + AccuracyTolerances.RestingDeadBand(extent, zeta, omega, RestingSag.Gravity, h[b]);
                double ratio = sag[a] / sag[b];
                double limit = bound * (1 + sagOverSize) + deadBands;
                if (!(Math.Abs(ratio - 1) <= limit))
                    return $"{s_Rates[a]} Hz / {s_Rates[b]} Hz: sag ratio {ratio:F5}, allowed 1 ± {limit:E2}";
                if (!elastic)
                    continue;
                double predA = RestingSag.PredictedSagRatio(omega, zeta, h[a]), predB = RestingSag.PredictedSagRatio(omega, zeta, h[b]);
                double deviation = ratio / (predA / predB) - 1;
                double allowed = sagOverSize * Math.Abs(predA - predB) + deadBands;
                TestContext.WriteLine($"{s_Rates[a]} Hz / {s_Rates[b]} Hz: ratio {ratio:F6}, rule {predA / predB:F6}, deviation {deviation:E2} (allowed {allowed:E2})");
                if (!(Math.Abs(deviation) <= allowed))
                    return $"{s_Rates[a]} Hz / {s_Rates[b]} Hz: sag ratio {ratio:F6} against the rule's {predA / predB:F6} (allowed ±{allowed:E2})";
            }
            return null;
        }
    }
}
