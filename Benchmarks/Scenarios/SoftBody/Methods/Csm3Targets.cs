using System;
using System.Collections.Generic;
using System.Globalization;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Reference values of the CSM3 scene (of the continuum: the same for every mesh of the methods), computed once per
    /// material: the float64 3-D beam (<see cref="Csm3SolidReference"/>) at the scene's frame rate and duration, at
    /// three meshes along the length with its Richardson estimate, and the coarsest mesh again at half the time step.
    /// </summary>
    public sealed class Csm3Targets
    {
        /// <summary>Tip u_y mean (m), amplitude (m) and frequency (Hz): the Richardson estimates of <see cref="Runs"/>.</summary>
        public double UyMean, UyAmplitude, UyFrequency;
        /// <summary>The reference per mesh of <see cref="ElementsAlong"/>, time step = the frame (1/60 s).</summary>
        public Csm3Result[] Runs;
        /// <summary>Richardson estimates (element length along x) of the u_y mean, amplitude and frequency.</summary>
        public ConvergenceEstimate Mean, Amplitude, Frequency;
        /// <summary>The coarsest mesh at half the time step (sampled at the same frames).</summary>
        public Csm3Result HalfStep;
        /// <summary>Wall-clock time of the reference runs (s), for the report only.</summary>
        public double Seconds;

        /// <summary>
        /// Q2 elements along the length, one across the height and one across the width. One Q2 element across the section
        /// holds the bending field of a beam (u_x linear, u_y quadratic across it, the anticlastic term included); refining
        /// across moves the values by less than 0.1 % (measured: 18 × 2 × 1 and 18 × 1 × 2 against 18 × 1 × 1, see
        /// <see cref="Csm3SolidReference"/>), while refining along the length moves them by ~2 % from 9 to 18 elements.
        /// </summary>
        public static readonly int[] ElementsAlong = { 9, 18, 36 };

        static readonly Dictionary<(float, float, float), Csm3Targets> s_Cache = new Dictionary<(float, float, float), Csm3Targets>();

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
            var t = new Csm3Targets { Runs = new Csm3Result[ElementsAlong.Length] };
            var size = new double[ElementsAlong.Length];
            var mean = new double[size.Length];
            var amplitude = new double[size.Length];
            var frequency = new double[size.Length];
            double dt = StudyScene.Dt;
            for (int i = 0; i < size.Length; i++)
            {
                t.Runs[i] = Csm3SolidReference.Run(ElementsAlong[i], 1, 1, dt, Csm3Scene.Duration, 1, e, nu, rho);
                t.Seconds += t.Runs[i].Seconds;
                size[i] = Csm3Reference.Length / ElementsAlong[i];
                mean[i] = t.Runs[i].UyMean;
                amplitude[i] = t.Runs[i].UyAmplitude;
                frequency[i] = t.Runs[i].UyFrequency;
            }
            t.Mean = RichardsonExtrapolation.Estimate(size, mean);
            t.Amplitude = RichardsonExtrapolation.Estimate(size, amplitude);
            t.Frequency = RichardsonExtrapolation.Estimate(size, frequency);
            (t.UyMean, t.UyAmplitude, t.UyFrequency) = (t.Mean.Extrapolated, t.Amplitude.Extrapolated, t.Frequency.Extrapolated);
            t.HalfStep = Csm3SolidReference.Run(ElementsAlong[0], 1, 1, 0.5 * dt, Csm3Scene.Duration, 2, e, nu, rho);
            t.Seconds += t.HalfStep.Seconds;
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
                s.Append(F(" Hz; Richardson (observed orders {0:0.0}, {1:0.0}, {2:0.0}): {3:0.000} ± {4:0.000} mm at {5:0.0000} Hz (the targets; estimated error of the finest mesh ",
                    Mean.Order, Amplitude.Order, Frequency.Order, UyMean * 1e3, UyAmplitude * 1e3, UyFrequency));
                s.Append(F("{0:0.00} %, {1:0.00} %, {2:0.00} %). ", 100 * Mean.ErrorEstimate / Math.Abs(UyMean),
                    100 * Amplitude.ErrorEstimate / UyAmplitude, 100 * Frequency.ErrorEstimate / UyFrequency));
                Csm3Result c = Runs[0];
                s.Append(F("Halving the time step on the {0}-element beam moves the mean by {1:0.000} %, the amplitude by {2:0.000} % and the frequency by {3:0.000} %. ",
                    c.ElementsX, Change(HalfStep.UyMean, c.UyMean), Change(HalfStep.UyAmplitude, c.UyAmplitude), Change(HalfStep.UyFrequency, c.UyFrequency)));
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
