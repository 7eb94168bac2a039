using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>The scenes of <see cref="FluidCouplingSuite"/>.</summary>
    public enum FluidCouplingScene
    {
        /// <summary>A 10 cm box held still under water: the fluid's force on it against ρ₀gV.</summary>
        HeldBox,
        /// <summary>A 10 cm shape-matching cube of 500 kg/m³ dropped into water: the share of its volume under the waterline against 0.5.</summary>
        FloatingCube,
        /// <summary>A 0.3 kg ball thrown at 1 m/s into a weightless blob: the change of the total momentum.</summary>
        BallInBlob,
        /// <summary>The held box's tank without the box, stepped by the plain fluid step: what the body costs.</summary>
        TankAlone,
    }

    /// <summary>
    /// One coupled fluid–body run (<see cref="FluidCoupling.Step"/>) at Δx = 2 cm, WCSPH defaults, 1/60 s frames; a step is the
    /// whole run. Metrics as <see cref="FluidCouplingSuite"/> defines them.
    /// </summary>
    public sealed class FluidCouplingScenario : IScenario, IScenarioRepeatCap, IScenarioShortWarmup
    {
        /// <summary>Fluid spacing (m) and body size (m).</summary>
        public const float Spacing = 0.02f, BodySize = 0.1f;
        /// <summary>Tank (m, square) and the water's depth for the held box and the floating cube.</summary>
        public const float Tank = 0.3f, HeldDepth = 0.2f, FloatDepth = 0.16f;
        /// <summary>Density of the floating cube (kg/m³).</summary>
        public const float CubeDensity = 500f;
        const float Dt = 1f / 60f;
        const int WarmupFrameCount = 3;

        readonly FluidCouplingScene m_Scene;
        readonly float m_Seconds;
        FluidConstants m_Constants;
        FluidBuffers m_Fluid;
        float3[] m_Initial;
        readonly FluidBodyProxy[] m_Proxies = new FluidBodyProxy[1];
        FluidBodyProxy m_StartProxy;
        ShapeMatchingInstance m_Cube;
        ColliderShape m_CubeRest;
        ColliderShape[] m_Walls;
        readonly double[] m_Tops = new double[(int)(Tank / Spacing) * (int)(Tank / Spacing)];
        long m_Items;
        double m_Sum, m_Count, m_MomentumBefore, m_MomentumChange;

        public FluidCouplingScenario(FluidCouplingScene scene, float seconds)
        {
            m_Scene = scene;
            m_Seconds = seconds;
            Size = scene == FluidCouplingScene.BallInBlob
                ? FluidScene.BlockCount(new float3(0.42f), new float3(0.58f), Spacing)
                : FluidScene.BlockCount(float3.zero, new float3(Tank, scene == FluidCouplingScene.FloatingCube ? FloatDepth : HeldDepth, Tank), Spacing);
        }

        public string Name => "FluidCoupling";
        public string Method => m_Scene switch
        {
            FluidCouplingScene.HeldBox => "box held under water",
            FluidCouplingScene.FloatingCube => "jelly cube, 500 kg/m³",
            FluidCouplingScene.BallInBlob => "ball into a weightless blob",
            _ => "tank alone (no body, FluidSolver.Step)",
        };
        /// <summary>Fluid particles at the start (the held box's scene takes out those where the box stands).</summary>
        public int Size { get; }
        public string SizeUnit => "particles";
        public long ItemsPerStep => Math.Max(1, m_Items);
        public int MaxRepeats => 1;
        int Frames => Math.Max(1, (int)Math.Round(m_Seconds / Dt));

        public void Setup()
        {
            FluidParameters p = FluidParameters.Default;
            if (m_Scene == FluidCouplingScene.BallInBlob)
            {
                p.ParticleSpacing = Spacing;
                p.DomainMin = float3.zero;
                p.DomainMax = new float3(1f);
                p.Gravity = float3.zero;
                m_Constants = new FluidConstants(p);
                m_Fluid = new FluidBuffers(FluidScene.BlockCount(new float3(0.42f), new float3(0.58f), Spacing), m_Constants.Grid);
                FluidScene.FillBlock(m_Fluid, new float3(0.42f), new float3(0.58f), Spacing);
                const float mass = 0.3f, radius = 0.04f;
                m_StartProxy = new FluidBodyProxy
                {
                    Shape = ColliderShape.Sphere(new float3(0.3f, 0.5f, 0.5f), radius).Moving(new float3(1f, 0f, 0f), float3.zero),
                    Mass = mass,
                    InverseInertia = float3x3.identity * (2.5f / (mass * radius * radius)),
                };
            }
            else
            {
                float depth = m_Scene == FluidCouplingScene.FloatingCube ? FloatDepth : HeldDepth;
                m_Fluid = FluidScene.BlockInBox(p, Spacing, new float3(Tank, 0.5f, Tank), new float3(Tank, depth, Tank), out m_Constants);
                if (m_Scene != FluidCouplingScene.FloatingCube)
                {
                    // Held with its top 6 cm under the surface; the water where it stands is taken out.
                    var box = ColliderShape.Box(new float3(0.5f * Tank, depth - 0.06f - 0.5f * BodySize, 0.5f * Tank), quaternion.identity, new float3(0.5f * BodySize));
                    for (int i = 0; i < m_Fluid.Status.Count; i++)
                        if (ParticleCollision.Contains(box, m_Fluid.Positions[i]))
                            m_Fluid.Positions[i] = new float3(float.NaN);
                    m_StartProxy = new FluidBodyProxy { Shape = box };
                }
                else if (m_Scene == FluidCouplingScene.FloatingCube)
                {
                    const int side = 5;
                    var model = LatticeBody.Create(new int3(side), BodySize / side, side, CubeDensity * BodySize * BodySize * BodySize);
                    var sp = ShapeMatchingParameters.Default;
                    sp.Body.SleepSpeed = 0f;
                    m_Cube = new ShapeMatchingInstance(model, sp, CubeStart, quaternion.identity);
                    var rest = ShapeMatchingSolver.Body(model.AsModel(), m_Cube.State);
                    m_CubeRest = FluidBodyProxy.RestBox(rest.RestPositions, rest.RestCenter, 0.5f * BodySize / side);
                    m_Walls = new[]
                    {
                        ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)), ColliderShape.Plane(float3.zero, new float3(1f, 0f, 0f)),
                        ColliderShape.Plane(float3.zero, new float3(0f, 0f, 1f)), ColliderShape.Plane(new float3(Tank), new float3(-1f, 0f, 0f)),
                        ColliderShape.Plane(new float3(Tank), new float3(0f, 0f, -1f)),
                    };
                }
            }
            m_Initial = (float3[])m_Fluid.Positions.Clone();
        }

        void Restart()
        {
            FluidScene.Restart(m_Fluid, m_Initial);
            m_Proxies[0] = m_StartProxy;
            m_Sum = m_Count = 0;
            m_Items = 0;
            if (m_Scene == FluidCouplingScene.FloatingCube)
            {
                m_Cube.Reset(CubeStart, quaternion.identity);
                m_Cube.Parameters.Body.Acceleration = m_Constants.Parameters.Gravity;
            }
            if (m_Scene == FluidCouplingScene.BallInBlob)
                m_MomentumBefore = MomentumX() + m_Proxies[0].Mass * m_Proxies[0].Shape.Velocity.x;
        }

        /// <summary>The cube's starting centre: its bottom 1 cm above the water.</summary>
        static float3 CubeStart => new float3(0.5f * Tank, FloatDepth + 0.5f * BodySize + 0.01f, 0.5f * Tank);

        public void Step() => Run(Frames);

        public void WarmupFrames() => Run(Math.Min(WarmupFrameCount, Frames));

        void Run(int frames)
        {
            Restart();
            int averaged = m_Scene == FluidCouplingScene.HeldBox ? frames / 4 : frames / 3;
            for (int f = 0; f < frames; f++)
            {
                bool measured = f >= frames - Math.Max(1, averaged);
                if (m_Scene == FluidCouplingScene.FloatingCube)
                {
                    var body = ShapeMatchingSolver.Body(m_Cube.Model.AsModel(), m_Cube.State);
                    m_Proxies[0] = FluidBodyProxy.Of(body, m_Cube.Status, m_CubeRest);
                    var report = FluidCoupling.Step(m_Constants, default, m_Proxies, Dt, m_Fluid.Particles, m_Fluid.Scratch, ref m_Fluid.Status);
                    m_Items += (long)report.Substeps * m_Fluid.Status.Count;
                    m_Proxies[0].ApplyAngularImpulse(body);
                    m_Cube.Parameters.Body.Acceleration = m_Constants.Parameters.Gravity + m_Proxies[0].LinearAcceleration(Dt);
                    m_Cube.Step(Dt, m_Walls);
                    if (measured)
                    {
                        m_Sum += SubmergedFraction(m_Proxies[0].Shape, Waterline(m_Cube.Status.Center));
                        m_Count++;
                    }
                }
                else if (m_Scene == FluidCouplingScene.TankAlone)
                {
                    var report = FluidSolver.Step(m_Constants, default, Dt, m_Fluid.Particles, m_Fluid.Scratch, ref m_Fluid.Status);
                    m_Items += (long)report.Substeps * m_Fluid.Status.Count;
                    if (measured)
                    {
                        m_Sum += report.Substeps;
                        m_Count++;
                    }
                }
                else
                {
                    ColliderShape held = m_StartProxy.Shape;
                    var report = FluidCoupling.Step(m_Constants, default, m_Proxies, Dt, m_Fluid.Particles, m_Fluid.Scratch, ref m_Fluid.Status);
                    m_Items += (long)report.Substeps * m_Fluid.Status.Count;
                    if (m_Scene == FluidCouplingScene.HeldBox)
                    {
                        if (measured)
                        {
                            m_Sum += m_Proxies[0].Impulse.y / Dt;
                            m_Count++;
                        }
                        m_Proxies[0].Shape = held;
                    }
                }
            }
            if (m_Scene == FluidCouplingScene.BallInBlob)
                m_MomentumChange = MomentumX() + m_Proxies[0].Mass * m_Proxies[0].Shape.Velocity.x - m_MomentumBefore;
        }

        /// <summary>The fluid's momentum along x (kg·m/s), summed in double.</summary>
        double MomentumX()
        {
            double sum = 0;
            for (int i = 0; i < m_Fluid.Status.Count; i++)
                sum += m_Fluid.Velocities[i].x;
            return m_Constants.Mass * sum;
        }

        /// <summary>Mean top (m) of the water columns farther than 0.75 body widths from the body on both axes: the top particle with ≥ 4 neighbours, plus Δx/2.</summary>
        double Waterline(float3 centre)
        {
            int cells = (int)(Tank / Spacing);
            double[] top = m_Tops;
            for (int k = 0; k < top.Length; k++)
                top[k] = double.NegativeInfinity;
            for (int i = 0; i < m_Fluid.Status.Count; i++)
            {
                float3 x = m_Fluid.Positions[i];
                if (math.abs(x.x - centre.x) < 0.75f * BodySize || math.abs(x.z - centre.z) < 0.75f * BodySize || m_Fluid.NeighbourCounts[i] < 4)
                    continue;
                int cx = math.clamp((int)(x.x / Spacing), 0, cells - 1), cz = math.clamp((int)(x.z / Spacing), 0, cells - 1);
                top[cx * cells + cz] = Math.Max(top[cx * cells + cz], x.y);
            }
            double sum = 0;
            int count = 0;
            foreach (double t in top)
                if (!double.IsNegativeInfinity(t))
                {
                    sum += t;
                    count++;
                }
            return count > 0 ? sum / count + 0.5 * Spacing : double.NaN;
        }

        /// <summary>Share of the proxy box's volume below the waterline, on a 16³ grid of sample points.</summary>
        static double SubmergedFraction(in ColliderShape box, double waterline)
        {
            const int s = 16;
            int below = 0;
            for (int a = 0; a < s; a++)
            for (int b = 0; b < s; b++)
            for (int c = 0; c < s; c++)
            {
                float3 u = (new float3(a, b, c) + 0.5f) / s * 2f - 1f;
                if (box.Center.y + math.mul(box.Rotation, u * box.HalfExtents).y < waterline)
                    below++;
            }
            return below / (double)(s * s * s);
        }

        public IReadOnlyList<Metric> Evaluate()
        {
            double weight = m_Constants.Parameters.RestDensity * 9.81 * BodySize * BodySize * BodySize;
            return m_Scene switch
            {
                FluidCouplingScene.HeldBox => new[]
                {
                                        new Metric("buoyancy error", m_Sum / m_Count / weight - 1.0, MetricUnit.Fraction),
                },
                FluidCouplingScene.FloatingCube => new[]
                {
                    new Metric("submerged fraction", m_Sum / m_Count, MetricUnit.Fraction),
                    new Metric("buoyancy error", CubeDensity / m_Constants.Parameters.RestDensity / (m_Sum / m_Count) - 1.0, MetricUnit.Fraction),
                },
                FluidCouplingScene.TankAlone => new[] { new Metric("substeps per frame", m_Sum / m_Count, MetricUnit.Dimensionless) },
                _ => new[]
                {
                    new Metric("momentum change", Math.Abs(m_MomentumChange) / (m_StartProxy.Mass * m_StartProxy.Shape.Velocity.x), MetricUnit.Fraction),
                },
            };
        }
    }
}
