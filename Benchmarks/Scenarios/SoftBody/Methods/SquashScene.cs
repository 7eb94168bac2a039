using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// A free jelly cube squashed to half its height between two frictionless plates, then released with no gravity: the
    /// volume it keeps while squashed (against the exact homogeneous Neo-Hookean compression), the time its deformation
    /// takes to fall below 1 % of its size and how far it overshoots its rest height (both against the float64 reference
    /// released from the same state, <see cref="SquashTargets"/>).
    /// </summary>
    public sealed class SquashScene : StudyScene
    {
        /// <summary>
        /// Cube edge L (m). The cube's lowest excited mode has f₁ ≈ 0.71 √(μ/ρ)/L (3.3 Hz here): with 18 frames per period the
        /// frame-sampled overshoot peak is read to ~0.1 % by its parabola. At 0.1 m (13 Hz, 4.5 frames per period) no
        /// estimator could read the peak from 1/60 s frames (the parabola would miss it by up to 8 % of the oscillation).
        /// </summary>
        public const float Size = 0.4f;
        /// <summary>Cells per edge of the default resolution.</summary>
        public const int DefaultCells = 4;
        /// <summary>Axial stretch λ of the squash: the plates are λL apart.</summary>
        public const float Stretch = 0.5f;
        /// <summary>Time between the plates (s): the lateral motion the start excites decays by e^(−ζ₁ω₁t) ≈ e^(−3) or faster (ζ₁ω₁ ≈ 2.9 s⁻¹ for the lowest mode, more for the others).</summary>
        public const float SquashTime = 1f;
        /// <summary>The squashed volume is averaged over this last part of <see cref="SquashTime"/> (s; about one period of ω₁).</summary>
        public const float VolumeAverageTime = 0.3f;
        /// <summary>Free run after the release (s): about twice the reference's recovery time (≈ 0.73 s).</summary>
        public const float ReleaseTime = 1.5f;
        /// <summary>Recovered when the deformation amplitude (<see cref="SquashMeasures"/>) is at most this fraction of L.</summary>
        public const float RecoveryThreshold = 0.01f;

        /// <summary>Metric: |V / (J V₀) − 1| while squashed.</summary>
        public const string VolumeError = "volume err";
        /// <summary>Metric: recovery-time error against the reference.</summary>
        public const string RecoveryError = "recovery err";
        /// <summary>Metric: overshoot error against the reference.</summary>
        public const string OvershootError = "overshoot err";
        /// <summary>Metric: recovery time (s); the release window if the body had not recovered by its end.</summary>
        public const string Recovery = "recovery";
        /// <summary>Metric: overshoot (fraction of the squash).</summary>
        public const string OvershootMetric = "overshoot";
        /// <summary>Metric: 1 if the body recovered within the window, else 0 (its recovery error is then a lower bound).</summary>
        public const string Recovered = "recovered";


        /// <summary>Gelatin (E 10 kPa, ν 0.45, 1000 kg/m³, ζ 0.1).</summary>
        public static ElasticMaterial Material => ElasticMaterial.Jelly;

        public override string Name => "MethodStudySquash";

        public override float CellSize => CellSizeAt(0);

        public override MethodBodySetup Setup => SetupAt(0);

        /// <summary>No gravity: the released cube's centre of mass stays put by symmetry.</summary>
        protected override float3 TimedGravity => float3.zero;

        /// <summary>The cube with <paramref name="resolution"/> cells per edge (0 = <see cref="DefaultCells"/>), built once.</summary>
        public override MethodBodySetup SetupAt(int resolution) =>
            CachedSetup(resolution > 0 ? resolution : DefaultCells, n => CreateSetup(n));

        public override float CellSizeAt(int resolution) => Size / (resolution > 0 ? resolution : DefaultCells);

        /// <summary>The cube centred at the origin with <paramref name="cells"/> cells per edge; no pins, point particles, no friction.</summary>
        public static MethodBodySetup CreateSetup(int cells) => new MethodBodySetup
        {
            Mesh = BoxTetrahedra.Create(new float3(Size), new int3(cells), float3.zero),
            Material = Material,
            // Point particles: the plates hold the face nodes exactly λL apart.
            ParticleRadius = 0f,
            Friction = 0f,
            CalibrationLength = Size,
            CalibrationLoad = ShapeMatchingCalibration.Load.Compression,
        };

        /// <summary>One timed frame: a free step of the released cube; every <see cref="StudyScene.FramesPerCycle"/> frames it is squashed again.</summary>
        public override void TimedFrame(IMethodBody body, int frame)
        {
            if (frame % FramesPerCycle == 0)
            {
                body.Place();
                WriteSquashed(body, UniaxialNeoHookean.Stress(Stretch, Material.YoungsModulus, Material.PoissonRatio, SquashReference.Law).LateralStretch);
            }
            body.Step(Dt, TimedGravity, ReadOnlySpan<ColliderShape>.Empty);
        }

        public override SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "What each method costs to keep a squashed jelly cube's volume and, once released, to recover its shape as fast and with as much overshoot as the reference.",
            Body = $"A free {Size} m cube, {DefaultCells}³ cells of 6 tetrahedra ({(DefaultCells + 1) * (DefaultCells + 1) * (DefaultCells + 1)} particles; " +
                   "rows swept in resolution: n³ cells, n = cells per edge in the label), point particles, no pins.",
            Material = $"Jelly ({MaterialText(Material)}, ζ = {Number(Material.DampingRatio)}); no gravity, frictionless plates.",
            Load = $"Written at rest in the exact homogeneous squash y → {Stretch}y, x, z → s·x, s·z (s: uniaxial, the package's stable Neo-Hookean law), held {SquashTime} s " +
                   $"between plates {Stretch}L apart, then released (plates removed) for {ReleaseTime} s.",
            Reference = "Volume: the exact ratio J = λs² of the package's Neo-Hookean law (stable Neo-Hookean, Smith et al. 2018; the classical compressible law keeps 1.4 % more). " +
                        "Recovery and overshoot: float64 FEM (Q2 hexahedra, the same law, Newmark, the package's " +
                        "Kelvin–Voigt damping) released from the same state, read at the same frames by the same estimators" +
                        (SquashTargets.TryGetCached(Material, out SquashTargets t) ? $": recovery {Number(t.RecoveryTime)} s, overshoot {Number(t.Overshoot)}." : "."),
            Metric = $"'{Error}' = the worst of '{VolumeError}' (|V/(J V₀) − 1|, V averaged over the last {VolumeAverageTime} s squashed), '{RecoveryError}' and " +
                     $"'{OvershootError}' (relative to the reference); '{Recovery}' (s) and '{OvershootMetric}' (fraction of the squash (1 − λ)L) are the raw values.",
            Notes = new[]
            {
                $"Recovery time: when the deformation amplitude A = √(X² + (V/ω₁)²)/L last falls below {RecoveryThreshold * 100} %; '{Recovered}' = 0: not within " +
                $"{ReleaseTime} s, which then counts as its recovery time (the error is a lower bound).",
            },
            Details = "choosing-a-method.md#squash-and-release-methodstudysquash",
        };

        /// <summary>Writes the homogeneous squash about the rest centre (y by λ, x and z by <paramref name="lateral"/>) at rest.</summary>
        public static void WriteSquashed(IMethodBody body, double lateral)
        {
            float3 scale = new float3((float)lateral, Stretch, (float)lateral);
            float3[] rest = body.RestPositions;
            for (int i = 0; i < body.ParticleCount; i++)
            {
                body.Positions[i] = scale * rest[i];
                body.Velocities[i] = float3.zero;
            }
            body.StateWritten();
        }

        /// <summary>The two frictionless plates: planes at y = ±λL/2, their normals toward the cube.</summary>
        public static ColliderShape[] Plates() => new[]
        {
            ColliderShape.Plane(new float3(0f, 0.5f * Stretch * Size, 0f), new float3(0f, -1f, 0f)),
            ColliderShape.Plane(new float3(0f, -0.5f * Stretch * Size, 0f), new float3(0f, 1f, 0f)),
        };

        public override object Reference() => SquashTargets.Get(Material);

        public override Type ReferenceType => typeof(SquashTargets);

        public override void UseReference(object values) => SquashTargets.Remember(Material, (SquashTargets)values);

        public override IReadOnlyList<Metric> Measure(MethodBodySetup setup, Func<MethodBodySetup, IMethodBody> build) =>
            Measure(setup, build, SquashTargets.Get(setup.Material));

        /// <summary><see cref="Measure(MethodBodySetup, Func{MethodBodySetup, IMethodBody})"/> against given targets (tests pass cheaper ones).</summary>
        public IReadOnlyList<Metric> Measure(MethodBodySetup setup, Func<MethodBodySetup, IMethodBody> build, SquashTargets targets)
        {
            IMethodBody body = build(setup);
            body.Place();
            WriteSquashed(body, targets.LateralStretch);
            ColliderShape[] plates = Plates();
            int squashFrames = (int)Math.Round(SquashTime / Dt), averageFrames = (int)Math.Round(VolumeAverageTime / Dt);
            double volume = 0;
            for (int k = 0; k < squashFrames; k++)
            {
                body.Step(Dt, float3.zero, plates);
                if (k >= squashFrames - averageFrames)
                    volume += StudyBox.Volume(setup.Mesh, body.Positions);
            }
            volume /= averageFrames;
            double restVolume = StudyBox.Volume(setup.Mesh, setup.Mesh.Positions);

            int releaseFrames = (int)Math.Round(ReleaseTime / Dt);
            var height = new double[releaseFrames + 1];
            var amplitude = new double[releaseFrames + 1];
            float half = 0.5f * Size, tolerance = 1e-4f * Size;
            double[] top = SquashMeasures.FaceWeights(setup.Mesh, half, tolerance), bottom = SquashMeasures.FaceWeights(setup.Mesh, -half, tolerance);
            for (int k = 0; ; k++)
            {
                SquashMeasures.Deformation(body, setup.Mesh, out double x, out double v);
                amplitude[k] = SquashMeasures.Amplitude(x, v, targets.Omega, Size);
                height[k] = SquashMeasures.Height(body.Positions, top, bottom);
                if (k == releaseFrames)
                    break;
                body.Step(Dt, float3.zero, ReadOnlySpan<ColliderShape>.Empty);
            }
            bool diverged = body.Resets > 0 || !Finite(body);
            double recovery = SquashMeasures.RecoveryTime(amplitude, Dt, RecoveryThreshold);
            bool recovered = !double.IsPositiveInfinity(recovery);
            if (!recovered)
                recovery = ReleaseTime;
            double overshoot = SquashMeasures.Overshoot(height, Size, Stretch * Size);
            double volumeErr = diverged ? double.NaN : Math.Abs(volume / (targets.VolumeRatio * restVolume) - 1);
            double recoveryErr = diverged ? double.NaN : Relative(recovery, targets.RecoveryTime);
            double overshootErr = diverged ? double.NaN : Relative(overshoot, targets.Overshoot);
            return new[]
            {
                new Metric(Error, Worst(diverged, volumeErr, recoveryErr, overshootErr), MetricUnit.Fraction),
                new Metric(VolumeError, volumeErr, MetricUnit.Fraction),
                new Metric(RecoveryError, recoveryErr, MetricUnit.Fraction),
                new Metric(OvershootError, overshootErr, MetricUnit.Fraction),
                new Metric(Recovery, diverged ? double.NaN : recovery, MetricUnit.Second),
                new Metric(OvershootMetric, diverged ? double.NaN : overshoot, MetricUnit.Dimensionless),
                new Metric(Recovered, recovered ? 1 : 0, MetricUnit.Flag),
                new Metric(Resets, body.Resets, MetricUnit.Count),
                new Metric(Particles, body.ParticleCount, MetricUnit.Count),
            };
        }
    }
}
