using System;
using System.Collections.Generic;
using System.Globalization;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// What each effect a scene can call for costs per 1/60 s frame: every effect is timed in one scene with it and
    /// without it, frame after frame in pairs (<see cref="EffectScenario"/>, <see cref="EffectScene"/>: the package's fixed
    /// step in .NET), and the summary gives the difference.
    /// A method or the fluid absent from a scene runs no step, so its "without" row is the frame of an empty scene.
    /// </summary>
    public sealed class EffectCostSuite : IScenarioSuite, IScenarioSuiteIndependent, IScenarioSuiteFindings
    {
        /// <summary>
        /// One effect: its summary name, the scene in words, the scene with (true) or without it (false), and the frames run
        /// before the timed one (<see cref="EffectScene.Start"/>).
        /// </summary>
        public sealed class Case
        {
            public readonly string Effect;
            public readonly string Scene;
            public readonly Func<bool, EffectScene> Build;
            public readonly int StartFrames;

            public Case(string effect, string scene, Func<bool, EffectScene> build, int startFrames)
            {
                Effect = effect;
                Scene = scene;
                Build = build;
                StartFrames = startFrames;
            }
        }

        /// <summary>Frames before the timed frame: a cube settling on the floor (0.5 s), the water block settling (0.5 s).</summary>
        public const int SettleFrames = 30;
        /// <summary>Frames before the timed frame of the plasticity scene: the cube has hit the floor and is squashing (0.3 s).</summary>
        public const int ImpactFrames = 18;

        /// <summary>Nodes per axis of every jelly cube.</summary>
        public const int JellyEdge = 8;
        /// <summary>Side of every jelly cube (m).</summary>
        public const float JellySize = 0.5f;
        /// <summary>Height the plasticity scene drops its cube from (bottom above the floor, m).</summary>
        public const float DropHeight = 0.3f;
        /// <summary>Fluid spacing (m) and the water block's side (m): 12³ = 1728 particles.</summary>
        public const float FluidSpacing = 0.02f, FluidBlock = 0.24f;

        // The block fills the box's floor, so it rests (no slump); the colliders hang 16 cm above its surface.
        static readonly float3 s_FluidDomain = new float3(FluidBlock, 0.5f, FluidBlock);

        public string Name => "EffectCost";

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "What each effect a scene can call for costs per 1/60 s frame: the same scene with and without it, on the package's fixed step.",
            Body = $"A {JellyEdge}³ = {JellyEdge * JellyEdge * JellyEdge}-node jelly cube of {JellySize} m (6 tetrahedra per cell) per soft-body effect; " +
                   $"a {Count(FluidBlock)}³ = {Count(FluidBlock) * Count(FluidBlock) * Count(FluidBlock)}-particle water block of {FluidBlock} m at Δx = {FluidSpacing} m " +
                   $"in a {s_FluidDomain.x} × {s_FluidDomain.y} × {s_FluidDomain.z} m box per fluid effect.",
            Material = "Jelly as in SoftBodyMethodsThroughput (shape matching linear with 3-cell clusters, mass-spring XPBD, FEM co-rotational implicit, " +
                       $"{SoftBodyMethodsThroughputSuite.Substeps} substeps); plasticity: clay's (yield 0.05, creep 10/s, at most 0.6); water at its defaults.",
            Load = $"Gravity. Each scene runs {SettleFrames} frames (cubes settling on a floor plane, the water block in its box; the plasticity cube, dropped " +
                   DropHeight.ToString(CultureInfo.InvariantCulture) + $" m onto the floor, {ImpactFrames} frames: just after impact), then every timed frame starts " +
                   "from that state again (positions and velocities put back), so with and without time the same frame.",
            Reference = "none (cost only).",
            Metric = "Each timed step is a pair: the frame with the effect, then the same frame without it, each under its own stopwatch " +
                     "(single-threaded managed .NET); every timed frame repeats the same work, so the metrics are the fastest time of each " +
                     "and their difference, which the summary's Effects list gives. ns/item is the pair's cost.",
            Notes = new[]
            {
                "Colliders (soft body): floor plane, sphere, capsule and box beside the cube, against none (the cube falls freely). " +
                "Colliders (fluid): a sphere in the water, a capsule across its surface and a box on its floor, against the same particles " +
                "without them; out of reach: sphere, capsule and box hanging above the water, against none (the box's walls are the " +
                "fluid's domain, not colliders).",
                "Cohesion and the implicit viscosity are priced on the droplet of FluidAccuracy.",
                "Quick run: every row but the two fluid-collider ones.",
            },
            Details = "effects.md",
        };

        public string ErrorMetricForPlot => null;

        /// <summary>The effects in summary order.</summary>
        public static IReadOnlyList<Case> Cases { get; } = new[]
        {
            new Case(EffectNames.ShapeMatchingBody, "a jelly cube on a floor", present => Jelly(present ? 0 : -1), SettleFrames),
            new Case(EffectNames.MassSpringBody, "a jelly cube on a floor", present => Jelly(present ? 3 : -1), SettleFrames),
            new Case(EffectNames.FemBody, "a jelly cube on a floor", present => Jelly(present ? 4 : -1), SettleFrames),
            new Case(EffectNames.Fluid, "a water block at rest", present => Water(present, colliders: false), SettleFrames),
            new Case(EffectNames.SoftBodyCollisions, "a shape-matching jelly cube, 4 colliders or none", present => JellyColliders(present), SettleFrames),
            new Case(EffectNames.FluidColliders, "a water block around 3 colliders, or the same particles without them",
                present => WaterAroundColliders(present), SettleFrames),
            new Case(EffectNames.FluidCollidersOutOfReach, "a water block, 3 colliders hanging above it or none", present => Water(true, colliders: present), SettleFrames),
            new Case(EffectNames.Plasticity, "a shape-matching jelly cube dropped on a floor", present => DroppedJelly(present), ImpactFrames),
        };

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            foreach (Case c in Cases)
                if (scope != RunScope.Quick || (c.Effect != EffectNames.FluidColliders && c.Effect != EffectNames.FluidCollidersOutOfReach))
                    yield return new EffectScenario(c);
        }

        /// <summary>One effect line per row: the fastest frames with and without it and their difference.</summary>
        public IEnumerable<Finding> Findings(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            foreach (Case c in Cases)
            foreach (ScenarioOutcome r in rows)
                if (r.Method == c.Effect)
                    yield return new EffectFinding
                    {
                        Effect = c.Effect,
                        Cost = CostText(r.Value(EffectScenario.WithMs), r.Value(EffectScenario.WithoutMs), r.Size, c.Scene),
                    };
        }

        /// <summary>"+x ms per frame (with y ms, without z ms; n particles: scene)", from the two fastest frames (ms).</summary>
        public static string CostText(double withMs, double withoutMs, int particles, string scene)
        {
            double delta = withMs - withoutMs;
            string head = delta > 0 ? $"+{Ms(delta)} ms per frame" : $"no cost above the timing noise ({Ms(delta)} ms per frame)";
            return $"{head} (with {Ms(withMs)} ms, without {Ms(withoutMs)} ms; {particles} particles: {scene})";
        }

        static string Ms(double ms) => ms.ToString(Math.Abs(ms) >= 10 ? "0.#" : Math.Abs(ms) >= 0.1 ? "0.##" : "0.####", CultureInfo.InvariantCulture);

        static int Count(float side) => (int)math.floor(side / FluidSpacing + 1e-3f);

        /// <summary>A jelly cube of variant <paramref name="variant"/> of <see cref="SoftBodyMethodsThroughputSuite.Variants"/> resting on a floor; -1 = the floor alone.</summary>
        static EffectScene Jelly(int variant)
        {
            var scene = new EffectScene { Colliders = new[] { Floor } };
            if (variant >= 0)
                scene.Bodies.Add(Cube(0f, (s, h) => SoftBodyMethodsThroughputSuite.Variants[variant].Create(s, h)));
            return scene;
        }

        static EffectScene JellyColliders(bool present)
        {
            var scene = new EffectScene();
            scene.Bodies.Add(Cube(0f, (s, h) => SoftBodyMethodsThroughputSuite.Variants[0].Create(s, h)));
            if (present)
                scene.Colliders = new[]
                {
                    Floor,
                    ColliderShape.Sphere(new float3(0.6f, 0.2f, 0f), 0.2f),
                    ColliderShape.Capsule(new float3(-0.6f, 0.1f, -0.3f), new float3(-0.6f, 0.1f, 0.3f), 0.1f),
                    ColliderShape.Box(new float3(0f, 0.1f, 0.6f), quaternion.identity, new float3(0.3f, 0.1f, 0.1f)),
                };
            return scene;
        }

        static EffectScene DroppedJelly(bool plastic)
        {
            PlasticityParameters plasticity = plastic ? ShapeMatchingMaterial.Clay.Plasticity : PlasticityParameters.None;
            var scene = new EffectScene { Colliders = new[] { Floor } };
            scene.Bodies.Add(Cube(DropHeight, (s, h) => new ShapeMatchingMethodBody(s, ShapeMatchingMode.Linear, SoftBodyMethodsThroughputSuite.Substeps,
                h * SoftBodyMethodsThroughputSuite.ClusterCells / ShapeMatchingMethodBody.ClusterCells, plasticity: plasticity)));
            return scene;
        }

        static EffectScene Water(bool present, bool colliders)
        {
            var scene = new EffectScene();
            if (present)
            {
                scene.Fluid = FluidScene.BlockInBox(FluidParameters.Default, FluidSpacing, s_FluidDomain, new float3(FluidBlock), out FluidConstants c);
                scene.FluidConstants = c;
            }
            if (colliders)
                scene.Colliders = new[]
                {
                    ColliderShape.Sphere(new float3(0.12f, 0.44f, 0.12f), 0.04f),
                    ColliderShape.Capsule(new float3(0.04f, 0.44f, 0.04f), new float3(0.2f, 0.44f, 0.04f), 0.02f),
                    ColliderShape.Box(new float3(0.12f, 0.46f, 0.2f), quaternion.identity, new float3(0.05f, 0.01f, 0.03f)),
                };
            return scene;
        }

        /// <summary>Three colliders in the water block: a sphere in its middle, a capsule across its surface, a box on its floor.</summary>
        static ColliderShape[] Submerged => new[]
        {
            ColliderShape.Sphere(new float3(0.12f, 0.12f, 0.12f), 0.05f),
            ColliderShape.Capsule(new float3(0.02f, 0.22f, 0.06f), new float3(0.22f, 0.22f, 0.06f), 0.03f),
            ColliderShape.Box(new float3(0.18f, 0.03f, 0.18f), quaternion.identity, new float3(0.04f, 0.03f, 0.04f)),
        };

        /// <summary>
        /// The water block with the particles inside the <see cref="Submerged"/> colliders (closer than the wall distance
        /// to their solids) left out, with the colliders or without them: the same particles either way.
        /// </summary>
        static EffectScene WaterAroundColliders(bool colliders)
        {
            EffectScene scene = Water(true, colliders: false);
            FluidBuffers b = scene.Fluid;
            ColliderShape[] shapes = Submerged;
            int kept = 0;
            for (int i = 0; i < b.Status.Count; i++)
            {
                bool inside = false;
                foreach (ColliderShape shape in shapes)
                    inside |= ParticleCollision.Penetration(shape, b.Positions[i], scene.FluidConstants.WallDistance, out _, out _);
                if (inside)
                    continue;
                b.Positions[kept] = b.Positions[i];
                b.Velocities[kept] = b.Velocities[i];
                b.Ages[kept] = b.Ages[i];
                b.Lifetimes[kept] = b.Lifetimes[i];
                b.Attributes[kept] = b.Attributes[i];
                b.Ids[kept] = b.Ids[i];
                kept++;
            }
            b.Status.Count = kept;
            if (colliders)
                scene.Colliders = shapes;
            return scene;
        }

        static ColliderShape Floor => ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f));

        /// <summary>A jelly cube whose bottom layer is one particle radius above <paramref name="bottom"/> (m), built by <paramref name="create"/> (setup, cell size).</summary>
        static IMethodBody Cube(float bottom, Func<MethodBodySetup, float, IMethodBody> create) =>
            create(MethodBodySetup.JellyCube(JellySize, JellyEdge, bottom), JellySize / (JellyEdge - 1));
    }
}
