using System;
using System.Collections.Generic;
using System.Globalization;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Reference values of the CSM3 scene (of the continuum: the same for every mesh of the methods), computed once per
    /// material from the float64 3-D beam (<see cref="Csm3SolidReference"/>) over the scene's duration, sampled at its
    /// frames: three meshes along the length at h = 1/60 s with their Richardson estimate (the mesh limit at that step),
    /// plus the time-step correction measured on the coarsest mesh, Δ_t = (f(h/2) − f(h))·4/3 (Richardson with
    /// Newmark's order 2), added to each value.
    /// <para>Why a step correction: the cycle extremes carry the second bending mode (1.4 % of the tip's static
    /// deflection in the Euler–Bernoulli modal expansion, at 6.27× the first frequency: ωh = 0.68 at 1/60 s), whose
    /// phase error shifts both extremes alike: the mean moves by ~1.6 % from h = 1/60 to 1/120 s, the amplitude by
    /// 0.1 %, the frequency by 0.2 %. Measured on 8 × 1 × 1 elements (sampled at the frames) at h = 1/60, 1/120, 1/240,
    /// 1/480 s: mean −70.471, −71.597, −71.813, −71.886 mm; amplitude 72.045, 71.980, 71.892, 71.952 mm; frequency
    /// 1.03475, 1.03683, 1.03743, 1.03747 Hz. The correction from the first two gives −72.00 mm, 71.96 mm, 1.03752 Hz:
    /// within 0.15 % of the finest. Mesh and step errors add nearly independently: the step moves the 16-element beam's
    /// mean by 1.00 mm where it moves the 8-element one's by 1.13 mm (0.2 % of the mean).</para>
    /// </summary>
    public sealed class Csm3Targets
    {
        /// <summary>Tip u_y mean (m), amplitude (m) and frequency (Hz): the mesh Richardson estimates plus the step correction.</summary>
        public double UyMean, UyAmplitude, UyFrequency;
        /// <summary>The reference per mesh of <see cref="ElementsAlong"/>, time step = the frame (1/60 s).</summary>
        public Csm3Result[] Runs;
        /// <summary>Richardson estimates (element length along x) of the u_y mean, amplitude and frequency at h = 1/60 s.</summary>
        public ConvergenceEstimate Mean, Amplitude, Frequency;
        /// <summary>The coarsest mesh at half the time step (sampled at the same frames).</summary>
        public Csm3Result HalfStep;
        /// <summary>Step corrections Δ_t of the mean (m), amplitude (m) and frequency (Hz).</summary>
        public double StepMean, StepAmplitude, StepFrequency;
        /// <summary>Wall-clock time of the reference (s; runs two at a time), for the report only.</summary>
        public double Seconds;

        /// <summary>
        /// Q2 elements along the length, one across the height and one across the width. One Q2 element across the section
        /// holds the bending field of a beam (u_x linear, u_y quadratic across it, the anticlastic term included): measured at
        /// h = 1/60 s, 18 × 2 × 1 and 18 × 1 × 2 elements move the mean, amplitude and frequency of 18 × 1 × 1 by ≤ 0.1 %,
        /// and 35 × 2 × 2 those of 36 × 1 × 1 by ≤ 0.1 %; refining along the length moves them by ~2 % from 9 to 18 elements
        /// (observed order ~1.4: the clamped face's edges are singular).
        /// </summary>
        public static readonly int[] ElementsAlong = { 8, 16, 32 };

        static readonly Dictionary<(float, float, float), Csm3Targets> s_Cache = new Dictionary<(float, float, float), Csm3Targets>();

        /// <summary>Takes <paramref name="targets"/> as the values of <paramref name="material"/>: values an earlier run computed from the same reference sources.</summary>
        public static void Remember(in ElasticMaterial material, Csm3Targets targets)
        {
            lock (s_Cache)
                s_Cache[(material.YoungsModulus, material.PoissonRatio, material.Density)] = targets;
        }

        /// <summary>The targets of a material (computed once: ~30 s on two cores).</summary>
        public static Csm3Targets Get(ElasticMaterial material)
        {
            lock (s_Cache)
            {
                var key = (material.YoungsModulus, material.PoissonRatio, material.Density);
                if (s_Cache.TryGetValue(key, out Csm3Targets t))
                    return t;
                s_Cache[key] = t = Compute(material.YoungsModulus, material.PoissonRatio, material.Density);
                return t;
            }
        }

        static Csm3Targets Compute(double e, double nu, double rho)
        {
            var clock = System.Diagnostics.Stopwatch.StartNew();
            int meshes = ElementsAlong.Length;
            var t = new Csm3Targets { Runs = new Csm3Result[meshes] };
            double dt = StudyScene.Dt;
            // Independent runs, two at a time (the finest alone on one core while the others share the second).
            var runs = new Csm3Result[meshes + 1];
            System.Threading.Tasks.Parallel.For(0, meshes + 1, new System.Threading.Tasks.ParallelOptions { MaxDegreeOfParallelism = 2 }, k =>
            {
                int i = meshes - k; // finest first; index meshes = the half step on the coarsest mesh
                runs[i] = i < meshes
                    ? Csm3SolidReference.Run(ElementsAlong[i], 1, 1, dt, Csm3Scene.Duration, 1, e, nu, rho)
                    : Csm3SolidReference.Run(ElementsAlong[0], 1, 1, 0.5 * dt, Csm3Scene.Duration, 2, e, nu, rho);
            });
            Array.Copy(runs, t.Runs, meshes);
            t.HalfStep = runs[meshes];
            var size = new double[meshes];
            var mean = new double[meshes];
            var amplitude = new double[meshes];
            var frequency = new double[meshes];
            for (int i = 0; i < meshes; i++)
            {
                size[i] = Csm3Reference.Length / ElementsAlong[i];
                mean[i] = t.Runs[i].UyMean;
                amplitude[i] = t.Runs[i].UyAmplitude;
                frequency[i] = t.Runs[i].UyFrequency;
            }
            t.Mean = RichardsonExtrapolation.Estimate(size, mean);
            t.Amplitude = RichardsonExtrapolation.Estimate(size, amplitude);
            t.Frequency = RichardsonExtrapolation.Estimate(size, frequency);
            Csm3Result c = t.Runs[0], h = t.HalfStep;
            t.StepMean = (h.UyMean - c.UyMean) * 4 / 3;
            t.StepAmplitude = (h.UyAmplitude - c.UyAmplitude) * 4 / 3;
            t.StepFrequency = (h.UyFrequency - c.UyFrequency) * 4 / 3;
            t.UyMean = t.Mean.Extrapolated + t.StepMean;
            t.UyAmplitude = t.Amplitude.Extrapolated + t.StepAmplitude;
            t.UyFrequency = t.Frequency.Extrapolated + t.StepFrequency;
            t.Seconds = clock.Elapsed.TotalSeconds;
            return t;
        }

        /// <summary>The reference and its convergence, for the scene's description.</summary>
        public string Summary
        {
            get
            {
                var s = new System.Text.StringBuilder();
                s.Append("Reference: the same 3-D beam in float64 (27-node hexahedra, St Venant–Kirchhoff, Newmark average acceleration at h = 1/60 s, ");
                s.Append("the mid node of the tip face sampled at the frames), one element across the section and ");
                for (int i = 0; i < Runs.Length; i++)
                    s.Append(F(i == 0 ? "{0}" : i == Runs.Length - 1 ? " and {0}" : ", {0}", Runs[i].ElementsX));
                s.Append(" along: u_y mean ");
                Values(s, r => r.UyMean * 1e3, "0.000");
                s.Append(" mm, amplitude ");
                Values(s, r => r.UyAmplitude * 1e3, "0.000");
                s.Append(" mm, frequency ");
                Values(s, r => r.UyFrequency, "0.00000");
                s.Append(F(" Hz; Richardson (observed orders {0:0.0}, {1:0.0}, {2:0.0}): {3:0.000} ± {4:0.000} mm at {5:0.0000} Hz (estimated error of the finest mesh ",
                    Mean.Order, Amplitude.Order, Frequency.Order, Mean.Extrapolated * 1e3, Amplitude.Extrapolated * 1e3, Frequency.Extrapolated));
                s.Append(F("{0:0.00} %, {1:0.00} %, {2:0.00} %). ", 100 * Mean.ErrorEstimate / Math.Abs(Mean.Extrapolated),
                    100 * Amplitude.ErrorEstimate / Amplitude.Extrapolated, 100 * Frequency.ErrorEstimate / Frequency.Extrapolated));
                Csm3Result c = Runs[0];
                s.Append(F("Halving the time step on the {0}-element beam moves the mean by {1:0.00} %, the amplitude by {2:0.00} % and the frequency by {3:0.00} % " +
                           "(the second bending mode's phase at the extremes); Richardson with Newmark's order 2 adds {4:0.000} mm, {5:0.000} mm and {6:0.0000} Hz. ",
                    c.ElementsX, Change(HalfStep.UyMean, c.UyMean), Change(HalfStep.UyAmplitude, c.UyAmplitude), Change(HalfStep.UyFrequency, c.UyFrequency),
                    StepMean * 1e3, StepAmplitude * 1e3, StepFrequency));
                s.Append(F("Targets: u_y = {0:0.000} ± {1:0.000} mm at {2:0.0000} Hz. ", UyMean * 1e3, UyAmplitude * 1e3, UyFrequency));
                s.Append(F("Against the published 2-D plane-strain CSM3 ({0:0.000} ± {1:0.000} mm at {2:0.0000} Hz) the 3-D beam sags and swings {3:0.0} % and {4:0.0} % further ",
                    Csm3Reference.PublishedUyMean * 1e3, Csm3Reference.PublishedUyAmplitude * 1e3, Csm3Reference.PublishedUyFrequency,
                    100 * (UyMean / Csm3Reference.PublishedUyMean - 1), 100 * (UyAmplitude / Csm3Reference.PublishedUyAmplitude - 1)));
                s.Append(F("and rings {0:0.0} % slower: plane strain stiffens bending by 1/(1 − ν²) = {1:0.000} (so at most {2:0.0} % further and {3:0.0} % slower; the large deflection ",
                    100 * (1 - UyFrequency / Csm3Reference.PublishedUyFrequency), 1 / (1 - Nu * Nu), 100 * (1 / (1 - Nu * Nu) - 1),
                    100 * (1 - Math.Sqrt(1 - Nu * Nu))));
                s.Append("stiffens both beams and takes back part of it). The scene's errors are against the 3-D reference.");
                return s.ToString();
            }
        }

        const double Nu = Csm3Reference.PoissonRatio;

        void Values(System.Text.StringBuilder s, Func<Csm3Result, double> value, string format)
        {
            for (int i = 0; i < Runs.Length; i++)
                s.Append((i > 0 ? ", " : "") + value(Runs[i]).ToString(format, CultureInfo.InvariantCulture));
        }

        static double Change(double value, double reference) => 100 * Math.Abs(value / reference - 1);

        static string F(string format, params object[] args) => string.Format(CultureInfo.InvariantCulture, format, args);
    }
}
