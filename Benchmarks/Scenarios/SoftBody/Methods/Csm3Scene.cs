using System;
using System.Collections.Generic;
using System.Globalization;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// The Turek–Hron CSM3 beam (<see cref="Csm3Reference"/>) made 3-D: 0.35 × 0.02 × 0.02 m, E = 1.4 MPa, ν = 0.4,
    /// ρ = 1000 kg/m³, no damping, its x = 0 face pinned, released from rest under g = 2 m/s² (−y). It swings about
    /// its sag (~20 % of its length at the bottom) for 3 s; point A (the tip face's mid-point) is measured as
    /// u_y mean ± amplitude at a frequency against the float64 reference of the same 3-D beam
    /// (<see cref="Csm3Targets"/>, <see cref="Csm3SolidReference"/>).
    /// </summary>
    public sealed class Csm3Scene : StudyScene
    {
        /// <summary>Beam length (m).</summary>
        public const float Length = (float)Csm3Reference.Length;
        /// <summary>Beam height (m, along y, the bending plane).</summary>
        public const float Height = (float)Csm3Reference.Height;
        /// <summary>Beam width (m, along z): the section is square.</summary>
        public const float Width = (float)Csm3SolidReference.Width;
        /// <summary>Cells across the height and width at the default resolution.</summary>
        public const int DefaultCellsAcross = 2;
        /// <summary>Cells along x, y, z at the default resolution (35 × 2 × 2).</summary>
        public static readonly int3 Cells = CellsAt(DefaultCellsAcross);
        /// <summary>Gravity of the benchmark (m/s², along −y).</summary>
        public const float Gravity = (float)Csm3Reference.Gravity;
        /// <summary>Frames of one measurement (1/60 s each): 3 s, two full periods of the ~1 Hz swing after the first crossing.</summary>
        public const int Frames = 180;
        /// <summary>Simulated time of a measurement (s).</summary>
        public const double Duration = Frames * (double)Dt;

        /// <summary>Metric: relative error of the tip's u_y mean.</summary>
        public const string MeanError = "uy mean err";
        /// <summary>Metric: relative error of the tip's u_y amplitude.</summary>
        public const string AmplitudeError = "uy amp err";
        /// <summary>Metric: relative error of the tip's frequency.</summary>
        public const string FrequencyError = "f err";
        /// <summary>Metric: the tip's u_y mean (m).</summary>
        public const string MeanValue = "uy mean";
        /// <summary>Metric: the tip's u_y amplitude (m).</summary>
        public const string AmplitudeValue = "uy amp";
        /// <summary>Metric: the tip's frequency (Hz).</summary>
        public const string FrequencyValue = "f";
        /// <summary>
        /// Metric: the largest sideways (z) excursion of the tip (m). The square section makes bending in y and in z
        /// degenerate; the continuum stays planar (the reference under an extra 10⁻⁴ g along z follows with z/u_y = 10⁻⁴
        /// throughout the 3 s, no growth), but a tetrahedral mesh that is not mirror-symmetric in z couples the two, and
        /// the swing's energy can beat into sideways bending; the cycle statistics then see longer, smaller cycles.
        /// </summary>
        public const string SidewaysValue = "uz max";


        /// <summary>The benchmark's material, undamped (E 1.4 MPa, ν 0.4, 1000 kg/m³, ζ 0).</summary>
        public static ElasticMaterial Material => new ElasticMaterial((float)Csm3Reference.YoungModulus, (float)Csm3Reference.PoissonRatio,
            (float)Csm3Reference.Density, 0f);

        public override string Name => "MethodStudyCsm3";

        public override float CellSize => CellSizeAt(0);

        public override MethodBodySetup Setup => SetupAt(0);

        protected override float3 TimedGravity => new float3(0f, -Gravity, 0f);

        /// <summary>
        /// The sweeps stop at 3 cells across (53 × 3 × 3 cells, 864 particles): the beam has 17.5n × n × n cells, so n = 4 is
        /// 1775 particles, where co-rotational implicit FEM's converged CG on this slender beam took ~3 min for one
        /// measurement (n = 3: ~1 min) and would alone exceed the suite's time budget.
        /// </summary>
        public override int MaxResolution => 3;

        /// <summary>Cells along x, y, z with <paramref name="across"/> cells across the height and width: (17.5n rounded half up, n, n), near-cubic cells.</summary>
        public static int3 CellsAt(int across) =>
            new int3((int)Math.Round(Length / (double)Height * across, MidpointRounding.AwayFromZero), across, across);

        /// <summary>The beam with <paramref name="resolution"/> cells across (0 = <see cref="DefaultCellsAcross"/>), built once.</summary>
        public override MethodBodySetup SetupAt(int resolution) =>
            CachedSetup(resolution > 0 ? resolution : DefaultCellsAcross, n => CreateSetup(CellsAt(n)));

        public override float CellSizeAt(int resolution) => Height / (resolution > 0 ? resolution : DefaultCellsAcross);

        /// <summary>The beam at a resolution (cells along x, y, z), its x = 0 face pinned.</summary>
        public static MethodBodySetup CreateSetup(int3 cells)
        {
            TetrahedralMesh mesh = BoxTetrahedra.Create(new float3(Length, Height, Width), cells, new float3(0.5f * Length, 0f, 0f));
            return new MethodBodySetup
            {
                Mesh = mesh,
                Material = Material,
                Pinned = StudyBox.NodesAt(mesh, 0, 0f, 1e-5f),
                CalibrationLength = Length * Length / Height,
            };
        }

        public override SuiteDefinition Definition
        {
            get
            {
                Csm3Targets t = Csm3Targets.Get(Material);
                return new SuiteDefinition
                {
                    Purpose = "What each method costs to reproduce the undamped swing of the Turek–Hron CSM3 beam made 3-D: the mean, amplitude and frequency of its tip.",
                    Body = $"A {Length} m beam of {Height}×{Width} m square section, {Cells.x}×{Cells.y}×{Cells.z} cells of 6 tetrahedra " +
                           $"({(Cells.x + 1) * (Cells.y + 1) * (Cells.z + 1)} particles; rows swept in resolution: 17.5n×n×n cells, up to n = {MaxResolution}), its x = 0 face pinned.",
                    Material = $"{MaterialText(Material)}, no damping (ζ = {Number(Material.DampingRatio)}). " +
                               "Shape matching's frequency comes from ShapeMatchingCalibration with L = L_beam²/h.",
                    Load = $"Released from rest under g = {Gravity} m/s² (−y), followed for {Duration:0.#} s ({Frames} frames of 1/60 s).",
                    Reference = "Float64 FEM of the same 3-D beam (Q2 hexahedra, St Venant–Kirchhoff, Newmark), extrapolated in mesh and step, measured the same way: " +
                                $"u_y = {Number(t.UyMean * 1e3)} ± {Number(t.UyAmplitude * 1e3)} mm at {t.UyFrequency.ToString("0.0000", CultureInfo.InvariantCulture)} Hz.",
                    Metric = $"'{Error}' = the worst of '{MeanError}', '{AmplitudeError}' and '{FrequencyError}': point A's (the tip face's mean) u_y mean, amplitude " +
                             "and frequency, cycle by cycle, relative to the reference; a tip with no complete cycle has a frequency error of 100 %.",
                    Notes = new[]
                    {
                        $"'{SidewaysValue}': the tip's largest sideways (z) excursion. The continuum stays planar, but a tetrahedral mesh that is not mirror-symmetric " +
                        "in z couples y and z bending, and the swing can beat into z (its y cycles then come out longer and smaller).",
                        "A reset ends the run: every value is then NaN.",
                    },
                    Details = "choosing-a-method.md#the-csm3-beam-in-3-d-methodstudycsm3",
                };
            }
        }

        public override IReadOnlyList<Metric> Measure(MethodBodySetup setup, Func<MethodBodySetup, IMethodBody> build) =>
            Measure(setup, build, Csm3Targets.Get(setup.Material));

        /// <summary><see cref="Measure(MethodBodySetup, Func{MethodBodySetup, IMethodBody})"/> against given targets (only their
        /// <see cref="Csm3Targets.UyMean"/>, <see cref="Csm3Targets.UyAmplitude"/> and <see cref="Csm3Targets.UyFrequency"/> are read).</summary>
        public override object Reference() => Csm3Targets.Get(Material);

        public override Type ReferenceType => typeof(Csm3Targets);

        public override void UseReference(object values) => Csm3Targets.Remember(Material, (Csm3Targets)values);

        /// <summary>Explicit FEM diverges on this beam at 128 substeps and reaches 64 % at 256: the default run leaves it to --full.</summary>
        public override int[] StandardKnobs(MethodVariant variant) => IsExplicitFem(variant) ? new int[0] : variant.StandardKnobs;

        /// <summary>The default run runs FEM at 1 cell across only: at 2 each point costs 10–25 s of 1/60 s steps on this beam.</summary>
        public override int StandardMaxResolution(MethodVariant variant) =>
            variant.Family.StartsWith("FEM", StringComparison.Ordinal) ? 1 : variant.StandardMaxResolution;

        /// <summary>
        /// The full run adds 8 and 64 substeps for quadratic co-rotational FEM at 1 and 2 cells across: the undamped swing's
        /// amplitude is lost to implicit Euler's first-order numerical damping (24 % at 2 substeps), which falls with the substep.
        /// </summary>
        public override int[] FullKnobs(MethodVariant variant, int resolution) =>
            variant.Family == FemMethodBody.FamilyName(FemMaterialModel.CoRotational, FemIntegrator.ImplicitEuler, FemElementOrder.Quadratic)
            && resolution <= 2
                ? new[] { 1, 2, 8, 64 }
                : variant.Knobs;

        public IReadOnlyList<Metric> Measure(MethodBodySetup setup, Func<MethodBodySetup, IMethodBody> build, Csm3Targets t)
        {
            bool[] tipFace = StudyBox.NodesAt(setup.Mesh, 0, Length, 1e-5f);
            IMethodBody body = build(setup);
            (double mean, double amplitude, double frequency, double sideways, int resets) = Swing(body, tipFace);
            bool diverged = resets > 0 || double.IsNaN(mean);
            double meanErr = diverged ? double.NaN : Relative(mean, t.UyMean);
            double ampErr = diverged ? double.NaN : Relative(amplitude, t.UyAmplitude);
            double fErr = diverged ? double.NaN : double.IsNaN(frequency) ? 1.0 : Relative(frequency, t.UyFrequency);
            return new[]
            {
                new Metric(Error, Worst(diverged, meanErr, ampErr, fErr), MetricUnit.Fraction),
                new Metric(MeanError, meanErr, MetricUnit.Fraction),
                new Metric(AmplitudeError, ampErr, MetricUnit.Fraction),
                new Metric(FrequencyError, fErr, MetricUnit.Fraction),
                new Metric(MeanValue, diverged ? double.NaN : mean, MetricUnit.Metre),
                new Metric(AmplitudeValue, diverged ? double.NaN : amplitude, MetricUnit.Metre),
                new Metric(FrequencyValue, diverged ? double.NaN : frequency, MetricUnit.Hertz),
                new Metric(SidewaysValue, diverged ? double.NaN : sideways, MetricUnit.Metre),
                new Metric(Resets, resets, MetricUnit.Count),
                new Metric(Particles, body.ParticleCount, MetricUnit.Count),
            };
        }

        /// <summary>
        /// Releases the body from rest and returns the tip's u_y mean (m), amplitude (m) and frequency (Hz) by
        /// <see cref="OscillationStatistics"/> (NaN frequency and whole-record extremes when no cycle completes), and its
        /// largest |u_z| (m) and its resets; NaN mean when the body is not finite at the end or was reset (a reset ends the run).
        /// </summary>
        public static (double Mean, double Amplitude, double Frequency, double Sideways, int Resets) Swing(IMethodBody body, bool[] tipFace)
        {
            body.Place();
            (double y0, double z0) = Tip(body, tipFace);
            var g = new float3(0f, -Gravity, 0f);
            var uy = new double[Frames + 1];
            double sideways = 0;
            for (int k = 1; k <= Frames && body.Resets == 0; k++)
            {
                body.Step(Dt, g, ReadOnlySpan<ColliderShape>.Empty);
                (double y, double z) = Tip(body, tipFace);
                uy[k] = y - y0;
                sideways = Math.Max(sideways, Math.Abs(z - z0));
            }
            int resets = body.Resets;
            if (resets > 0 || !Finite(body))
                return (double.NaN, double.NaN, double.NaN, double.NaN, resets);
            (double mean, double amplitude, double frequency) = OscillationStatistics.Measure(uy, Dt);
            if (double.IsNaN(mean))
            {
                double lo = double.PositiveInfinity, hi = double.NegativeInfinity;
                foreach (double v in uy)
                {
                    lo = Math.Min(lo, v);
                    hi = Math.Max(hi, v);
                }
                (mean, amplitude) = (0.5 * (hi + lo), 0.5 * (hi - lo));
            }
            return (mean, amplitude, frequency, sideways, resets);
        }

        /// <summary>Mean y and z of the flagged nodes (m), summed in double.</summary>
        static (double Y, double Z) Tip(IMethodBody body, bool[] nodes)
        {
            double y = 0, z = 0;
            int n = 0;
            for (int i = 0; i < nodes.Length; i++)
                if (nodes[i])
                {
                    y += body.Positions[i].y;
                    z += body.Positions[i].z;
                    n++;
                }
            n = Math.Max(1, n);
            return (y / n, z / n);
        }
    }
}
