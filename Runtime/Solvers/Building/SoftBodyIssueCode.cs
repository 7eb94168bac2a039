namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One vocabulary for everything that can be wrong with a soft body's mesh, build settings or
    /// solver parameters, shared by the pure builder, the Unity authoring and the editor. The values
    /// are stable (they may be stored); new codes take new numbers.
    /// </summary>
    public enum SoftBodyIssueCode
    {
        // ---- mesh source (detected by the Unity-side authoring only)

        /// <summary>No mesh is assigned.</summary>
        NoMesh = 1,
        /// <summary>The mesh's data is not readable on the CPU (Read/Write disabled in its import settings).</summary>
        MeshNotReadable = 2,

        // ---- mesh content

        /// <summary>The mesh has no vertices or no triangles.</summary>
        EmptyMesh = 10,
        /// <summary>A vertex position is NaN or infinite. Index: the first such vertex.</summary>
        NonFiniteVertex = 11,
        /// <summary>The triangle index buffer's length is not a multiple of 3.</summary>
        TriangleCountNotMultipleOfThree = 12,
        /// <summary>A triangle refers to a vertex that does not exist. Index: the first such triangle.</summary>
        TriangleIndexOutOfRange = 13,
        /// <summary>All vertices coincide (zero-size bounds), or welding merged them all into one particle.</summary>
        ZeroSize = 14,
        /// <summary>Warning: triangles with zero area or a repeated vertex after welding. Index: the first such triangle.</summary>
        DegenerateTriangles = 15,
        /// <summary>Warning: edges shared by more than two triangles. Index: the first triangle using such an edge.</summary>
        NonManifoldEdges = 16,
        /// <summary>Warning: the mesh has boundary edges, so it has no inside; interior particles were skipped. Index: the first boundary triangle.</summary>
        NotClosed = 17,
        /// <summary>Warning: neighbouring triangles are wound in opposite senses, so inside and outside are undefined; interior particles were skipped. Index: the first such triangle.</summary>
        InconsistentWinding = 18,

        // ---- build settings

        /// <summary>The relative or absolute weld tolerance is negative, NaN or infinite.</summary>
        WeldToleranceInvalid = 30,
        /// <summary>The total mass is zero, negative, NaN or infinite.</summary>
        TotalMassNotPositive = 31,
        /// <summary>The cluster size is negative, NaN, infinite, or so small that the cluster lattice cannot be indexed.</summary>
        ClusterSizeInvalid = 32,
        /// <summary>The interior spacing is negative, NaN, infinite, or so small that the lattice is unreasonably large.</summary>
        InteriorSpacingInvalid = 33,
        /// <summary>The particle limit is not positive.</summary>
        MaxParticlesInvalid = 34,
        /// <summary>The body would have more particles than the limit.</summary>
        TooManyParticles = 35,
        /// <summary>Warning: clusters with fewer than 4 particles or a planar rest shape had to be kept, because they alone cover some particles.</summary>
        WeakClusters = 36,

        // ---- shape-matching parameters

        /// <summary>A parameter is NaN or infinite.</summary>
        ParameterNotFinite = 60,
        /// <summary>The shape-matching mode is not one of the defined values.</summary>
        ModeInvalid = 61,
        /// <summary>Frequency below 0 Hz or above <see cref="ShapeMatchingParameters.MaxFrequency"/>.</summary>
        FrequencyOutOfRange = 62,
        /// <summary>Warning: frequency 0 Hz, so the body will not hold its shape.</summary>
        FrequencyZero = 63,
        /// <summary>β outside [0, 1].</summary>
        BetaOutOfRange = 64,
        /// <summary>Damping ratio below 0 or above <see cref="ShapeMatchingParameters.MaxDampingRatio"/>.</summary>
        DampingRatioOutOfRange = 65,
        /// <summary>Substeps outside 1..64.</summary>
        SubstepsOutOfRange = 66,
        /// <summary>Particle radius not positive, or implausibly large.</summary>
        ParticleRadiusInvalid = 67,
        /// <summary>Friction below 0.</summary>
        FrictionNegative = 68,
        /// <summary>Restitution outside [0, 1].</summary>
        RestitutionOutOfRange = 69,
        /// <summary>A plasticity field (yield, creep, maximum deformation) below 0.</summary>
        PlasticityNegative = 70,
        /// <summary>Sleep speed below 0.</summary>
        SleepSpeedNegative = 71,
        /// <summary>Sleep delay below 0.</summary>
        SleepDelayNegative = 72,
        /// <summary>Maximum speed not positive.</summary>
        MaxSpeedNotPositive = 73,
        /// <summary>Rotation iterations below 1.</summary>
        RotationIterationsInvalid = 74,
        /// <summary>Warning: β above <see cref="ShapeMatchingParameters.MaxBeta"/> acts as <see cref="ShapeMatchingParameters.MaxBeta"/>.</summary>
        BetaLimited = 75,
        /// <summary>Maximum substep phase not positive.</summary>
        MaxSubstepPhaseNotPositive = 76,
        /// <summary>Maximum depenetration speed not positive.</summary>
        MaxDepenetrationSpeedNotPositive = 77,
        /// <summary>Warning: plasticity is set but the mode is Rigid, whose goals cannot hold a deformed rest shape: it has no effect.</summary>
        PlasticityIgnoredInRigidMode = 78,

        // Colliders (SoftBodyColliderAuthoring).
        /// <summary>The collider shape is not one of plane, sphere, box or capsule.</summary>
        ColliderShapeInvalid = 100,
        /// <summary>A collider size, radius, height or centre is NaN or infinite.</summary>
        ColliderSizeNotFinite = 101,
        /// <summary>A collider box size or radius is zero or negative, or a capsule height is negative.</summary>
        ColliderSizeNotPositive = 102,
        /// <summary>The collider transform's position, rotation or scale is NaN or infinite.</summary>
        ColliderTransformNotFinite = 103,
        /// <summary>A scale factor the collider shape depends on is zero: it would have no volume.</summary>
        ColliderScaleZero = 104,
        /// <summary>Warning: a sphere (or a capsule across its axis) is scaled non-uniformly; the largest factor is used.</summary>
        ColliderNonUniformScale = 105,
        /// <summary>Warning: a capsule's height is less than its diameter, so it is a sphere.</summary>
        ColliderCapsuleShorterThanDiameter = 106,

        // ---- tetrahedralisation (LatticeTetrahedralizer) and tetrahedral meshes (TetrahedralMeshChecks)

        /// <summary>TetrahedralizationSettings.Resolution outside 1..128.</summary>
        TetResolutionOutOfRange = 160,
        /// <summary>TetrahedralizationSettings.MaxNodes is not positive.</summary>
        MaxNodesInvalid = 161,
        /// <summary>The volume mesh would have more nodes than TetrahedralizationSettings.MaxNodes.</summary>
        TooManyNodes = 162,
        /// <summary>The surface has boundary or non-manifold edges (after welding), so it encloses no volume to fill with tetrahedra. Index: the first such triangle.</summary>
        VolumeMeshNotClosed = 163,
        /// <summary>Neighbouring triangles are wound in opposite senses, so the inside of the volume is undefined. Index: the first such triangle.</summary>
        VolumeMeshInconsistentWinding = 164,
        /// <summary>A tetrahedral mesh has no nodes or no tetrahedra.</summary>
        EmptyTetrahedralMesh = 165,
        /// <summary>A tetrahedral-mesh node position is NaN or infinite. Index: the first such node.</summary>
        NonFiniteNode = 166,
        /// <summary>A tetrahedron refers to a node that does not exist. Index: the first such tetrahedron.</summary>
        TetrahedronIndexOutOfRange = 167,
        /// <summary>A tetrahedron has zero volume (a repeated node, or flat to float32 precision). Index: the first such tetrahedron.</summary>
        TetrahedronDegenerate = 168,
        /// <summary>A tetrahedron has negative volume: its nodes are not positively oriented. Index: the first such tetrahedron.</summary>
        TetrahedronInverted = 169,
        /// <summary>Warning: tetrahedra of poor shape (quality below TetrahedralMeshChecks.SliverQuality). Index: the worst one.</summary>
        TetrahedronSliver = 170,
        /// <summary>Warning: nodes that no tetrahedron uses (they get no mass and move freely). Index: the first such node.</summary>
        UnusedNodes = 171,

        // Mass-spring networks (MassSpringNetwork.Build, MassSpringCalibration).
        /// <summary>The tetrahedral mesh has no nodes or no tetrahedra.</summary>
        MassSpringEmptyMesh = 120,
        /// <summary>A tetrahedron refers to a node that does not exist. Index: the first such tetrahedron.</summary>
        MassSpringTetrahedronIndexOutOfRange = 121,
        /// <summary>A node position is NaN or infinite. Index: the first such node.</summary>
        MassSpringNonFiniteNode = 122,
        /// <summary>
        /// Warning: an edge has zero rest length (a tetrahedron repeats a node, or two nodes coincide). Its spring is
        /// left out: it has no direction to act along. Index: the first such tetrahedron.
        /// </summary>
        MassSpringZeroLengthEdge = 123,
        /// <summary>
        /// Warning: a tetrahedron appears twice (the same four nodes, e.g. doubled back-to-back geometry). The copy is
        /// merged: its edges and volume count once. Index: the first copy.
        /// </summary>
        MassSpringDuplicateTetrahedron = 124,
        /// <summary>Warning: a tetrahedron has zero volume; it adds no stiffness or mass. Index: the first such tetrahedron.</summary>
        MassSpringDegenerateTetrahedron = 125,
        /// <summary>Warning: a node belongs to no tetrahedron: it gets no spring and the mean mass, and falls freely. Index: the first such node.</summary>
        MassSpringIsolatedNode = 126,
        /// <summary>No spring is left after the zero-length edges were removed.</summary>
        MassSpringNoSprings = 127,
        /// <summary>The material is invalid (E ≤ 0, ν outside [0, 0.5), ρ ≤ 0 or ζ &lt; 0, or not finite).</summary>
        MassSpringMaterialInvalid = 128,
        /// <summary>
        /// Warning: the springs are too stiff for the substep of an explicit integrator (symplectic Euler, Verlet):
        /// h exceeds <see cref="MassSpringStability.MaxStableStep"/> and the body would blow up (the guard resets it).
        /// Use more substeps, softer springs, or the ImplicitEuler or Xpbd integrator.
        /// </summary>
        MassSpringStepAboveStableLimit = 129,
        /// <summary>The mass-spring integrator is not one of the defined values.</summary>
        MassSpringIntegratorInvalid = 130,
        /// <summary>Mass-spring substeps (1–256), XPBD iterations (1–64) or CG iterations (1–1000) out of range.</summary>
        MassSpringIterationsOutOfRange = 131,
        /// <summary>The mass-spring conjugate-gradient tolerance is not a finite relative residual above 0 and below 1.</summary>
        MassSpringCgToleranceInvalid = 132,

        // ---- finite-element model (FemModelData.Create)

        /// <summary>The tetrahedral mesh has no nodes or no tetrahedra.</summary>
        FemMeshEmpty = 140,
        /// <summary>A tetrahedron refers to a node that does not exist, or repeats a node. Index: the tetrahedron.</summary>
        FemTetrahedronNodeInvalid = 141,
        /// <summary>A tetrahedron has zero volume at rest (its four nodes are coplanar, or a position is not finite). Index: the tetrahedron.</summary>
        FemTetrahedronDegenerate = 142,
        /// <summary>A tetrahedron is inverted at rest (negative signed volume: nodes in the wrong order). Index: the tetrahedron.</summary>
        FemTetrahedronInverted = 143,
        /// <summary>
        /// Warning: a sliver tetrahedron, quality 6√2 V / l_rms³ below <see cref="FemModelData.SliverQuality"/> (1 for a
        /// regular tetrahedron): it stiffens the body and shortens the explicit stable step. Index: the tetrahedron.
        /// </summary>
        FemTetrahedronSliver = 144,
        /// <summary>Warning: a node is used by no tetrahedron; it has no stiffness and is held in place (pinned). Index: the node.</summary>
        FemNodeUnused = 145,
        /// <summary>The material is invalid (E ≤ 0, ν outside [0, 0.5), ρ ≤ 0 or ζ &lt; 0, or a value not finite).</summary>
        FemMaterialInvalid = 146,
        /// <summary>The pinned-node list's length differs from the node count.</summary>
        FemPinnedCountMismatch = 147,

        // ---- Authoring of every method (SoftBodyAuthoringValidation)

        /// <summary>The authoring component's method is not one of Shape Matching, Mass Spring or FEM.</summary>
        MethodInvalid = 190,
        /// <summary>
        /// Warning: the finite elements are too stiff for the substep of the explicit integrator (symplectic Euler, or an
        /// unsupported model/integrator pair that falls back to it): h exceeds <c>FemStability.MaxStableStep</c>. Use more
        /// substeps, a softer material, a lower resolution, or an unconditionally stable integrator.
        /// </summary>
        FemStepAboveStableLimit = 191,
        /// <summary>The FEM material model or integrator is not one of the defined values.</summary>
        FemModelInvalid = 192,
        /// <summary>FEM substeps (1–256), XPBD iterations (1–64), CG iterations (1–10000) or Newton iterations (1–16) out of range.</summary>
        FemIterationsOutOfRange = 193,
        /// <summary>The conjugate-gradient tolerance is not a finite relative residual above 0 and below 1.</summary>
        FemCgToleranceInvalid = 194,
        /// <summary>The Rayleigh damping reference frequency is negative or not finite (0 = the model's estimate).</summary>
        FemDampingFrequencyInvalid = 195,
        /// <summary>The FEM element order is not Linear or Quadratic.</summary>
        FemElementOrderInvalid = 196,
        /// <summary>Warning: the rest factor of the implicit step could not be built; the body uses block-Jacobi preconditioning.</summary>
        FemRestFactorFailed = 197,

        // ---- Fluids (FluidValidation)

        /// <summary>The particle spacing is not a positive finite length (m).</summary>
        FluidSpacingInvalid = 200,
        /// <summary>The kernel radius ratio h/Δx is outside 1.5–4 (too few or far too many neighbours).</summary>
        FluidKernelRatioInvalid = 201,
        /// <summary>The rest density is not a positive finite value (kg/m³).</summary>
        FluidDensityInvalid = 202,
        /// <summary>The speed of sound is not positive and finite, or absurd (above 1500 m/s, the real value for water, which would need thousands of substeps).</summary>
        FluidSpeedOfSoundInvalid = 203,
        /// <summary>The domain box is not finite or is smaller than one kernel radius along some axis.</summary>
        FluidDomainInvalid = 204,
        /// <summary>The domain holds more grid cells than the grid allows (<c>FluidGrid.MaxCells</c>): the cells get coarser and the neighbour search slower. Shrink the domain or increase the spacing.</summary>
        FluidGridTooLarge = 205,
        /// <summary>The particle budget is not positive.</summary>
        FluidBudgetInvalid = 206,
        /// <summary>Viscosity, cohesion, separation, alignment or surface tension is negative or not finite.</summary>
        FluidCoefficientInvalid = 207,
        /// <summary>Warning: the CFL limit asks for more substeps per 1/60 s frame than the cap allows even for a fluid at rest; the step will run capped (and report it). Lower the speed of sound or raise the cap.</summary>
        FluidSubstepCapTooLow = 208,

        // ---- Fluid taps and drains (FluidTapValidation)

        /// <summary>The tap's shape is not one of point, disc, sphere or box.</summary>
        FluidTapShapeInvalid = 220,
        /// <summary>The tap's radius or half extents are negative or not finite (m).</summary>
        FluidTapSizeInvalid = 221,
        /// <summary>The tap's rotation is not a finite non-zero quaternion (no flow direction).</summary>
        FluidTapDirectionInvalid = 222,
        /// <summary>The cone angle is outside [0°, 180°).</summary>
        FluidTapConeInvalid = 223,
        /// <summary>The speed or its random range is negative or not finite (m/s), or the range exceeds the speed.</summary>
        FluidTapSpeedInvalid = 224,
        /// <summary>The rate (particles/s) or volume flow (L/s) is negative or not finite.</summary>
        FluidTapRateInvalid = 225,
        /// <summary>The pulse period is negative or the duty cycle is outside (0, 1].</summary>
        FluidTapPulseInvalid = 226,
        /// <summary>Duration, start delay or prewarm is negative or not finite (s).</summary>
        FluidTapTimingInvalid = 227,
        /// <summary>A burst has a negative time or count, fewer than one cycle, or several cycles with no positive interval.</summary>
        FluidTapBurstInvalid = 228,
        /// <summary>The lifetime or its random range is negative or not finite (s), or the range exceeds the lifetime.</summary>
        FluidTapLifetimeInvalid = 229,
        /// <summary>The steady-state alive count (rate × lifetime, with bursts) exceeds the fluid's particle budget: the tap would stall at the budget.</summary>
        FluidTapOverBudget = 230,
        /// <summary>Warning: the tap emits nothing (zero rate and no bursts).</summary>
        FluidTapSilent = 231,
        /// <summary>The drain's shape is invalid (non-positive or non-finite size).</summary>
        FluidDrainInvalid = 232,
        /// <summary>A fluid with Entities storage has no particle prefab to instantiate.</summary>
        FluidPrefabMissing = 233,
        /// <summary>A fluid asks for the GPU but no compute shader is assigned: it runs on the CPU.</summary>
        FluidComputeShaderMissing = 234,
        /// <summary>A fluid with Entities storage asks for the GPU: one entity per particle needs the CPU path.</summary>
        FluidGpuNeedsPackedStorage = 235,
        /// <summary>The GPU read-back interval is below one frame.</summary>
        FluidReadbackIntervalInvalid = 236,
        /// <summary>The fluid surface has no fluid to draw, or its sphere radius (in particle spacings) is not positive and finite.</summary>
        FluidSurfaceInvalid = 237,
        /// <summary>Warning: a value of the fluid surface's custom look was out of range and replaced.</summary>
        FluidSurfaceLookReplaced = 238,
        /// <summary>Warning: the sphere radius leaves gaps between neighbouring particles (below 0.5 spacing) or blurs the fluid (above 2).</summary>
        FluidSurfaceRadiusUnusual = 239,
        /// <summary>Warning: a periodic axis of the fluid's domain is shorter than three kernel radii, so it is not periodic.</summary>
        FluidPeriodicAxisTooShort = 241,
        /// <summary>Warning: the fluid's implicit viscosity needs more Jacobi iterations than a substep runs to converge at its substep (a steady flow then runs too fast).</summary>
        FluidViscosityUnresolved = 242,
        /// <summary>Warning: a fluid's wall friction μ or no-slip share (colliders or domain faces) is outside [0, 1] or NaN; the step clamps it.</summary>
        FluidWallShareOutOfRange = 243,
    }
}
