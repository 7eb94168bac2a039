using System;
using System.Collections.Generic;
using System.Globalization;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// A scene of the method study: a body setup, the frame the harness times (one 1/60 s step of the scene's motion)
    /// and the measurement that compares a method's answer with the scene's reference (never with the method itself).
    /// </summary>
    public abstract class StudyScene
    {
        /// <summary>Frame length of every scene (s).</summary>
        public const float Dt = 1f / 60f;
        /// <summary>Timed frames run from the rest shape; every this many frames the body is placed again.</summary>
        public const int FramesPerCycle = 120;
        /// <summary>Metric every scene plots and ranks: the worst of its relative errors (dimensionless).</summary>
        public const string Error = "err";
        /// <summary>Metric: NaN-guard resets during the measurement.</summary>
        public const string Resets = "resets";

        /// <summary>Suite name.</summary>
        public abstract string Name { get; }
        /// <summary>What the scene does and which reference it compares with (the report's definition; the suite adds how cost is counted).</summary>
        public abstract SuiteDefinition Definition { get; }
        /// <summary>The body every method is built from.</summary>
        public abstract MethodBodySetup Setup { get; }
        /// <summary>Edge of one cell of the box (m): shape matching's cluster size is a multiple of it.</summary>
        public abstract float CellSize { get; }

        /// <summary>Metric: particles of the body measured (the cost per step is ns per particle-step times this).</summary>
        public const string Particles = "particles";

        /// <summary>
        /// Finest resolution (cells across) this scene runs of a variant's sweep: finer ones are left out (a scene whose body
        /// is large at a given n, or whose reference is not resolved enough to judge finer meshes, caps it). Default: no cap.
        /// </summary>
        public virtual int MaxResolution => int.MaxValue;

        /// <summary>
        /// Finest resolution of a variant's sweep in the default run (0 = no cap): the variant's own cap, which a scene where a
        /// point costs minutes lowers.
        /// </summary>
        public virtual int StandardMaxResolution(MethodVariant variant) => variant.StandardMaxResolution;

        /// <summary>Knob values of a variant in the default run: all of the variant's, which a scene where they only diverge at great cost leaves out.</summary>
        public virtual int[] StandardKnobs(MethodVariant variant) => variant.StandardKnobs;

        /// <summary>Knob values of a variant at a resolution in the full run: the variant's, to which a scene may add the points its question needs.</summary>
        public virtual int[] FullKnobs(MethodVariant variant, int resolution) => variant.Knobs;

        /// <summary>True for the explicit FEM variants, which diverge on the beams at the study's substep counts.</summary>
        protected static bool IsExplicitFem(MethodVariant variant) =>
            variant.Family.StartsWith("FEM", StringComparison.Ordinal) && variant.Family.EndsWith("explicit", StringComparison.Ordinal);

        static readonly Dictionary<(Type Scene, int CellsAcross), MethodBodySetup> s_Setups = new Dictionary<(Type, int), MethodBodySetup>();

        /// <summary>The body of this scene at <paramref name="cellsAcross"/>, built by <paramref name="create"/> once per scene type and resolution.</summary>
        protected MethodBodySetup CachedSetup(int cellsAcross, Func<int, MethodBodySetup> create)
        {
            lock (s_Setups)
            {
                var key = (GetType(), cellsAcross);
                if (!s_Setups.TryGetValue(key, out MethodBodySetup setup))
                    s_Setups[key] = setup = create(cellsAcross);
                return setup;
            }
        }

        /// <summary>The body at a resolution (cells across its thinnest side); 0 = <see cref="Setup"/>.</summary>
        public virtual MethodBodySetup SetupAt(int resolution) => Setup;
        /// <summary>Cell edge (m) of <see cref="SetupAt"/>; 0 = <see cref="CellSize"/>.</summary>
        public virtual float CellSizeAt(int resolution) => CellSize;

        /// <summary>Uniform acceleration of the timed frames (m/s²).</summary>
        protected virtual float3 TimedGravity => new float3(0f, -9.81f, 0f);

        /// <summary>One timed frame: the scene's load on the body, placed again every <see cref="FramesPerCycle"/> frames.</summary>
        public virtual void TimedFrame(IMethodBody body, int frame)
        {
            if (frame % FramesPerCycle == 0)
                body.Place();
            body.Step(Dt, TimedGravity, ReadOnlySpan<SoftBodyDynamics.Solvers.ColliderShape>.Empty);
        }

        /// <summary>
        /// Runs the scene's measurements on bodies of <paramref name="build"/> made from <paramref name="setup"/> (one of
        /// <see cref="SetupAt"/>; one body per material the scene needs) and returns the metrics, <see cref="Error"/> first.
        /// A body that diverged gives NaN errors.
        /// </summary>
        public abstract IReadOnlyList<Metric> Measure(MethodBodySetup setup, Func<MethodBodySetup, IMethodBody> build);

        /// <summary>Computes (and caches) the scene's float64 reference, which every <see cref="Measure"/> compares with.</summary>
        public void PrepareReference() => Reference();

        /// <summary>The scene's float64 reference values, computed on the first call (then cached per material).</summary>
        public abstract object Reference();

        /// <summary>Type of <see cref="Reference"/>'s values.</summary>
        public abstract Type ReferenceType { get; }

        /// <summary>Takes stored values (of <see cref="ReferenceType"/>, from an earlier run of the same reference sources) as the scene's reference.</summary>
        public abstract void UseReference(object values);

        /// <summary>"E = 1 MPa, ν = 0.45, ρ = 1100 kg/m³": a material's elastic constants for the definitions (ζ is stated where it applies).</summary>
        public static string MaterialText(in ElasticMaterial m)
        {
            double e = m.YoungsModulus;
            string modulus = e >= 1e6 ? Number(e / 1e6) + " MPa" : e >= 1e3 ? Number(e / 1e3) + " kPa" : Number(e) + " Pa";
            return $"E = {modulus}, ν = {Number(m.PoissonRatio)}, ρ = {Number(m.Density)} kg/m³";
        }

        /// <summary>A number with up to three decimals, invariant culture.</summary>
        protected static string Number(double v) => v.ToString("0.###", CultureInfo.InvariantCulture);

        /// <summary>|a/b − 1|, NaN when a is not finite.</summary>
        protected static double Relative(double value, double reference) =>
            double.IsFinite(value) ? Math.Abs(value / reference - 1.0) : double.NaN;

        /// <summary>The largest of the errors that have a reference (NaN ones are skipped); NaN when <paramref name="diverged"/>.</summary>
        protected static double Worst(bool diverged, params double[] errors)
        {
            if (diverged)
                return double.NaN;
            double w = 0;
            foreach (double v in errors)
                if (!double.IsNaN(v))
                    w = Math.Max(w, v);
            return w;
        }

        /// <summary>True when every position and velocity is finite.</summary>
        protected static bool Finite(IMethodBody body)
        {
            for (int i = 0; i < body.ParticleCount; i++)
                if (!math.all(math.isfinite(body.Positions[i])) || !math.all(math.isfinite(body.Velocities[i])))
                    return false;
            return true;
        }

        /// <summary>Mean of the positions of the flagged nodes (m).</summary>
        protected static float3 Mean(IMethodBody body, bool[] nodes)
        {
            double x = 0, y = 0, z = 0;
            int n = 0;
            for (int i = 0; i < nodes.Length; i++)
                if (nodes[i])
                {
                    x += body.Positions[i].x;
                    y += body.Positions[i].y;
                    z += body.Positions[i].z;
                    n++;
                }
            n = Math.Max(1, n);
            return new float3((float)(x / n), (float)(y / n), (float)(z / n));
        }
    }
}
