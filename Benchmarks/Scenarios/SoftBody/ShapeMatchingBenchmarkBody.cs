using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// The bodies and settings every shape-matching benchmark shares: a cubic lattice of a given edge
    /// length, its cluster layout, and the default jelly parameters with a chosen mode and substep count.
    /// </summary>
    public static class ShapeMatchingBenchmarkBody
    {
        /// <summary>Simulation step (s): one frame at 60 Hz.</summary>
        public const float TimeStep = 1f / 60f;
        /// <summary>Lattice points per cluster edge in <see cref="ShapeMatchingClusterLayout.Overlapping"/>.</summary>
        public const int ClusterEdge = 4;
        /// <summary>Mass of every benchmark body (kg); the metrics are relative and do not depend on it.</summary>
        public const float TotalMass = 10f;

        /// <summary>A cube of <paramref name="edge"/>³ particles spanning <paramref name="size"/> metres per side.</summary>
        public static ShapeMatchingModelData Lattice(int edge, float size, ShapeMatchingClusterLayout layout, ShapeMatchingMode mode)
        {
            int clusterEdge = layout == ShapeMatchingClusterLayout.Single ? edge : ClusterEdge;
            return LatticeBody.Create(new int3(edge), Spacing(edge, size), clusterEdge, TotalMass,
                mode == ShapeMatchingMode.Quadratic);
        }

        /// <summary>Distance between neighbouring lattice points (m).</summary>
        public static float Spacing(int edge, float size) => size / math.max(1, edge - 1);

        /// <summary>Particle radius of every benchmark body (m): half the spacing, so neighbouring particles touch.</summary>
        public static float ParticleRadius(int edge, float size) => 0.5f * Spacing(edge, size);

        /// <summary>Natural frequency (Hz) of every benchmark body (the default jelly's).</summary>
        public const float Frequency = 9f;
        /// <summary>Damping ratio of every benchmark body (the default jelly's).</summary>
        public const float DampingRatio = 0.13f;
        /// <summary>Blend β of the linear or quadratic transform (the default jelly's).</summary>
        public const float Beta = 0.5f;
        /// <summary>
        /// Substep phase limit of the benchmarks (rad): large enough that the step takes exactly the requested
        /// substeps, so the substep count is the cost axis the sweeps set.
        /// </summary>
        public const float NoSubstepFloor = 1000f;
        /// <summary>Friction coefficient against the floor (the default jelly's).</summary>
        public const float Friction = 0.5f;
        /// <summary>Restitution against the floor (the default jelly's).</summary>
        public const float Restitution = 0.1f;

        /// <summary>
        /// The default jelly's settings, pinned here so the benchmarks measure the same body when the defaults
        /// change (9 Hz, ζ = 0.13, β = 0.5, friction 0.5, restitution 0.1, no plasticity), with the given
        /// mode, exactly the given substeps (<see cref="NoSubstepFloor"/>), acceleration (m/s²) and particle radius
        /// (m, <see cref="ParticleRadius"/>), and no sleeping, so every step does the full work.
        /// </summary>
        public static ShapeMatchingParameters Parameters(ShapeMatchingMode mode, int substeps, float3 acceleration, float particleRadius)
        {
            var p = ShapeMatchingParameters.Default;
            p.Mode = mode;
            p.Frequency = Frequency;
            p.DampingRatio = DampingRatio;
            p.Beta = Beta;
            p.MaxSubstepPhase = NoSubstepFloor;
            p.Body.Friction = Friction;
            p.Body.Restitution = Restitution;
            p.Plasticity = PlasticityParameters.None;
            p.Body.Substeps = substeps;
            p.Body.Acceleration = acceleration;
            p.Body.ParticleRadius = particleRadius;
            p.Body.SleepSpeed = 0f;
            return p;
        }

        /// <summary>"rigid", "linear" or "quadratic".</summary>
        public static string ModeLabel(ShapeMatchingMode mode) => mode switch
        {
            ShapeMatchingMode.Rigid => "rigid",
            ShapeMatchingMode.Linear => "linear",
            _ => "quadratic",
        };

        /// <summary>"1 cluster" or "4^3 clusters".</summary>
        public static string LayoutLabel(ShapeMatchingClusterLayout layout) =>
            layout == ShapeMatchingClusterLayout.Single ? "1 cluster" : $"{ClusterEdge}^3 clusters";

        /// <summary>The method column of every shape-matching scenario, e.g. "linear (4^3 clusters)".</summary>
        public static string Label(ShapeMatchingMode mode, ShapeMatchingClusterLayout layout) =>
            $"{ModeLabel(mode)} ({LayoutLabel(layout)})";
    }
}
