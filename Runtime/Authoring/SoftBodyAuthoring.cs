using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEngine;
using UnityEngine.Serialization;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Makes this GameObject's mesh (from its MeshFilter) a soft body simulated by the chosen <see cref="method"/>.
    /// Shape matching: at bake time the mesh, scaled by the Transform, is welded into surface particles, optionally
    /// filled with interior particles, grouped into overlapping clusters and stored in a blob. Mass-spring and FEM: the
    /// closed mesh is filled with tetrahedra on a lattice of <see cref="tetResolution"/> cells along its longest side,
    /// the render vertices are embedded in them, and the springs or elements are built from the physical material
    /// (<see cref="Material"/>). At runtime the body starts at this GameObject's world position and rotation, as a root
    /// entity (not parented) at scale 1.
    /// Every field is checked by <see cref="SoftBodyAuthoringValidation"/>; a body with an error is not baked.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("Soft Body Dynamics/Soft Body")]
    public sealed class SoftBodyAuthoring : MonoBehaviour, ISerializationCallbackReceiver
    {
        // The defaults: the Jelly preset's material values (so a new component holds the preset it names), and the
        // solver's own defaults for everything else. The tooltips quote them.
        static readonly ShapeMatchingMaterial k_Jelly = SoftBodyPresets.Jelly;
        static readonly ShapeMatchingParameters k_Solver = ShapeMatchingParameters.Default;

        // ---- Method

        [Tooltip("What holds the body together. Shape Matching: particles pulled toward best-fit cluster shapes (cheapest, "
                 + "stable at any step). Mass Spring: springs along the edges of tetrahedra that fill the mesh. FEM: linear "
                 + "tetrahedral finite elements (the accurate reference). Mass Spring and FEM need a closed mesh. Default Shape Matching.")]
        public SoftBodyMethod method = SoftBodyMethod.ShapeMatching;

        // ---- Preset

        [Tooltip("Material preset: sets the physical material (Young's modulus, Poisson ratio, density, damping ratio; used by "
                 + "Mass Spring and FEM) and the shape-matching values (Mode, Frequency, Damping Ratio, Beta, Plasticity), Friction "
                 + "and Restitution. Editing one of those by hand switches to Custom.")]
        public SoftBodyPreset preset = SoftBodyPreset.Jelly;

        /// <summary>The preset whose values the fields hold (detects a newly picked preset in OnValidate).</summary>
        [SerializeField, HideInInspector]
        internal SoftBodyPreset appliedPreset = SoftBodyPreset.Jelly;

        // ---- Shape (bake-time build settings)

        [Tooltip("Size of the overlapping shape-matching regions (m). 0, or at least the mesh's longest side, makes one cluster "
                 + "of the whole body: it keeps its overall shape but cannot bend. Smaller clusters bend and wobble locally; "
                 + "about a quarter of the body is a good start. Default 0.4 m.")]
        [Min(0f)]
        public float clusterSize = 0.4f;

        [Tooltip("Fill a closed mesh with particles on a cubic lattice, so the body has volume and its clusters are not hollow "
                 + "shells. Open meshes get a warning and no interior particles. Default on.")]
        public bool addInteriorParticles = true;

        [Tooltip("Distance between interior particles (m). 0 picks one eighth of the mesh's longest side. Smaller: more "
                 + "particles, better volume, slower bake and simulation. Default 0 (automatic).")]
        [Min(0f)]
        public float interiorSpacing = 0f;

        [Tooltip("Render vertices closer than this fraction of the mesh's bounds diagonal become one particle (dimensionless). "
                 + "The default 1e-5 merges the copies a mesh splits for UV seams and hard edges. Ignored when Weld Distance > 0.")]
        [Min(0f)]
        public float weldTolerance = MeshWelding.DefaultRelativeTolerance;

        [Tooltip("Absolute weld distance (m). Above 0 it replaces Weld Tolerance: use it to merge vertices a modelling tool "
                 + "left slightly apart. Default 0 (use the relative tolerance).")]
        [Min(0f)]
        public float weldDistance = 0f;

        [Tooltip("Mass of the whole body (kg), spread evenly over all particles. Default 1 kg.")]
        [Min(0f)]
        public float totalMass = SoftBodyBuildSettings.Default.TotalMass;

        // ---- Material

        [Tooltip("Rigid: rotation only (stiff, cheapest). Linear: also shear and stretch, blended by Beta. "
                 + "Quadratic: also bending and twisting within one cluster (costs 324 bytes per cluster). Default Linear.")]
        public ShapeMatchingMode mode = k_Jelly.Mode;

        [Tooltip("Natural frequency (Hz) at which the body springs back to its shape: a time, so the material is the same at "
                 + "any frame rate and substep count. 2 = soft jelly, 20 = firm rubber. Shear and stretch the goals follow "
                 + "(Beta) wobble at Frequency·√(1 − Beta). Jelly 7.7 Hz.")]
        [Range(0f, 100f)]
        public float frequency = k_Jelly.Frequency;

        [Tooltip("Damping ratio ζ of the wobble (dimensionless): 0 = wobbles forever, 0.1 = many visible wobbles, 1 = returns "
                 + "without overshoot. Falling and spinning are never damped. Jelly 0.13.")]
        [Range(0f, 2f)]
        public float dampingRatio = k_Jelly.DampingRatio;

        [Tooltip("β: how much of the linear or quadratic deformation the goal shape keeps (0–1; above 0.99 acts as 0.99). "
                 + "0 = rigid goals, near 1 = the body shears and stretches with little resistance. Unused in Rigid mode. Jelly 0.6.")]
        [Range(0f, 1f)]
        public float beta = k_Jelly.Beta;

        [Tooltip("Fewest simulation substeps per fixed step (1–64). The solver adds substeps until Frequency·2π·substep ≤ "
                 + "Max Substep Phase. More: stiffer contacts and less tunnelling, at proportional cost. Default 4.")]
        [Range(ShapeMatchingParameterValidation.MinSubsteps, ShapeMatchingParameterValidation.MaxSubsteps)]
        public int substeps = k_Solver.Body.Substeps;

        [Tooltip("Largest phase ω·h (rad) of one substep; the solver uses as many substeps as that needs (up to 64). It bounds "
                 + "the error of the resting sag (about ζ·ω·h + (ω·h)²/12 relative); frequency and damping are exact at any step. "
                 + "Smaller: more accurate, slower. Default 0.5 rad.")]
        [Min(0.001f)]
        public float maxSubstepPhase = k_Solver.MaxSubstepPhase;

        [Tooltip("Uniform acceleration on every particle (m/s²): gravity plus any wind-like force per mass. Default (0, −9.81, 0).")]
        public Vector3 gravity = UnityMathConversions.ToVector3(k_Solver.Body.Acceleration);

        // ---- Physical material (mass-spring and FEM)

        [Tooltip("Young's modulus E (Pa): stress per unit strain; how stiff the material is, whatever the method. 1e4 = soft "
                 + "jelly, 1e6 = rubber. Jelly 1e4 Pa.")]
        [Min(0f)]
        public float youngsModulus = ElasticMaterial.Jelly.YoungsModulus;

        [Tooltip("Poisson ratio ν (dimensionless, 0 to below 0.5): how much the material narrows when stretched; near 0.5 it "
                 + "keeps its volume. Jelly 0.45.")]
        [Range(0f, 0.499f)]
        public float poissonRatio = ElasticMaterial.Jelly.PoissonRatio;

        [Tooltip("Density ρ (kg/m³): the body's mass is ρ times the volume of its tetrahedra. Water 1000. Jelly 1000 kg/m³.")]
        [Min(0f)]
        public float density = ElasticMaterial.Jelly.Density;

        [Tooltip("Damping ratio ζ of the body's slowest deformation mode (dimensionless): 0 = rings forever, 1 = critically "
                 + "damped. Jelly 0.1.")]
        [Min(0f)]
        public float materialDampingRatio = ElasticMaterial.Jelly.DampingRatio;

        // ---- Tetrahedra (mass-spring and FEM)

        [Tooltip("Lattice cells along the mesh's longest side (1–128). Each kept cell becomes 6 tetrahedra; cost grows with "
                 + "the cube of it (8: about 500 nodes for a compact body). More: finer deformation and a closer volume, slower "
                 + "bake and step. Default 8.")]
        [Range(TetrahedralizationSettings.MinResolution, TetrahedralizationSettings.MaxResolution)]
        public int tetResolution = TetrahedralizationSettings.DefaultResolution;

        // ---- Mass-spring

        [Tooltip("How the springs advance in time. Symplectic Euler and Verlet: cheapest, stable only below the stable step "
                 + "(the inspector warns). Implicit Euler: stable at any step, damps fast wobble. XPBD: stable at any step, "
                 + "converges with substeps. Default Symplectic Euler.")]
        public MassSpringIntegrator massSpringIntegrator = MassSpringParameters.Default.Integrator;

        [Tooltip("Add a bending spring across every pair of tetrahedra sharing a face (stiffer against hinging). The material "
                 + "calibration accounts for them. Default off.")]
        public bool bendingSprings = MassSpringBuildSettings.Default.BendingSprings;

        // ---- FEM

        [Tooltip("Constitutive model. Co-Rotational: linear elasticity with element rotations removed (exact for large "
                 + "rotations, linear in stretch). Neo-Hookean: non-linear, stiffens under compression, recovers from "
                 + "inversion. Default Co-Rotational.")]
        public FemMaterialModel femModel = FemParameters.Default.Model;

        [Tooltip("How the elements advance in time. Symplectic Euler: explicit, stable only below the stable step (the "
                 + "inspector warns). Implicit Euler: both models, stable at any step. XPBD: Neo-Hookean only, stable at "
                 + "any step. An unsupported pair falls back to Symplectic Euler. Default from the solver.")]
        public FemIntegrator femIntegrator = FemParameters.Default.Integrator;

        [Tooltip("Element order. Linear: 4-node tetrahedra, cheapest per element but stiff in bending (a thin part needs many "
                 + "elements across). Quadratic: 10-node tetrahedra (a node on every edge), bending without locking: on a "
                 + "clamped beam one element across sags within 10 % and two within 3 % of the converged value. Default Linear.")]
        public FemElementOrder femElementOrder = FemBuildSettings.Default.Order;

        [Tooltip("Bake a sparse Cholesky factor of the rest system as the implicit solver's preconditioner (implicit Euler "
                 + "only): a few iterations per substep instead of hundreds, for memory of about 3 × bandwidth floats per node "
                 + "(the bake reports its size). Built for the assumed fixed step (1/60 s) over Substeps. Default off.")]
        public bool femRestFactor = FemBuildSettings.Default.RestFactor;

        // ---- Plasticity

        [Tooltip("Strain (‖S − I‖, dimensionless) above which the rest shape starts to flow. 0 with Creep 0 = perfectly elastic. "
                 + "Clay 0.05.")]
        [Min(0f)]
        public float plasticYield = k_Jelly.Plasticity.Yield;

        [Tooltip("Rate (1/s) at which the rest shape follows the deformation while yielding. 0 = elastic. Clay 10.")]
        [Min(0f)]
        public float plasticCreep = k_Jelly.Plasticity.Creep;

        [Tooltip("Largest plastic strain (dimensionless) the rest shape may accumulate. 0 = elastic. Clay 0.6.")]
        [Min(0f)]
        public float plasticMaxDeformation = k_Jelly.Plasticity.MaxDeformation;

        // ---- Collisions

        [Tooltip("Radius of every particle against colliders (m). Default 0.02 m.")]
        [Min(0f)]
        public float particleRadius = k_Solver.Body.ParticleRadius;

        [Tooltip("Coulomb friction coefficient μ against colliders (0 = ice, about 1 = rubber on concrete). Jelly 0.4.")]
        [Min(0f)]
        public float friction = k_Jelly.Friction;

        [Tooltip("Restitution e of contacts (0–1): 0 = no bounce, 1 = perfectly elastic bounce. Jelly 0.2.")]
        [Range(0f, 1f)]
        public float restitution = k_Jelly.Restitution;

        [Tooltip("Speed (m/s) at which particles that start a step inside a collider are pushed out: a body spawned inside a "
                 + "collider leaves it at this speed, whole and along one direction, instead of being shot out. Default 2 m/s.")]
        [Min(0.001f)]
        public float maxDepenetrationSpeed = k_Solver.Body.MaxDepenetrationSpeed;

        // ---- Sleep

        [Tooltip("The body sleeps once every particle has stayed slower than this for Sleep Delay (m/s). 0 = never sleeps. Default 0.02 m/s.")]
        [Min(0f)]
        public float sleepSpeed = k_Solver.Body.SleepSpeed;

        [Tooltip("Time every particle must stay below Sleep Speed before the body sleeps (s). Default 1 s.")]
        [Min(0f)]
        public float sleepDelay = k_Solver.Body.SleepDelay;

        // ---- Limits

        [Tooltip("Most particles this body may have. Baking fails above it: simplify the mesh or raise Interior Spacing. Default 16384.")]
        [Min(1f)]
        public int maxParticles = SoftBodyBuildSettings.DefaultMaxParticles;

        [Tooltip("Speed above which the state counts as broken and the body is reset to its rest shape (m/s). Default 500 m/s.")]
        [Min(0f)]
        public float maxSpeed = k_Solver.Body.MaxSpeed;

        [Tooltip("Rotation-extraction iterations per cluster and substep (warm-started; 2–3 usually suffice). Default 20 (a cap, rarely reached).")]
        [Range(1, 100)]
        public int rotationIterations = k_Solver.RotationIterations;

        /// <summary>How the mesh becomes particles and clusters (bake time).</summary>
        public SoftBodyBuildSettings BuildSettings => new SoftBodyBuildSettings
        {
            WeldTolerance = weldTolerance,
            WeldDistance = weldDistance,
            AddInteriorParticles = addInteriorParticles,
            InteriorSpacing = interiorSpacing,
            ClusterSize = clusterSize,
            TotalMass = totalMass,
            BuildQuadratic = mode == ShapeMatchingMode.Quadratic,
            MaxParticles = maxParticles,
        };

        /// <summary>The physical material of the mass-spring and FEM methods.</summary>
        public ElasticMaterial Material => new ElasticMaterial(youngsModulus, poissonRatio, density, materialDampingRatio);

        /// <summary>How the mesh becomes tetrahedra for the mass-spring and FEM methods (bake time); the weld settings are the Shape section's.</summary>
        public TetrahedralizationSettings TetrahedralizationSettings => new TetrahedralizationSettings
        {
            Resolution = tetResolution,
            MaxNodes = maxParticles,
            WeldTolerance = weldTolerance,
            WeldDistance = weldDistance,
        };

        /// <summary>The springs the mass-spring network gets besides the structural ones (bake time).</summary>
        public MassSpringBuildSettings MassSpringBuildSettings => new MassSpringBuildSettings { BendingSprings = bendingSprings };

        /// <summary>The mass-spring solver parameters (runtime): the shared body settings and the integrator.</summary>
        public MassSpringParameters MassSpringParameters
        {
            get
            {
                MassSpringParameters p = MassSpringParameters.Default;
                p.Integrator = massSpringIntegrator;
                p.Body = BodySettings;
                return p;
            }
        }

        /// <summary>The finite-element solver parameters (runtime): the shared body settings, model and integrator.</summary>
        public FemParameters FemParameters
        {
            get
            {
                FemParameters p = FemParameters.Default;
                p.Model = femModel;
                p.Integrator = femIntegrator;
                p.Body = BodySettings;
                return p;
            }
        }

        /// <summary>How the finite-element model is baked: element order, rest factor (for the assumed fixed step over the substeps).</summary>
        public FemBuildSettings FemBuildSettings => new FemBuildSettings
        {
            Model = femModel,
            Order = femElementOrder,
            RestFactor = femRestFactor,
            Substep = SoftBodyAuthoringValidation.AssumedFixedTimeStep / System.Math.Max(1, substeps),
            DampingFrequency = 0f,
        };

        /// <summary>The shape-matching solver parameters (runtime).</summary>
        public ShapeMatchingParameters Parameters => new ShapeMatchingParameters
        {
            Mode = mode,
            Frequency = frequency,
            DampingRatio = dampingRatio,
            Beta = beta,
            Body = BodySettings,
            MaxSubstepPhase = maxSubstepPhase,
            Plasticity = new PlasticityParameters { Yield = plasticYield, Creep = plasticCreep, MaxDeformation = plasticMaxDeformation },
            RotationIterations = rotationIterations,
        };

        /// <summary>The settings every method shares (gravity, substeps, contacts, sleep, guard), from the inspector.</summary>
        public ParticleBodySettings BodySettings => new ParticleBodySettings
        {
            Acceleration = UnityMathConversions.ToFloat3(gravity),
            Substeps = substeps,
            MaxDepenetrationSpeed = maxDepenetrationSpeed,
            ParticleRadius = particleRadius,
            Friction = friction,
            Restitution = restitution,
            SleepSpeed = sleepSpeed,
            SleepDelay = sleepDelay,
            MaxSpeed = maxSpeed,
        };

        /// <summary>
        /// The scale baked into the rest shape: the magnitude of the Transform's lossy scale. Soft bodies are simulated
        /// and drawn at scale 1, so a scaled GameObject becomes a body of the size it shows in the Scene view.
        /// </summary>
        public float3 BakedScale => math.abs(UnityMathConversions.ToFloat3(transform.lossyScale));

        /// <summary>Writes <paramref name="value"/>'s material values into this component and selects it.</summary>
        public void ApplyPreset(SoftBodyPreset value) => SoftBodyPresets.Apply(this, value);

        // ---- Migration from 0.2 (per-frame stiffness α and a damping rate), read from the old field names.

        /// <summary>0.2's stiffness α of a component saved by that version; −1 once migrated or for a new component.</summary>
        [SerializeField, HideInInspector, FormerlySerializedAs("stiffness")]
        public float legacyStiffness = -1f;

        /// <summary>0.2's damping rate (1/s) of a component saved by that version; −1 once migrated or for a new component.</summary>
        [SerializeField, HideInInspector, FormerlySerializedAs("damping")]
        public float legacyDamping = -1f;

        void ISerializationCallbackReceiver.OnBeforeSerialize() { }

        /// <summary>
        /// A component saved by 0.2 keeps its material (<see cref="SoftBodyPresets.MigrateLegacyStiffness"/>); one saved before
        /// the physical material existed takes its preset's (<see cref="SoftBodyPresets.MigrateElasticMaterial"/>).
        /// </summary>
        void ISerializationCallbackReceiver.OnAfterDeserialize()
        {
            SoftBodyPresets.MigrateLegacyStiffness(this);
            SoftBodyPresets.MigrateElasticMaterial(this);
        }

        void OnValidate() => SoftBodyPresets.Synchronize(this);
    }
}
