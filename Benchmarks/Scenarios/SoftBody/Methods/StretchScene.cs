using System;
using System.Collections.Generic;
using System.Globalization;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// The force–extension curve: a square rubber bar hanging from its clamped top face, pulled along its axis by its own
    /// weight at three load levels (small: ~1 % strain at the clamp, medium, large: stretch ~1.5 at the clamp), each
    /// reached by a smooth ramp from the previous one and held until static. The extension (the mean displacement of the
    /// free end face along the bar) at each load is compared with the float64 Neo-Hookean FEM reference of the same
    /// clamped bar (<see cref="StretchTargets"/>). The load is the bar's weight ρ g V, so the curve of extension
    /// against g is the force–extension curve; since the nominal stress at a section is the weight below it, ρ g (L − X),
    /// it also probes each method's stress–stretch law up to the clamp's stress ρ g L.
    /// </summary>
    public sealed class StretchScene : StudyScene
    {
        /// <summary>Bar length (m), along −y from the clamp at y = 0.</summary>
        public const float Length = 0.4f;
        /// <summary>Side of the square cross-section (m).</summary>
        public const float Thickness = 0.05f;
        /// <summary>Cells across the section at the default resolution.</summary>
        public const int DefaultCellsAcross = 2;
        /// <summary>Cells along x, y, z at the default resolution.</summary>
        public static readonly int3 Cells = CellsAt(DefaultCellsAcross);
        /// <summary>Standard gravity (m/s²); the loads are multiples of it.</summary>
        public const double Gravity = 9.81;
        /// <summary>
        /// Load levels, multiples of <see cref="Gravity"/> along the bar: nominal stress at the clamp ρ g L = 8.6 kPa,
        /// 129 kPa and 345 kPa for rubber (E = 1 MPa), i.e. stretch at the clamp λ ≈ 1.009, 1.15 and 1.48 (uniaxial
        /// Neo-Hookean): a linear, a mildly and a strongly nonlinear point of the curve.
        /// </summary>
        public static readonly double[] Loads = { 2, 30, 80 };
        /// <summary>Names of the load levels, in <see cref="Loads"/> order.</summary>
        public static readonly string[] LevelNames = { "small", "medium", "large" };
        /// <summary>
        /// Each level is reached from the previous one by a raised-cosine ramp of this length (s), five periods of the bar's
        /// first axial mode (√(E/ρ)/(4L) ≈ 19 Hz), so the ramp leaves an oscillation of a small fraction of the step in
        /// extension (the step response of a smooth ramp of length T falls as 1/(ωT)² and faster).
        /// </summary>
        public const float RampTime = 0.25f;
        /// <summary>
        /// Then held this long (s) before the extension is read: FEM's and mass-spring's calibrated damping (ζ = 0.2 at
        /// ω_ref = π√(μ/ρ)/L_box ≈ 139 rad/s, stiffness-proportional) gives the axial mode ζ ≈ 0.17 at ≈ 120 rad/s, a decay
        /// rate ≈ 20 /s: e^(−20·0.5) ≈ 5e-5 of the ramp's residual by the end. Checked against 2 s holds: the extensions agree
        /// within 1 % for every variant within 100 % of the reference, except MS Verlet at 256 substeps at the small load (−1.2 %:
        /// its position update a·h² is a few float32 ulps of the 0.4 m coordinates) and Neo-Hookean XPBD's small-load jitter (±1–4 %).
        /// </summary>
        public const float HoldTime = 0.5f;
        /// <summary>The extension is averaged over the last this long (s) of each hold (about two periods of the axial mode).</summary>
        public const float AverageTime = 0.1f;
        /// <summary>
        /// Damping ratio of the runs: the material's own (rubber's 0.2), as in the cantilever's static runs. The explicit
        /// mass-spring integrators run at 256 substeps; explicit FEM is reset at its 128 and 256 (stiffness-proportional damping
        /// shortens the stable step in proportion to ζ: it was reset at ζ = 0.05 too and ran at 256 substeps only at ζ = 0.02,
        /// where the XPBD methods' static extensions change with ζ and the small load is not settled to 1 % within the hold).
        /// </summary>
        public const float StaticDampingRatio = 0.2f;

        /// <summary>Frames of one level's ramp.</summary>
        public static int RampFrames => (int)Math.Round(RampTime / Dt);
        /// <summary>Frames of one level's ramp and hold.</summary>
        public static int LevelFrames => RampFrames + (int)Math.Round(HoldTime / Dt);
        /// <summary>Frames averaged at the end of each level.</summary>
        public static int AverageFrames => Math.Max(1, (int)Math.Round(AverageTime / Dt));
        /// <summary>Frames of the whole measurement (every level in turn).</summary>
        public static int TotalFrames => LevelFrames * Loads.Length;

        /// <summary>Metric: the extension's error against the reference at a level, signed (δ/δ_ref − 1): + = too soft.</summary>
        public static string LevelError(int level) => $"{LevelNames[level]} δ/ref-1";
        /// <summary>Metric: the extension at a level (m).</summary>
        public static string LevelExtension(int level) => $"δ {LevelNames[level]}";


        /// <summary>Soft rubber (E 1 MPa, ν 0.45, 1100 kg/m³, ζ 0.2).</summary>
        public static ElasticMaterial Material => ElasticMaterial.Rubber;

        public override string Name => "MethodStudyStretch";

        public override float CellSize => Thickness / DefaultCellsAcross;

        public override MethodBodySetup Setup => SetupAt(0);

        /// <summary>Cells along x, y, z with <paramref name="across"/> cells across the section: (n, 8n, n), cubic cells, the bar along y.</summary>
        public static int3 CellsAt(int across) => new int3(across, 8 * across, across);

        /// <summary>The bar with <paramref name="resolution"/> cells across (0 = <see cref="DefaultCellsAcross"/>), built once.</summary>
        public override MethodBodySetup SetupAt(int resolution) =>
            CachedSetup(resolution > 0 ? resolution : DefaultCellsAcross, n => CreateSetup(CellsAt(n)));

        public override float CellSizeAt(int resolution) => Thickness / (resolution > 0 ? resolution : DefaultCellsAcross);

        /// <summary>
        /// The bar at a resolution (cells along x, y, z): from y = 0 (its top face, pinned) down to y = −L. The shape-matching
        /// calibration length is the cantilever's L²/h: it is the same body, and the calibration belongs to the body, not to the load.
        /// </summary>
        public static MethodBodySetup CreateSetup(int3 cells)
        {
            TetrahedralMesh mesh = BoxTetrahedra.Create(new float3(Thickness, Length, Thickness), cells, new float3(0f, -0.5f * Length, 0f));
            return new MethodBodySetup
            {
                Mesh = mesh,
                Material = Material,
                Pinned = StudyBox.NodesAt(mesh, 1, 0f, 1e-5f),
                CalibrationLength = Length * Length / Thickness,
            };
        }

        /// <summary>Acceleration along −y (m/s²) during frame <paramref name="frame"/> of the measurement (evaluated at the frame's end).</summary>
        public static double LoadAt(int frame)
        {
            int level = Math.Min(frame / LevelFrames, Loads.Length - 1);
            int inLevel = frame - level * LevelFrames;
            double from = level > 0 ? Loads[level - 1] : 0, to = Loads[level];
            double s = Math.Min(1.0, (inLevel + 1) / (double)RampFrames);
            return Gravity * (from + (to - from) * 0.5 * (1 - Math.Cos(Math.PI * s)));
        }

        /// <summary>The timed frames follow the measurement's load history, placed again at its end.</summary>
        public override void TimedFrame(IMethodBody body, int frame)
        {
            int k = frame % TotalFrames;
            if (k == 0)
                body.Place();
            body.Step(Dt, new float3(0f, -(float)LoadAt(k), 0f), ReadOnlySpan<ColliderShape>.Empty);
        }

        public override SuiteDefinition Definition
        {
            get
            {
                StretchTargets t = StretchTargets.Get(Material);
                double weight = Material.Density * Gravity * Length * Thickness * Thickness;
                return new SuiteDefinition
                {
                    Purpose = "What each method costs to follow a hanging rubber bar's force–extension curve, from a linear to a strongly nonlinear stretch.",
                    Body = $"A {Length} m bar of {Thickness}×{Thickness} m section, {Cells.x}×{Cells.y}×{Cells.z} cells of 6 tetrahedra " +
                           $"({(Cells.x + 1) * (Cells.y + 1) * (Cells.z + 1)} particles; rows swept in resolution: n×8n×n cells, n = cells across in the label), its top face pinned.",
                    Material = $"Soft rubber ({MaterialText(Material)}), ζ = {StaticDampingRatio}. " +
                               "Shape matching's frequency comes from ShapeMatchingCalibration with L = L_bar²/h, as for the cantilever (the same body).",
                    Load = $"Its own weight along its axis at {string.Join(", ", Array.ConvertAll(Loads, l => $"{l} g"))} (g = {Gravity} m/s²; ρgV = " +
                           $"{string.Join(", ", Array.ConvertAll(Loads, l => Fmt(weight * l)))} N), each reached by a {RampTime} s raised-cosine ramp and held {HoldTime} s.",
                    Reference = "Float64 FEM of the same clamped bar (Q2 hexahedra, compressible Neo-Hookean, Newton statics) at " +
                                $"{string.Join(", ", t.Resolutions)} elements across, extrapolated per load: δ = " +
                                $"{string.Join(", ", Array.ConvertAll(t.Extensions, v => Fmt(1e3 * v)))} mm.",
                    Metric = $"'{Error}' = the worst |δ/δ_ref − 1| of the three loads; '{LevelError(0)}', … signed (+ = too soft); '{LevelExtension(0)}', … the raw δ (m): " +
                             $"the free end face's mean displacement along the bar, averaged over the last {AverageTime} s of each hold.",
                    Notes = new[]
                    {
                        "A reset ends the run: its level and the later ones are NaN.",
                    },
                    Details = "choosing-a-method.md#stretch-the-forceextension-curve-methodstudystretch",
                };
            }
        }

        static string Fmt(double v) => v.ToString(Math.Abs(v) >= 100 ? "0.0" : "0.000", CultureInfo.InvariantCulture);

        public override object Reference() => StretchTargets.Get(Material);

        public override Type ReferenceType => typeof(StretchTargets);

        public override void UseReference(object values) => StretchTargets.Remember(Material, (StretchTargets)values);

        public override IReadOnlyList<Metric> Measure(MethodBodySetup setup, Func<MethodBodySetup, IMethodBody> build) =>
            Measure(setup, build, StretchTargets.Get(setup.Material));

        /// <summary><see cref="Measure(MethodBodySetup, Func{MethodBodySetup, IMethodBody})"/> against given targets (e.g. a cheaper reference in tests).</summary>
        public IReadOnlyList<Metric> Measure(MethodBodySetup setup, Func<MethodBodySetup, IMethodBody> build, StretchTargets targets)
        {
            ElasticMaterial m = setup.Material;
            IMethodBody body = build(setup.With(new ElasticMaterial(m.YoungsModulus, m.PoissonRatio, m.Density, StaticDampingRatio)));
            double[] extensions = Extensions(body, StudyBox.NodesAt(setup.Mesh, 1, -Length, 1e-5f), out int resets);
            var errors = new double[Loads.Length];
            bool diverged = false;
            for (int k = 0; k < Loads.Length; k++)
            {
                errors[k] = extensions[k] / targets.Extensions[k] - 1.0;
                diverged |= double.IsNaN(extensions[k]);
            }
            var metrics = new List<Metric> { new Metric(Error, Worst(diverged, Array.ConvertAll(errors, Math.Abs)), MetricUnit.Fraction) };
            for (int k = 0; k < Loads.Length; k++)
                metrics.Add(new Metric(LevelError(k), errors[k], MetricUnit.Fraction));
            for (int k = 0; k < Loads.Length; k++)
                metrics.Add(new Metric(LevelExtension(k), extensions[k], MetricUnit.Metre));
            metrics.Add(new Metric(Resets, resets, MetricUnit.Count));
            metrics.Add(new Metric(Particles, body.ParticleCount, MetricUnit.Count));
            return metrics;
        }

        /// <summary>
        /// Runs the load history on <paramref name="body"/> from rest and returns the extension (m) at each level, the mean of
        /// the last <see cref="AverageFrames"/> frames of its hold; NaN for a level at whose end the body had been reset or was
        /// not finite. The run stops at the first reset (every later level is NaN: the guard put the body back at rest).
        /// </summary>
        public static double[] Extensions(IMethodBody body, bool[] endFace, out int resets)
        {
            body.Place();
            double y0 = Mean(body, endFace).y;
            var result = new double[Loads.Length];
            for (int k = 0; k < result.Length; k++)
                result[k] = double.NaN;
            int level = 0;
            double sum = 0;
            for (int k = 0; k < TotalFrames && body.Resets == 0; k++)
            {
                body.Step(Dt, new float3(0f, -(float)LoadAt(k), 0f), ReadOnlySpan<ColliderShape>.Empty);
                int inLevel = k - level * LevelFrames;
                if (inLevel >= LevelFrames - AverageFrames)
                    sum += y0 - Mean(body, endFace).y;
                if (inLevel == LevelFrames - 1)
                {
                    if (body.Resets > 0 || !Finite(body))
                        break;
                    result[level++] = sum / AverageFrames;
                    sum = 0;
                }
            }
            resets = body.Resets;
            return result;
        }
    }
}
