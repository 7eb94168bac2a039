using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Reference values of the squash-and-release scene (of the continuum: the same for every mesh), computed once per
    /// material: the exact squashed state (<see cref="UniaxialNeoHookean"/>) and the release of the float64 reference
    /// (<see cref="SquashReference"/>) read by <see cref="SquashMeasures"/> at the study's frame instants, extrapolated in
    /// mesh size and time step.
    /// </summary>
    public sealed class SquashTargets
    {
        /// <summary>Lateral stretch s of the squashed cube (exact).</summary>
        public double LateralStretch;
        /// <summary>Volume ratio J = λ s² of the squashed cube (exact).</summary>
        public double VolumeRatio;
        /// <summary>Rayleigh coefficient β = 2ζ/ω_ref (s) the reference is damped with (the package's FEM and mass-spring rule).</summary>
        public double Beta;
        /// <summary>ω₁ (rad/s): the lowest mode of the cube the squash excites (finest reference mesh), the velocity scale of the amplitude.</summary>
        public double Omega;
        /// <summary>Target overshoot (dimensionless, see <see cref="SquashMeasures.Overshoot"/>).</summary>
        public double Overshoot;
        /// <summary>Target recovery time (s, see <see cref="SquashMeasures.RecoveryTime"/>).</summary>
        public double RecoveryTime;
        /// <summary>Overshoot and recovery time of the finest run read at every reference step instead of every frame (the estimators' sampling bias).</summary>
        public double OvershootEveryStep, RecoveryTimeEveryStep;
        /// <summary>Elements per half edge of the mesh runs (ascending), all at <see cref="StepsPerFrame"/>[0] steps per frame.</summary>
        public int[] Resolutions;
        /// <summary>Newmark steps per frame of the time-step runs (ascending), all at <see cref="Resolutions"/>[0].</summary>
        public int[] StepsPerFrame;
        /// <summary>Overshoot and recovery time (s) per mesh run.</summary>
        public double[] OvershootByMesh, RecoveryByMesh;
        /// <summary>Overshoot and recovery time (s) per time-step run.</summary>
        public double[] OvershootByStep, RecoveryByStep;
        /// <summary>Richardson estimates over the mesh runs (order NaN with fewer than 3 runs or no monotone convergence).</summary>
        public ConvergenceEstimate OvershootMesh, RecoveryMesh;
        /// <summary>Richardson estimates over the time-step runs.</summary>
        public ConvergenceEstimate OvershootTime, RecoveryTimeStep;
        /// <summary>Seconds the computation took.</summary>
        public double Seconds;

        /// <summary>Mesh runs of the study's targets: 1, 2 and 3 Q2 elements per half edge (2, 4, 6 across the cube).</summary>
        public static readonly int[] ReferenceResolutions = { 1, 2, 3 };
        /// <summary>Time-step runs of the study's targets: 4, 8 and 16 Newmark steps per 1/60 s frame.</summary>
        public static readonly int[] ReferenceStepsPerFrame = { 4, 8, 16 };
        /// <summary>Frames of the first (coarsest) run; the others stop 10 frames after its recovery (the runs differ by ~1 frame).</summary>
        public const int MaxFrames = 90;

        static readonly Dictionary<(float, float, float, float), SquashTargets> s_Cache = new Dictionary<(float, float, float, float), SquashTargets>();

        /// <summary>Takes <paramref name="targets"/> as the values of <paramref name="material"/>: values an earlier run computed from the same reference sources.</summary>
        public static void Remember(in ElasticMaterial material, SquashTargets targets)
        {
            lock (s_Cache)
                s_Cache[(material.YoungsModulus, material.PoissonRatio, material.Density, material.DampingRatio)] = targets;
        }

        /// <summary>The study's targets for <paramref name="material"/>, computed once (<see cref="ReferenceResolutions"/>, <see cref="ReferenceStepsPerFrame"/>).</summary>
        public static SquashTargets Get(in ElasticMaterial material)
        {
            lock (s_Cache)
            {
                var key = (material.YoungsModulus, material.PoissonRatio, material.Density, material.DampingRatio);
                if (!s_Cache.TryGetValue(key, out SquashTargets t))
                    s_Cache[key] = t = Compute(material, ReferenceResolutions, ReferenceStepsPerFrame);
                return t;
            }
        }

        /// <summary>The targets for <paramref name="material"/> if <see cref="Get"/> has computed them (computes nothing).</summary>
        public static bool TryGetCached(in ElasticMaterial material, out SquashTargets targets)
        {
            lock (s_Cache)
                return s_Cache.TryGetValue((material.YoungsModulus, material.PoissonRatio, material.Density, material.DampingRatio), out targets);
        }

        /// <summary>β = 2ζ/ω_ref with ω_ref = π √(μ/ρ) / L for the cube of edge L: the rule of FemModelData.DefaultReferenceFrequency and MassSpringCalibration.</summary>
        public static double DampingCoefficient(in ElasticMaterial material, float size)
        {
            float omega = FemModelData.DefaultReferenceFrequency(material, size);
            return omega > 0f ? 2.0 * material.DampingRatio / omega : 0.0;
        }

        /// <summary>
        /// Targets from mesh runs at <paramref name="resolutions"/> (each at <paramref name="stepsPerFrame"/>[0]) and time-step runs
        /// at <paramref name="stepsPerFrame"/> (each at <paramref name="resolutions"/>[0]): value = mesh estimate + (time estimate −
        /// coarsest-step value), the two discretisation errors being additive to leading order. An estimate from fewer than
        /// three runs is the finest run's value.
        /// </summary>
        public static SquashTargets Compute(in ElasticMaterial material, int[] resolutions, int[] stepsPerFrame)
        {
            var clock = System.Diagnostics.Stopwatch.StartNew();
            double e = material.YoungsModulus, nu = material.PoissonRatio, rho = material.Density, size = SquashScene.Size;
            double stretch = SquashScene.Stretch;
            UniaxialResult squashed = UniaxialNeoHookean.Stress(stretch, e, nu, SquashReference.Law);
            var t = new SquashTargets
            {
                LateralStretch = squashed.LateralStretch,
                VolumeRatio = squashed.VolumeRatio,
                Beta = DampingCoefficient(material, SquashScene.Size),
                Omega = SquashReference.LowestSymmetricFrequency(size, e, nu, rho, resolutions[resolutions.Length - 1]),
                Resolutions = resolutions,
                StepsPerFrame = stepsPerFrame,
                OvershootByMesh = new double[resolutions.Length],
                RecoveryByMesh = new double[resolutions.Length],
                OvershootByStep = new double[stepsPerFrame.Length],
                RecoveryByStep = new double[stepsPerFrame.Length],
            };
            int frames = MaxFrames;
            for (int i = 0; i < resolutions.Length; i++)
            {
                SquashHistory h = SquashReference.Release(size, e, nu, rho, resolutions[i], stretch, t.Beta, StudyScene.Dt, stepsPerFrame[0], frames);
                (t.OvershootByMesh[i], t.RecoveryByMesh[i]) = t.Read(h, h.StepsPerFrame);
                if (i == 0)
                {
                    if (t.RecoveryByMesh[0] < MaxFrames * StudyScene.Dt)
                        frames = Math.Min(MaxFrames, (int)Math.Ceiling(t.RecoveryByMesh[0] / StudyScene.Dt) + 10);
                    (t.OvershootByStep[0], t.RecoveryByStep[0]) = (t.OvershootByMesh[0], t.RecoveryByMesh[0]);
                }
                if (i == resolutions.Length - 1)
                    (t.OvershootEveryStep, t.RecoveryTimeEveryStep) = t.Read(h, 1);
            }
            for (int j = 1; j < stepsPerFrame.Length; j++)
            {
                SquashHistory h = SquashReference.Release(size, e, nu, rho, resolutions[0], stretch, t.Beta, StudyScene.Dt, stepsPerFrame[j], frames);
                (t.OvershootByStep[j], t.RecoveryByStep[j]) = t.Read(h, h.StepsPerFrame);
            }
            var meshSize = new double[resolutions.Length];
            for (int i = 0; i < meshSize.Length; i++)
                meshSize[i] = 0.5 * size / resolutions[i];
            var stepSize = new double[stepsPerFrame.Length];
            for (int j = 0; j < stepSize.Length; j++)
                stepSize[j] = StudyScene.Dt / stepsPerFrame[j];
            t.OvershootMesh = Estimate(meshSize, t.OvershootByMesh);
            t.RecoveryMesh = Estimate(meshSize, t.RecoveryByMesh);
            t.OvershootTime = Estimate(stepSize, t.OvershootByStep);
            t.RecoveryTimeStep = Estimate(stepSize, t.RecoveryByStep);
            t.Overshoot = t.OvershootMesh.Extrapolated + (t.OvershootTime.Extrapolated - t.OvershootByStep[0]);
            t.RecoveryTime = t.RecoveryMesh.Extrapolated + (t.RecoveryTimeStep.Extrapolated - t.RecoveryByStep[0]);
            t.Seconds = clock.Elapsed.TotalSeconds;
            return t;
        }

        /// <summary>Overshoot and recovery time (s) of a reference run read every <paramref name="stride"/> steps.</summary>
        (double Overshoot, double Recovery) Read(SquashHistory h, int stride)
        {
            int count = (h.Height.Length - 1) / stride + 1;
            var height = new double[count];
            var amplitude = new double[count];
            for (int k = 0; k < count; k++)
            {
                height[k] = h.Height[k * stride];
                amplitude[k] = SquashMeasures.Amplitude(h.Displacement[k * stride], h.Speed[k * stride], Omega, SquashScene.Size);
            }
            return (SquashMeasures.Overshoot(height, SquashScene.Size, SquashScene.Stretch * SquashScene.Size),
                SquashMeasures.RecoveryTime(amplitude, h.Interval * stride, SquashScene.RecoveryThreshold));
        }

        static ConvergenceEstimate Estimate(double[] h, double[] f) =>
            f.Length >= 3 ? RichardsonExtrapolation.Estimate(h, f)
                : new ConvergenceEstimate { Extrapolated = f[f.Length - 1], Order = double.NaN,
                    ErrorEstimate = f.Length == 2 ? Math.Abs(f[1] - f[0]) : double.NaN };

        /// <summary>The reference's values per run and their extrapolation, for the scene's description.</summary>
        public string Summary()
        {
            var s = new StringBuilder();
            s.Append($"Reference ({Seconds:0} s to compute): exact squashed state s = {F(LateralStretch, 5)}, J = {F(VolumeRatio, 5)}; ");
            s.Append($"β = {F(Beta * 1e3, 3)} ms; ω₁ = {F(Omega, 3)} rad/s. Overshoot ");
            Runs(s, Resolutions, OvershootByMesh, "", 4);
            s.Append($" at {string.Join(", ", Resolutions)} Q2 elements per half edge ({StepsPerFrame[0]} steps per frame; Richardson {F(OvershootMesh.Extrapolated, 4)}, order {F(OvershootMesh.Order, 1)}), ");
            Runs(s, StepsPerFrame, OvershootByStep, "", 4);
            s.Append($" at {string.Join(", ", StepsPerFrame)} steps per frame ({Resolutions[0]} per half edge; Richardson {F(OvershootTime.Extrapolated, 4)}, order {F(OvershootTime.Order, 1)}): target {F(Overshoot, 4)} ");
            s.Append($"({F(OvershootEveryStep, 4)} read at every step instead of every frame). Recovery time ");
            Runs(s, Resolutions, RecoveryByMesh, " s", 4);
            s.Append($" by mesh (Richardson {F(RecoveryMesh.Extrapolated, 4)} s, order {F(RecoveryMesh.Order, 1)}), ");
            Runs(s, StepsPerFrame, RecoveryByStep, " s", 4);
            s.Append($" by step (Richardson {F(RecoveryTimeStep.Extrapolated, 4)} s, order {F(RecoveryTimeStep.Order, 1)}): target {F(RecoveryTime, 4)} s ");
            s.Append($"({F(RecoveryTimeEveryStep, 4)} s read at every step).");
            return s.ToString();
        }

        static void Runs(StringBuilder s, int[] runs, double[] values, string unit, int digits)
        {
            for (int i = 0; i < runs.Length; i++)
                s.Append(i == 0 ? "" : ", ").Append(F(values[i], digits)).Append(unit);
        }

        static string F(double v, int digits) => double.IsNaN(v) ? "n/a" : v.ToString("F" + digits, CultureInfo.InvariantCulture);
    }
}
