using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEngine;
using UnityEngine.Serialization;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Makes this GameObject's mesh (from its MeshFilter) a shape-matching soft body. At bake time the mesh, scaled
    /// by the Transform, is welded into surface particles, optionally filled with interior particles, grouped into
    /// overlapping clusters and stored in a blob; at runtime the body starts at this GameObject's world position and
    /// rotation, as a root entity (not parented) at scale 1.
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

        // ---- Preset

        [Tooltip("Material preset: sets Mode, Frequency, Damping Ratio, Beta, Plasticity, Friction and Restitution. "
                 + "Editing one of those by hand switches to Custom.")]
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
        public int substeps = k_Solver.Substeps;

        [Tooltip("Largest phase ω·h (rad) of one substep; the solver uses as many substeps as that needs (up to 64). It bounds "
                 + "the error of the resting sag (about ζ·ω·h + (ω·h)²/12 relative); frequency and damping are exact at any step. "
                 + "Smaller: more accurate, slower. Default 0.5 rad.")]
        [Min(0.001f)]
        public float maxSubstepPhase = k_Solver.MaxSubstepPhase;

        [Tooltip("Uniform acceleration on every particle (m/s²): gravity plus any wind-like force per mass. Default (0, −9.81, 0).")]
        public Vector3 gravity = UnityMathConversions.ToVector3(k_Solver.Acceleration);

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
        public float particleRadius = k_Solver.ParticleRadius;

        [Tooltip("Coulomb friction coefficient μ against colliders (0 = ice, about 1 = rubber on concrete). Jelly 0.4.")]
        [Min(0f)]
        public float friction = k_Jelly.Friction;

        [Tooltip("Restitution e of contacts (0–1): 0 = no bounce, 1 = perfectly elastic bounce. Jelly 0.2.")]
        [Range(0f, 1f)]
        public float restitution = k_Jelly.Restitution;

        [Tooltip("Speed (m/s) at which particles that start a step inside a collider are pushed out: a body spawned inside a "
                 + "collider leaves it at this speed instead of being shot out. Default 2 m/s.")]
        [Min(0.001f)]
        public float maxDepenetrationSpeed = k_Solver.MaxDepenetrationSpeed;

        // ---- Sleep

        [Tooltip("The body sleeps once every particle has stayed slower than this for Sleep Delay (m/s). 0 = never sleeps. Default 0.02 m/s.")]
        [Min(0f)]
        public float sleepSpeed = k_Solver.SleepSpeed;

        [Tooltip("Time every particle must stay below Sleep Speed before the body sleeps (s). Default 1 s.")]
        [Min(0f)]
        public float sleepDelay = k_Solver.SleepDelay;

        // ---- Limits

        [Tooltip("Most particles this body may have. Baking fails above it: simplify the mesh or raise Interior Spacing. Default 16384.")]
        [Min(1f)]
        public int maxParticles = SoftBodyBuildSettings.DefaultMaxParticles;

        [Tooltip("Speed above which the state counts as broken and the body is reset to its rest shape (m/s). Default 500 m/s.")]
        [Min(0f)]
        public float maxSpeed = k_Solver.MaxSpeed;

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

        /// <summary>The solver parameters (runtime).</summary>
        public ShapeMatchingParameters Parameters => new ShapeMatchingParameters
        {
            Mode = mode,
            Frequency = frequency,
            DampingRatio = dampingRatio,
            Beta = beta,
            Acceleration = UnityMathConversions.ToFloat3(gravity),
            Substeps = substeps,
            MaxSubstepPhase = maxSubstepPhase,
            MaxDepenetrationSpeed = maxDepenetrationSpeed,
            ParticleRadius = particleRadius,
            Friction = friction,
            Restitution = restitution,
            Plasticity = new PlasticityParameters { Yield = plasticYield, Creep = plasticCreep, MaxDeformation = plasticMaxDeformation },
            SleepSpeed = sleepSpeed,
            SleepDelay = sleepDelay,
            MaxSpeed = maxSpeed,
            RotationIterations = rotationIterations,
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

        /// <summary>A component saved by 0.2 keeps its material: see <see cref="SoftBodyPresets.MigrateLegacyStiffness"/>.</summary>
        void ISerializationCallbackReceiver.OnAfterDeserialize() => SoftBodyPresets.MigrateLegacyStiffness(this);

        void OnValidate() => SoftBodyPresets.Synchronize(this);
    }
}
