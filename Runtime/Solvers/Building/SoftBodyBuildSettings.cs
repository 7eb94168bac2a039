namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// How <see cref="SoftBodyBuilder"/> turns a triangle mesh into a shape-matching body. Each field's
    /// summary doubles as its inspector tooltip; units are in brackets.
    /// </summary>
    public struct SoftBodyBuildSettings
    {
        /// <summary>Default particle limit per body.</summary>
        public const int DefaultMaxParticles = 16384;

        /// <summary>
        /// Render vertices closer than this fraction of the mesh's bounds diagonal are merged into one
        /// particle [dimensionless, ≥ 0]. 1e-5 merges the copies a mesh splits for UV seams, hard edges
        /// and poles without merging real detail. Ignored when WeldDistance is above 0.
        /// </summary>
        public float WeldTolerance;

        /// <summary>
        /// Absolute weld distance [m, ≥ 0]: when above 0 it replaces WeldTolerance. Use it to merge
        /// vertices a modelling tool left slightly apart; 0 uses the relative tolerance.
        /// </summary>
        public float WeldDistance;

        /// <summary>
        /// Fill a closed mesh with particles on a cubic lattice, so the body has volume and its clusters
        /// are not hollow shells [on/off]. Open meshes get a warning and no interior particles.
        /// </summary>
        public bool AddInteriorParticles;

        /// <summary>
        /// Distance between interior particles [m, ≥ 0]. 0 chooses one eighth of the mesh's longest side.
        /// Smaller spacing: more particles, better volume, slower building and simulation.
        /// </summary>
        public float InteriorSpacing;

        /// <summary>
        /// Size of the overlapping shape-matching regions [m, ≥ 0]. 0 (or at least the mesh's longest
        /// side) makes one cluster of the whole body: it keeps its overall shape but cannot bend. Smaller
        /// clusters bend and wobble locally; about a quarter of the body is a good start.
        /// </summary>
        public float ClusterSize;

        /// <summary>
        /// Mass of the whole body [kg, &gt; 0], spread uniformly over all particles (surface and interior):
        /// each particle weighs TotalMass / particle count, so the mass follows the particle density.
        /// </summary>
        public float TotalMass;

        /// <summary>
        /// Also precompute the quadratic deformation mode (bending and twisting within one cluster) [on/off].
        /// Costs 324 bytes per cluster; needed only when the body uses the Quadratic mode.
        /// </summary>
        public bool BuildQuadratic;

        /// <summary>
        /// Most particles the body may have [count, &gt; 0; default 16384]. Building fails above it: reduce
        /// the mesh or raise InteriorSpacing. The limit keeps the bake (the interior test costs particles ×
        /// triangles) and the per-body solve within real-time budgets.
        /// </summary>
        public int MaxParticles;

        /// <summary>Weld tolerance 1e-5, no interior particles (auto spacing when enabled), one cluster, 1 kg, no quadratic mode, 16384 particles at most.</summary>
        public static SoftBodyBuildSettings Default => new SoftBodyBuildSettings
        {
            WeldTolerance = MeshWelding.DefaultRelativeTolerance,
            WeldDistance = 0f,
            AddInteriorParticles = false,
            InteriorSpacing = 0f,
            ClusterSize = 0f,
            TotalMass = 1f,
            BuildQuadratic = false,
            MaxParticles = DefaultMaxParticles,
        };
    }
}
