using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>What <see cref="RestingSag.Run"/> measured.</summary>
    public struct RestingSagResult
    {
        /// <summary>Height of the centre of mass above the floor at rest (m), the mean over the last <see cref="RestingSag.Window"/>.</summary>
        public double Height;
        /// <summary>How far the centre sank below its undeformed height (m): the sag.</summary>
        public double Deflection;
        /// <summary>det(A_pq A_qq⁻¹) of the whole body at rest (1 = volume kept).</summary>
        public double VolumeRatio;
        /// <summary>Largest − smallest centre height over the averaging window (m): what is left of the settling.</summary>
        public double Unsettled;
        /// <summary>Time simulated (s).</summary>
        public double SettleTime;
        /// <summary>Substeps per step the solver took.</summary>
        public int Substeps;
        /// <summary>NaN-guard resets (0 expected).</summary>
        public int Resets;
        /// <summary>Plastic updates of any cluster (0 expected: the sag strain is far below every preset's yield).</summary>
        public int PlasticUpdates;
    }

    /// <summary>The dt → 0 resting state of <see cref="RestingSag.Extrapolate"/>.</summary>
    public struct RestingSagReference
    {
        /// <summary>Sag (m).</summary>
        public double Deflection;
        /// <summary>Centre height (m).</summary>
        public double Height;
        /// <summary>det(A_pq A_qq⁻¹) at rest.</summary>
        public double VolumeRatio;
        /// <summary>Estimated relative error of <see cref="Deflection"/> (dimensionless).</summary>
        public double Uncertainty;
        /// <summary>Largest coordinate of the body relative to its centre (m): what float32 positions round against.</summary>
        public double Extent;
        /// <summary>ωh of the finest run (rad).</summary>
        public double FinestPhase;
        /// <summary>Largest unsettled height spread of the runs (m).</summary>
        public double Unsettled;
    }

    /// <summary>
    /// The resting test: a body placed in its rest shape (centre at the origin) with its bottom particles touching a
    /// floor plane at their radius, released under gravity (−9.81 m/s² along y) and left to settle (sleeping off, so the solver keeps stepping;
    /// see <see cref="Run"/>). The sag is the drop of the centre of mass from its undeformed height.
    /// <para>Why the sag depends on the step, and by how much: at rest (v = 0) a substep leaves x unchanged when
    /// h a + α (g − x)/h + contact = 0, while the continuous model rests where a + ω² (g − x) + contact = 0. The
    /// discrete body is therefore the continuous one with ω² replaced by α/h², and a small sag scales with 1/ω²:
    /// sag(h) / sag(0) = (ωh)²/α(ωh, ζ) = 1 + ζωh + (1/12 + ζ²/3)(ωh)² + O((ωh)³), with α the pull of
    /// <see cref="OscillatorDiscretization"/>.</para>
    /// </summary>
    public static class RestingSag
    {
        /// <summary>Shortest settling time (s).</summary>
        public const double MinSettleTime = 2.0;
        /// <summary>Longest settling time (s).</summary>
        public const double MaxSettleTime = 8.0;
        /// <summary>Window (s) the height is averaged over and its spread checked in.</summary>
        public const double Window = 0.5;
        /// <summary>Settled when the centre height varies by less than this fraction of the sag over a window.</summary>
        public const double SettleTolerance = 1e-4;
        /// <summary>Gravity (m/s², along −y).</summary>
        public const float Gravity = 9.81f;

        /// <summary>
        /// Settles the body (at least <see cref="MinSettleTime"/>, then window by window until the centre height varies
        /// by less than <see cref="SettleTolerance"/> of the sag within one, at most <see cref="MaxSettleTime"/>) and
        /// measures the last window. A body on a floor settles slowly in its squash mode: the damping acts only on the
        /// velocity that differs from the body's rigid motion, and the centre bobbing on the floor is mostly rigid
        /// translation (Jelly: about 1.8/s, so about 6 s). The body's rest centre is at the world origin and the floor
        /// below it, so float32 positions keep their finest resolution (|x| &lt; 0.5 m for the suite's body).
        /// </summary>
        public static RestingSagResult Run(ShapeMatchingModelData model, ShapeMatchingParameters parameters, float dt)
        {
            parameters.Body.Acceleration = new float3(0f, -Gravity, 0f);
            parameters.Body.SleepSpeed = 0f;
            var body = new ShapeMatchingInstance(model, parameters, float3.zero, quaternion.identity);
            ColliderShape[] floor = { Floor(model, parameters.Body.ParticleRadius) };
            double floorHeight = floor[0].Center.y;
            double restHeight = BodyMeasures.Center(body.Positions, model.Masses).Y - floorHeight;
            int window = Math.Max(2, (int)Math.Round(Window / dt));
            int minSteps = (int)Math.Round(MinSettleTime / dt), maxSteps = (int)Math.Round(MaxSettleTime / dt);
            var result = new RestingSagResult();
            int step = 0;
            while (true)
            {
                double sum = 0, lowest = double.PositiveInfinity, highest = double.NegativeInfinity;
                for (int s = 0; s < window; s++, step++)
                {
                    ShapeMatchingStepReport report = body.Step(dt, floor);
                    result.Substeps = report.Substeps;
                    result.Resets += report.Reset ? 1 : 0;
                    result.PlasticUpdates += report.PlasticUpdates;
                    double height = BodyMeasures.Center(body.Positions, model.Masses).Y + body.Status.Origin.y - floorHeight;
                    sum += height;
                    lowest = Math.Min(lowest, height);
                    highest = Math.Max(highest, height);
                }
                result.Height = sum / window;
                result.Deflection = restHeight - result.Height;
                result.Unsettled = highest - lowest;
                result.SettleTime = step * (double)dt;
                if (step >= maxSteps || (step >= minSteps && result.Unsettled <= SettleTolerance * Math.Abs(result.Deflection)))
                    break;
            }
            result.VolumeRatio = BodyMeasures.VolumeRatio(body.Positions, model.AsModel());
            return result;
        }

        /// <summary>The floor plane under a body whose rest centre is at the origin: its bottom particles touch it at their radius.</summary>
        public static ColliderShape Floor(ShapeMatchingModelData model, float particleRadius)
        {
            float bottom = float.MaxValue;
            foreach (float3 p in model.RestPositions)
                bottom = math.min(bottom, p.y);
            float3 restCenter = ShapeMatching.CenterOfMass(model.RestPositions, model.Masses);
            return ColliderShape.Plane(new float3(0f, bottom - restCenter.y - particleRadius, 0f), new float3(0f, 1f, 0f));
        }

        /// <summary>Phase ωh (rad) of the finest of the three runs <see cref="Extrapolate"/> combines.</summary>
        public const double ReferencePhase = 0.05;
        /// <summary>Frame step of the extrapolation runs (s).</summary>
        public const float ReferenceStep = 1f / 120f;

        /// <summary>
        /// The dt → 0 resting state, by Richardson extrapolation of the solver itself: runs at ωh ≈ φ, 2φ and 4φ
        /// (φ = <see cref="ReferencePhase"/>, 1/120 s steps with as many substeps as that takes); the sag is
        /// s(h) = s₀(1 + c₁h + c₂h² + c₃h³ + …), so (8 s(φ) − 6 s(2φ) + s(4φ)) / 3 removes the first two terms.
        /// Its relative uncertainty (returned) has two parts: the c₃ term left, 8·c₃·φ³ with c₃ ≈ ζ/12 (the rule's
        /// expansion, <see cref="PredictedSagRatio"/>), taken 1.5 times; and the float32 dead band of the runs
        /// (<see cref="AccuracyTolerances.RestingDeadBand"/> at the finest h), which the extrapolation's coefficients
        /// amplify by √(8² + 6² + 1²)/3 ≈ 3.4. φ is not taken smaller because the dead band grows as 1/h.
        /// </summary>
        public static RestingSagReference Extrapolate(ShapeMatchingModelData model, ShapeMatchingParameters parameters)
        {
            ShapeMatchingParameters p = parameters.Sanitized();
            double omega = p.AngularFrequency;
            int fine = Math.Min(ShapeMatchingParameters.MaxSubsteps, Math.Max(4, (int)Math.Ceiling(omega * ReferenceStep / ReferencePhase)));
            fine += (4 - fine % 4) % 4;
            p.MaxSubstepPhase = 1000f;
            var runs = new RestingSagResult[3];
            for (int k = 0; k < 3; k++)
            {
                p.Body.Substeps = fine >> k;
                runs[k] = Run(model, p, ReferenceStep);
            }
            double deflection = (8 * runs[0].Deflection - 6 * runs[1].Deflection + runs[2].Deflection) / 3;
            double volume = (8 * runs[0].VolumeRatio - 6 * runs[1].VolumeRatio + runs[2].VolumeRatio) / 3;
            double restHeight = runs[0].Height + runs[0].Deflection;
            double phase = omega * ReferenceStep / fine;
            double zeta = p.DampingRatio;
            double extent = MaxExtent(model);
            return new RestingSagReference
            {
                Deflection = deflection,
                Height = restHeight - deflection,
                VolumeRatio = volume,
                Uncertainty = 1.5 * 8 * (zeta / 12) * phase * phase * phase
                              + 3.4 * AccuracyTolerances.RestingDeadBand(extent, zeta, omega, Gravity, ReferenceStep / fine),
                FinestPhase = phase,
                Unsettled = Math.Max(runs[0].Unsettled, Math.Max(runs[1].Unsettled, runs[2].Unsettled)),
                Extent = extent,
            };
        }

        /// <summary>Largest |x⁰ − x⁰_cm| of the rest shape (m): the float32 positions of a body centred at the origin stay about this size.</summary>
        public static double MaxExtent(ShapeMatchingModelData model)
        {
            float3 c = ShapeMatching.CenterOfMass(model.RestPositions, model.Masses);
            double extent = 0;
            foreach (float3 p in model.RestPositions)
                extent = Math.Max(extent, math.cmax(math.abs(p - c)));
            return extent;
        }

        /// <summary>
        /// sag(h)/sag(0) = (ωh)²/α predicted for a substep of <paramref name="h"/> (s), with α from the oscillator's exact
        /// eigenvalues (<see cref="AccuracyTolerances.Pull"/>, float64, independent of <see cref="OscillatorDiscretization"/>).
        /// </summary>
        public static double PredictedSagRatio(double omega, double zeta, double h)
        {
            double x = omega * h;
            return x * x / AccuracyTolerances.Pull(omega, zeta, h);
        }
    }
}
