using System;
using System.Diagnostics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Tip-displacement statistics of a CSM3 run.</summary>
    public struct Csm3Result
    {
        /// <summary>Tip u_y: mean (max + min)/2 (m), amplitude (max − min)/2 (m), frequency (Hz).</summary>
        public double UyMean, UyAmplitude, UyFrequency;
        /// <summary>Tip u_x: mean (m), amplitude (m), frequency (Hz), measured the same way.</summary>
        public double UxMean, UxAmplitude, UxFrequency;
        /// <summary>Elements along the length and across the height.</summary>
        public int ElementsX, ElementsY;
        /// <summary>Elements across the width (<see cref="Csm3SolidReference"/>; 0 for the 2-D plane-strain run).</summary>
        public int ElementsZ;
        /// <summary>Time step (s), duration (s), Newton iterations over the run, and whether every step converged.</summary>
        public double TimeStep, Duration;
        /// <summary>Newton iterations over the run.</summary>
        public int NewtonIterations;
        /// <summary>True if every step met the residual tolerance.</summary>
        public bool Converged;
        /// <summary>Wall-clock cost of the run (s), for the report only.</summary>
        public double Seconds;
    }

    /// <summary>
    /// The Turek–Hron CSM3 benchmark (Turek &amp; Hron 2006, "Proposal for numerical benchmarking of fluid–structure
    /// interaction", §3.2): an elastic beam 0.35 × 0.02 m, ρ = 1000 kg/m³, E = 1.4·10⁶ Pa, ν = 0.4, St Venant–Kirchhoff,
    /// gravity g = 2 m/s² (−y) applied from rest, no damping; the tip-midpoint A displacement is reported as
    /// mean ± amplitude [frequency]: u_y = −63.607 ± 65.160 mm [1.0995 Hz], u_x = −14.305 ± 14.305 mm [2.1991 Hz].
    /// <para>Here: 2-D plane strain, 9-node quadrilaterals (<see cref="FemReferenceModel"/>), the left end x = 0 clamped on a
    /// straight edge (the benchmark attaches it to a circle of radius 0.05; the straight clamp shortens the free
    /// edges by at most 0.001 m, ~0.3 % of L), Newmark average acceleration (<see cref="FemNewmark"/>, residual 1e-9).
    /// Statistics per complete cycle of the tip history (<see cref="OscillationStatistics"/>). The published u_x
    /// frequency is twice u_y's; the u_x history measured here repeats once per u_y cycle (shortening is largest at
    /// the lowest point and vanishes at the highest), so its measured frequency equals u_y's.</para>
    /// <para>Measured (h = 5 ms, 3 s): resolution 2 (35 × 2 elements) u_y = −64.12 ± 64.11 mm at 1.1008 Hz (mean +0.8 %,
    /// amplitude −1.6 %, frequency +0.12 % from the benchmark; ~5 s on two cores); resolution 4 (70 × 4)
    /// −64.28 ± 64.27 mm at 1.0994 Hz. Halving h moves mean and amplitude by ≤ 0.1 % (not monotonically: the sampled
    /// extremes carry higher bending modes) and the frequency converges at order ≈ 3.5 to 1.1010 Hz.</para>
    /// </summary>
    public static class Csm3Reference
    {
        /// <summary>Beam length (m).</summary>
        public const double Length = 0.35;
        /// <summary>Beam height (m).</summary>
        public const double Height = 0.02;
        /// <summary>ρ (kg/m³).</summary>
        public const double Density = 1000;
        /// <summary>E (Pa).</summary>
        public const double YoungModulus = 1.4e6;
        /// <summary>ν.</summary>
        public const double PoissonRatio = 0.4;
        /// <summary>g (m/s²).</summary>
        public const double Gravity = 2;

        /// <summary>Published u_y mean (m), amplitude (m), frequency (Hz).</summary>
        public const double PublishedUyMean = -0.063607, PublishedUyAmplitude = 0.065160, PublishedUyFrequency = 1.0995;
        /// <summary>Published u_x mean (m), amplitude (m), frequency (Hz).</summary>
        public const double PublishedUxMean = -0.014305, PublishedUxAmplitude = 0.014305, PublishedUxFrequency = 2.1991;

        /// <summary>Integrates the beam from rest and measures the tip.</summary>
        /// <param name="resolution">Elements across the height (≥ 1); 17.5× as many along the length (rounded).</param>
        /// <param name="timeStep">h (s), e.g. 0.005.</param>
        /// <param name="duration">Simulated time (s); ≥ 2.5 s gives two full periods.</param>
        public static Csm3Result Run(int resolution, double timeStep, double duration)
        {
            var clock = Stopwatch.StartNew();
            int nx = Math.Max(1, (int)Math.Round(Length / Height * resolution));
            FemBoxMesh mesh = FemBoxMesh.Rectangle(Length, Height, nx, resolution);
            var fixedDofs = new bool[mesh.DofCount];
            for (int j = 0; j < mesh.NodesY; j++)
            {
                int node = mesh.Node(0, j, 0);
                fixedDofs[node * 2] = fixedDofs[node * 2 + 1] = true;
            }
            var model = new FemReferenceModel(mesh, new FemMaterial(FemMaterialLaw.StVenantKirchhoff, YoungModulus, PoissonRatio), Density, fixedDofs);
            var integrator = new FemNewmark(model, model.BodyForce(new[] { 0, -Gravity }), timeStep);
            int tip = mesh.Node(mesh.NodesX - 1, resolution, 0);
            int steps = (int)Math.Round(duration / timeStep);
            var ux = new double[steps + 1];
            var uy = new double[steps + 1];
            var result = new Csm3Result { ElementsX = nx, ElementsY = resolution, TimeStep = timeStep, Duration = steps * timeStep, Converged = true };
            for (int s = 1; s <= steps; s++)
            {
                FemSolveReport r = integrator.Step();
                result.NewtonIterations += r.NewtonIterations;
                result.Converged &= r.Converged;
                ux[s] = integrator.U[tip * 2];
                uy[s] = integrator.U[tip * 2 + 1];
            }
            (result.UyMean, result.UyAmplitude, result.UyFrequency) = OscillationStatistics.Measure(uy, timeStep);
            (result.UxMean, result.UxAmplitude, result.UxFrequency) = OscillationStatistics.Measure(ux, timeStep);
            result.Seconds = clock.Elapsed.TotalSeconds;
            return result;
        }

        /// <summary>
        /// The u_y statistics at time steps <paramref name="timeSteps"/> (descending, ≥ 3) with a Richardson estimate per
        /// quantity: Values[0], [1], [2] of each entry = mean, amplitude, frequency.
        /// </summary>
        public static (Csm3Result[] Runs, ConvergenceEstimate Mean, ConvergenceEstimate Amplitude, ConvergenceEstimate Frequency)
            TimeStepConvergence(int resolution, double[] timeSteps, double duration)
        {
            var runs = new Csm3Result[timeSteps.Length];
            var mean = new double[runs.Length];
            var amplitude = new double[runs.Length];
            var frequency = new double[runs.Length];
            for (int i = 0; i < runs.Length; i++)
            {
                runs[i] = Run(resolution, timeSteps[i], duration);
                mean[i] = runs[i].UyMean;
                amplitude[i] = runs[i].UyAmplitude;
                frequency[i] = runs[i].UyFrequency;
            }
            return (runs, RichardsonExtrapolation.Estimate(timeSteps, mean), RichardsonExtrapolation.Estimate(timeSteps, amplitude),
                RichardsonExtrapolation.Estimate(timeSteps, frequency));
        }
    }

    /// <summary>Mean, amplitude and frequency of a sampled oscillation, cycle by cycle.</summary>
    public static class OscillationStatistics
    {
        /// <summary>
        /// Cycles are cut at the upward crossings of the mid-level c = (max y + min y)/2 (linear interpolation; a crossing
        /// counts only after y has been below c − (max − min)/4 since the last one, so small superposed vibrations do not
        /// add crossings). Per complete cycle: its maximum and minimum (each refined by the parabola through the sample
        /// and its neighbours); mean = (avg max + avg min)/2, amplitude = (avg max − avg min)/2, frequency = 1 / the mean
        /// spacing of the crossings. NaN if fewer than one complete cycle is sampled.
        /// </summary>
        public static (double Mean, double Amplitude, double Frequency) Measure(ReadOnlySpan<double> y, double dt)
        {
            double hi = double.NegativeInfinity, lo = double.PositiveInfinity;
            foreach (double v in y)
            {
                hi = Math.Max(hi, v);
                lo = Math.Min(lo, v);
            }
            double c = 0.5 * (hi + lo), arm = c - 0.25 * (hi - lo);
            bool armed = false;
            int cycles = 0, lastK = -1;
            double firstT = 0, lastT = 0, maxSum = 0, minSum = 0;
            for (int k = 1; k < y.Length; k++)
            {
                if (y[k] < arm)
                    armed = true;
                if (!(armed && y[k - 1] < c && y[k] >= c))
                    continue;
                armed = false;
                double t = (k - 1 + (c - y[k - 1]) / (y[k] - y[k - 1])) * dt;
                if (lastK >= 0)
                {
                    cycles++;
                    maxSum += Extremum(y, lastK, k, +1);
                    minSum += Extremum(y, lastK, k, -1);
                }
                else
                    firstT = t;
                lastT = t;
                lastK = k;
            }
            if (cycles < 1)
                return (double.NaN, double.NaN, double.NaN);
            double top = maxSum / cycles, bottom = minSum / cycles;
            return (0.5 * (top + bottom), 0.5 * (top - bottom), cycles / (lastT - firstT));
        }

        /// <summary>The largest (sign +1) or smallest (−1) sample in [from, to), parabola-refined.</summary>
        static double Extremum(ReadOnlySpan<double> y, int from, int to, int sign)
        {
            int best = from;
            for (int k = from; k < to; k++)
                if (sign * y[k] > sign * y[best])
                    best = k;
            if (best == 0 || best + 1 >= y.Length)
                return y[best];
            double curvature = y[best - 1] - 2 * y[best] + y[best + 1];
            if (curvature == 0)
                return y[best];
            double delta = 0.5 * (y[best - 1] - y[best + 1]) / curvature;
            return y[best] - 0.25 * (y[best - 1] - y[best + 1]) * delta;
        }
    }
}
