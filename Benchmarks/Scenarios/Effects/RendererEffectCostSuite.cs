using System;
using System.Collections.Generic;
using System.Globalization;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// What the screen-space fluid renderer and each of its optional passes cost per frame: the frame whose
    /// <see cref="FluidSurfacePassList"/> has the pass against the frame whose list does not, timed in pairs
    /// (<see cref="RendererEffectScenario"/>) on the C# reference passes on the CPU — not a GPU time — next to the
    /// counted memory traffic of a 1920 × 1080 frame (<see cref="FluidSurfaceCost"/>), the device-independent figure.
    /// </summary>
    public sealed class RendererEffectCostSuite : IScenarioSuite, IScenarioSuiteIndependent, IScenarioSuiteFindings
    {
        public const string SuiteName = "EffectCostRenderer";

        /// <summary>One row: its summary name, the pair in words, and the frame with (true) or without it (false; null = no fluid to draw).</summary>
        public sealed class Case
        {
            public readonly string Effect;
            public readonly string Scene;
            public readonly Func<bool, FluidSurfaceCpuFrame> Build;

            public Case(string effect, string scene, Func<bool, FluidSurfaceCpuFrame> build)
            {
                Effect = effect;
                Scene = scene;
                Build = build;
            }
        }

        /// <summary>The timed screen: small, so the reference frames (every pixel against every particle of its tile rectangle) take tens of ms.</summary>
        public const int Width = 160, Height = 90;
        /// <summary>The screen the counted traffic is given for.</summary>
        public const int CountedWidth = 1920, CountedHeight = 1080;
        /// <summary>Timed pairs at most: the default run's (its 0.5 s budget usually stops it first), and the full run's.</summary>
        public const int Repeats = 25, FullRepeats = 60;

        public string Name => SuiteName;

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "What the screen-space fluid renderer and each of its optional passes cost per frame: the frame whose pass list has it against the frame whose list does not.",
            Body = $"The renderer's sphere scene: a ball of about 500 water particles (radius 0.1 m, drawn at 1.4 cm) over a checkerboard floor, seen at {Width} × {Height}.",
            Material = "Looks: water (lit: refraction, absorption, Fresnel), water without refraction and absorption, toon, flat. Settings: the desktop tier (full resolution, one narrow-range iteration) and the mobile tier.",
            Load = "One frame of the surface passes as FluidSurfaceFrame records them for the settings and look (FluidSurfacePassList), run by the C# reference passes on the CPU (FluidSurfaceCpuFrame).",
            Reference = "none (cost only).",
            Metric = "Each timed step is a pair: the frame with the pass, then the frame without it, each under its own stopwatch (single-threaded managed .NET, " +
                     "the C# reference passes: not a GPU time); the metrics are the fastest of each (after two warm-up pairs) and their difference, the fastest " +
                     "time of the kernels only the frame with the pass dispatches (timed inside it), the compute dispatches of each list, and the counted bytes " +
                     $"per screen pixel of each (FluidSurfaceCost), which the summary multiplies by {CountedWidth} × {CountedHeight}.",
            Notes = new[]
            {
                "The reference builds no tile lists (each pixel tests every particle whose tile rectangle covers its tile) and runs no overlay: " +
                "the four tile-list dispatches cost nothing here, and the overlay's bytes are counted but not timed.",
                "Quick run: the whole renderer and smoothing only.",
            },
            Details = "effects.md",
        };

        public string ErrorMetricForPlot => null;

        /// <summary>The rows in summary order.</summary>
        public static IReadOnlyList<Case> Cases { get; } = new[]
        {
            new Case(EffectNames.FluidRenderer, "water in the desktop tier, against no fluid to draw (nothing recorded)",
                present => present ? Frame(Desktop, FluidLook.Water) : null),
            new Case(EffectNames.RendererSmoothing, "water in the desktop tier, one narrow-range iteration (2 passes) against none",
                present => Frame(present ? Desktop : Unsmoothed, FluidLook.Water)),
            new Case(EffectNames.RendererThickness, "water against water without refraction and absorption (no thickness splat)",
                present => Frame(Desktop, present ? FluidLook.Water : ClearWater)),
            new Case(EffectNames.RendererNormals, "the toon look against the flat one (no normals pass; neither reads thickness)",
                present => Frame(Desktop, present ? FluidLook.Toon : FluidLook.FlatColour)),
            new Case(EffectNames.RendererFullResolution, "water in the desktop tier against the mobile tier (depth, smoothing, normals and composite at half resolution)",
                present => Frame(present ? Desktop : Mobile, FluidLook.Water)),
        };

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            foreach (Case c in Cases)
                if (scope != RunScope.Quick || c.Effect == EffectNames.FluidRenderer || c.Effect == EffectNames.RendererSmoothing)
                    yield return new RendererEffectScenario(c, scope == RunScope.Full ? FullRepeats : Repeats);
        }

        /// <summary>One effect line per row: the fastest frames with and without the pass, and the counted traffic it adds at 1920 × 1080.</summary>
        public IEnumerable<Finding> Findings(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            foreach (Case c in Cases)
            foreach (ScenarioOutcome r in rows)
                if (r.Method == c.Effect)
                    yield return new EffectFinding
                    {
                        Effect = c.Effect,
                        Cost = CostText(r.Value(EffectScenario.WithMs), r.Value(EffectScenario.WithoutMs), r.Value(RendererEffectScenario.PassMs), r.Size, c.Scene,
                            r.Value(RendererEffectScenario.BytesWith), r.Value(RendererEffectScenario.BytesWithout)),
                    };
        }

        /// <summary>
        /// "+x ms per frame (…; n particles: C# reference passes on the CPU at w × h, not a GPU time; scene); the pass alone
        /// p ms; counted traffic of a 1920 × 1080 frame: +m MB (+b B/px)" (no "pass alone" when <paramref name="passMs"/> is NaN).
        /// </summary>
        public static string CostText(double withMs, double withoutMs, double passMs, int particles, string scene, double bytesWith, double bytesWithout)
        {
            string timed = EffectCostSuite.CostText(withMs, withoutMs, particles,
                $"C# reference passes on the CPU at {Width} × {Height}, not a GPU time; {scene}");
            if (!double.IsNaN(passMs))
                timed += $"; timed inside the frame, its passes alone take {passMs.ToString(passMs >= 10 ? "0.#" : "0.##", CultureInfo.InvariantCulture)} ms";
            double bytes = bytesWith - bytesWithout;
            double megabytes = bytes * CountedWidth * CountedHeight / 1e6;
            string sign = bytes > 0 ? "+" : "";
            return $"{timed}; counted traffic of a {CountedWidth} × {CountedHeight} frame: {sign}{megabytes.ToString("0.#", CultureInfo.InvariantCulture)} MB " +
                   $"({sign}{bytes.ToString("0.##", CultureInfo.InvariantCulture)} B/px)";
        }

        static FluidSurfaceScene s_Scene;
        static readonly object s_Lock = new object();

        /// <summary>The sphere scene, built once and shared (read only) by every frame.</summary>
        static FluidSurfaceScene Scene
        {
            get
            {
                lock (s_Lock)
                    return s_Scene ??= FluidSurfaceScene.Sphere(Width, Height);
            }
        }

        static FluidSurfaceSettings Desktop => FluidSurfaceSettings.Desktop(Scene.Radius);

        static FluidSurfaceSettings Mobile => FluidSurfaceSettings.Mobile(Scene.Radius);

        static FluidSurfaceSettings Unsmoothed
        {
            get
            {
                FluidSurfaceSettings s = Desktop;
                s.Iterations = 0;
                return s;
            }
        }

        /// <summary>Water whose shading reads no thickness: no refraction, no absorption (it emits nothing either).</summary>
        static FluidLook ClearWater
        {
            get
            {
                FluidLook l = FluidLook.Water;
                l.Refraction = 0f;
                l.Absorption = new Unity.Mathematics.float3(0f);
                return l;
            }
        }

        static FluidSurfaceCpuFrame Frame(FluidSurfaceSettings settings, FluidLook look) => new FluidSurfaceCpuFrame(Scene, settings, look);
    }
}
