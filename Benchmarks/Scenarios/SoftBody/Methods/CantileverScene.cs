using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// A square rubber beam clamped at x = 0 (its end face pinned) sagging under gravity: static tip deflection under a
    /// small load (against Euler–Bernoulli and the float64 FEM reference) and a large one (against the float64 reference),
    /// and the first bending frequency (against the reference).
    /// </summary>
    public sealed class CantileverScene : StudyScene
    {
        /// <summary>Beam length (m).</summary>
        public const float Length = 0.4f;
        /// <summary>Side of the square cross-section (m).</summary>
        public const float Thickness = 0.05f;
        /// <summary>Cells across the thickness of the default resolution.</summary>
        public const int DefaultCellsAcross = 2;
        /// <summary>Cells along the length and across at the default resolution.</summary>
        public static readonly int3 Cells = CellsAt(DefaultCellsAcross);
        /// <summary>Small load: gravity times this (tip deflection ≈ 2 % of the length).</summary>
        public const float SmallLoad = 0.05f;
        /// <summary>Large load: gravity times this (tip deflection ≈ 20 % of the length).</summary>
        public const float LargeLoad = 0.5f;
        /// <summary>
        /// Static runs: this long (s) with the material's ζ = 0.2 (which the explicit integrators tolerate at their substeps,
        /// unlike ζ = 1: stiffness-proportional damping shortens the stable step in proportion to ζ), the tip averaged over
        /// the last period of the reference's first mode. The first mode decays as e^(−ζω₁t): by 5 s to ~1e-4 of the sag.
        /// </summary>
        public const float StaticTime = 5f;
        /// <summary>Damping ratio of the static runs.</summary>
        public const float StaticDampingRatio = 0.2f;
        /// <summary>Free oscillation for the frequency (s).</summary>
        public const float OscillationTime = 3f;

        /// <summary>Metric: small-load tip deflection over the reference, minus 1.</summary>
        public const string SmallTip = "small tip err";
        /// <summary>Metric: small-load tip deflection over Euler–Bernoulli, minus 1 (signed).</summary>
        public const string SmallTipEb = "tip/EB-1";
        /// <summary>Metric: large-load tip deflection error against the reference.</summary>
        public const string LargeTip = "large tip err";
        /// <summary>Metric: first-frequency error against the reference.</summary>
        public const string Frequency = "f1 err";
        /// <summary>Metric: 1 when the free run oscillated enough to measure the frequency (two upward crossings), else 0 (then 'err' is the worst static error).</summary>
        public const string FrequencyMeasured = "f1 measured";


        /// <summary>Soft rubber (E 1 MPa, ν 0.45, 1100 kg/m³, ζ 0.2).</summary>
        public static ElasticMaterial Material => ElasticMaterial.Rubber;

        public override string Name => "MethodStudyCantilever";

        public override float CellSize => Length / Cells.x;

        public override MethodBodySetup Setup => SetupAt(0);

        /// <summary>Cells along x, y, z with <paramref name="across"/> cells across the thickness: (8n, n, n), cubic cells.</summary>
        public static int3 CellsAt(int across) => new int3(8 * across, across, across);

        /// <summary>The beam with <paramref name="resolution"/> cells across (0 = <see cref="DefaultCellsAcross"/>), built once.</summary>
        public override MethodBodySetup SetupAt(int resolution) =>
            CachedSetup(resolution > 0 ? resolution : DefaultCellsAcross, n => CreateSetup(CellsAt(n)));

        public override float CellSizeAt(int resolution) => Thickness / (resolution > 0 ? resolution : DefaultCellsAcross);

        /// <summary>The beam at a resolution (cells along x, y, z).</summary>
        public static MethodBodySetup CreateSetup(int3 cells)
        {
            TetrahedralMesh mesh = BoxTetrahedra.Create(new float3(Length, Thickness, Thickness), cells, new float3(0.5f * Length, 0f, 0f));
            return new MethodBodySetup
            {
                Mesh = mesh,
                Material = Material,
                Pinned = StudyBox.NodesAt(mesh, 0, 0f, 1e-5f),
                CalibrationLength = Length * Length / Thickness,
            };
        }

        public override SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "What each method costs to match a clamped rubber beam's static tip sag under a small and a large load and its first bending frequency.",
            Body = $"A {Length} m beam of {Thickness}×{Thickness} m section, {Cells.x}×{Cells.y}×{Cells.z} cells of 6 tetrahedra " +
                   $"({(Cells.x + 1) * (Cells.y + 1) * (Cells.z + 1)} particles; rows swept in resolution: 8n×n×n cells, n = cells across in the label), its x = 0 face pinned.",
            Material = $"Soft rubber ({MaterialText(Material)}); ζ = {StaticDampingRatio} for the static runs, 0.01 for the free run, both at the reference's first mode (FEM's Rayleigh β = 2ζ/ω₁). " +
                       "Shape matching's frequency comes from ShapeMatchingCalibration with L = L_beam²/h.",
            Load = $"Gravity × {SmallLoad} and × {LargeLoad}, {StaticTime} s each, the tip averaged over the last period of the reference's first mode; " +
                   $"then a free oscillation about the sag under {SmallLoad} g for {OscillationTime} s.",
            Reference = "Float64 FEM (Q2 hexahedra, Neo-Hookean, Newton statics, inverse iteration for the frequency) at " +
                        $"{string.Join(", ", CantileverTargets.ReferenceResolutions)} elements across, Richardson-extrapolated; Euler–Bernoulli qL⁴/(8EI) for '{SmallTipEb}'.",
            Metric = $"'{Error}' = the worst of '{SmallTip}', '{LargeTip}' (geometrically nonlinear) and '{Frequency}' (first bending frequency from the tip's upward crossings), " +
                     $"each relative to the reference; '{SmallTipEb}' is signed; 'tip small' (m) and 'f1' (Hz) are the raw values.",
            Notes = new[]
            {
                $"'{FrequencyMeasured}' = 0: the free run did not oscillate through two upward crossings (implicit Euler's numerical damping), so '{Error}' is the worse static error.",
                "A reset ends the run it happens in: its value is NaN.",
            },
            Details = "choosing-a-method.md#cantilever-methodstudycantilever",
        };

        public override object Reference() => CantileverTargets.Get(Setup);

        public override Type ReferenceType => typeof(CantileverTargets);

        public override void UseReference(object values) => CantileverTargets.Remember(Material, (CantileverTargets)values);

        /// <summary>
        /// Explicit FEM diverges on this beam at 128 and 256 substeps, at ~8 s a point: the default run leaves it to --full and to the
        /// stability suite (its largest stable step against the explicit limit).
        /// </summary>
        public override int[] StandardKnobs(MethodVariant variant) => IsExplicitFem(variant) ? new int[0] : variant.StandardKnobs;

        /// <summary>
        /// The default run keeps the sweeps behind the scene's findings — mass-spring implicit Euler to 5 cells across (where it
        /// comes within 5 %), quadratic co-rotational implicit FEM to 2 (where it comes within 5 %) — and runs the other FEM
        /// variants at 1 cell across only: linear elements lock at any resolution the default run can afford.
        /// </summary>
        public override int StandardMaxResolution(MethodVariant variant) =>
            variant.Family.StartsWith("FEM", StringComparison.Ordinal) && variant.Family != QuadraticCoRotational ? 1 : variant.StandardMaxResolution;

        static readonly string QuadraticCoRotational =
            FemMethodBody.FamilyName(FemMaterialModel.CoRotational, FemIntegrator.ImplicitEuler, FemElementOrder.Quadratic);

        public override IReadOnlyList<Metric> Measure(MethodBodySetup setup, Func<MethodBodySetup, IMethodBody> build)
        {
            bool[] tipFace = StudyBox.NodesAt(setup.Mesh, 0, Length, 1e-5f);
            ElasticMaterial m = Material;
            CantileverTargets t = CantileverTargets.Get(setup);
            int average = Math.Max(1, (int)Math.Round(1.0 / (t.Frequency * Dt)));
            // ζ refers to the first bending mode (FEM's Rayleigh damping at its own estimate, the shear mode, would leave it at ~0.01).
            float firstMode = (float)(2.0 * Math.PI * t.Frequency);
            IMethodBody staticBody = build(setup.With(new ElasticMaterial(m.YoungsModulus, m.PoissonRatio, m.Density, StaticDampingRatio), firstMode));
            double small = StaticTip(staticBody, tipFace, SmallLoad, average, out int r1);
            double large = StaticTip(staticBody, tipFace, LargeLoad, average, out int r2);
            IMethodBody free = build(setup.With(new ElasticMaterial(m.YoungsModulus, m.PoissonRatio, m.Density, 0.01f), firstMode));
            double f = FirstFrequency(free, tipFace, out int r3);
            double smallErr = Relative(small, t.SmallTip), largeErr = Relative(large, t.LargeTip), fErr = Relative(f, t.Frequency);
            return new[]
            {
                // A frequency that could not be measured without a reset (implicit Euler's numerical damping can remove the
                // oscillation of a stiff coarse beam before two crossings) is left out of 'err' and flagged; a reset is divergence.
                new Metric(Error, Worst(double.IsNaN(small) || double.IsNaN(large) || r3 > 0, smallErr, largeErr, fErr), MetricUnit.Fraction),
                new Metric(SmallTip, smallErr, MetricUnit.Fraction),
                new Metric(SmallTipEb, small / t.SmallTipEulerBernoulli - 1.0, MetricUnit.Fraction),
                new Metric(LargeTip, largeErr, MetricUnit.Fraction),
                new Metric(Frequency, fErr, MetricUnit.Fraction),
                new Metric(FrequencyMeasured, double.IsNaN(f) ? 0 : 1, MetricUnit.Flag),
                new Metric("tip small", small, MetricUnit.Metre),
                new Metric("f1", f, MetricUnit.Hertz),
                new Metric(Resets, r1 + r2 + r3, MetricUnit.Count),
                new Metric(Particles, staticBody.ParticleCount, MetricUnit.Count),
            };
        }

        /// <summary>Downward static tip deflection (m) under <paramref name="load"/> g, the mean of the last <paramref name="average"/> frames; NaN when the body diverged or was reset (a reset ends the run).</summary>
        static double StaticTip(IMethodBody body, bool[] tipFace, float load, int average, out int resets)
        {
            body.Place();
            float y0 = Mean(body, tipFace).y;
            var g = new float3(0f, -9.81f * load, 0f);
            int frames = (int)Math.Round(StaticTime / Dt);
            double sum = 0;
            for (int k = 0; k < frames && body.Resets == 0; k++)
            {
                body.Step(Dt, g, ReadOnlySpan<ColliderShape>.Empty);
                if (k >= frames - average)
                    sum += y0 - Mean(body, tipFace).y;
            }
            resets = body.Resets;
            return resets == 0 && Finite(body) ? sum / average : double.NaN;
        }

        /// <summary>First frequency (Hz): upward zero crossings of the tip's y about the mid-range of its oscillation under the small load; NaN after a reset (which ends the run).</summary>
        static double FirstFrequency(IMethodBody body, bool[] tipFace, out int resets)
        {
            body.Place();
            var g = new float3(0f, -9.81f * SmallLoad, 0f);
            int frames = (int)Math.Round(OscillationTime / Dt);
            var y = new double[frames + 1];
            y[0] = Mean(body, tipFace).y;
            for (int k = 1; k <= frames && body.Resets == 0; k++)
            {
                body.Step(Dt, g, ReadOnlySpan<ColliderShape>.Empty);
                y[k] = Mean(body, tipFace).y;
            }
            resets = body.Resets;
            if (resets > 0 || !Finite(body))
                return double.NaN;
            return OscillationFrequency(y, Dt);
        }

        /// <summary>Frequency (Hz) of a sampled oscillation from its upward crossings of its mid-range (linearly interpolated); NaN with fewer than two.</summary>
        public static double OscillationFrequency(double[] y, double dt)
        {
            double lo = double.PositiveInfinity, hi = double.NegativeInfinity;
            foreach (double v in y)
            {
                lo = Math.Min(lo, v);
                hi = Math.Max(hi, v);
            }
            double mid = 0.5 * (lo + hi);
            double first = double.NaN, last = double.NaN;
            int count = 0;
            for (int k = 1; k < y.Length; k++)
                if (y[k - 1] < mid && y[k] >= mid)
                {
                    double t = (k - 1 + (mid - y[k - 1]) / (y[k] - y[k - 1])) * dt;
                    if (count == 0)
                        first = t;
                    last = t;
                    count++;
                }
            return count >= 2 ? (count - 1) / (last - first) : double.NaN;
        }
    }
}
