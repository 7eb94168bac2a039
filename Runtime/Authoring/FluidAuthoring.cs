using SoftBodyDynamics.Solvers;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>A fluid material for the inspector: one of the presets, or Custom to set every value by hand.</summary>
    public enum FluidAuthoringPreset
    {
        Custom = 0,
        Water = 1,
        Honey = 2,
        Oil = 3,
        Slime = 4,
        Lava = 5,
    }

    /// <summary>
    /// A particle fluid: its material, resolution, solver and domain. Taps (<see cref="FluidTapAuthoring"/>) pour into
    /// it and drains (<see cref="FluidDrainAuthoring"/>) remove from it; its particles live in packed buffers on the
    /// fluid entity. The domain box is axis-aligned and centred on this GameObject's position (rotation and scale are
    /// ignored). With a preset other than Custom, the material values (density, viscosity and its iterations,
    /// cohesion) come from the preset and the fields below them are ignored.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("Soft Body Dynamics/Fluid")]
    public sealed class FluidAuthoring : MonoBehaviour
    {
        [Tooltip("Material preset (physical density and viscosity). Custom: use the material fields below.")]
        public FluidAuthoringPreset preset = FluidAuthoringPreset.Water;

        [Tooltip("Pressure solver. Weakly compressible SPH: cheap per substep, substep set by the speed of sound. Position-based fluids: large substeps, accuracy set by the iterations.")]
        public FluidSolverKind solver = FluidSolverKind.WeaklyCompressible;

        [Tooltip("Rest distance between particles (m). Sets particle mass and the spawn lattice; halving it means 8× the particles. Default 0.02 m.")]
        [Min(0f)]
        public float particleSpacing = 0.02f;

        [Tooltip("Kernel radius h as a multiple of the spacing (1.5–4). 2 gives about 30 neighbours.")]
        [Range(1.5f, 4f)]
        public float kernelRadiusRatio = 2f;

        [Tooltip("Custom material: rest density ρ₀ (kg/m³). Water 1000.")]
        [Min(0f)]
        public float restDensity = 1000f;

        [Tooltip("Weakly compressible: numerical speed of sound c₀ (m/s). 10·√(v² + gH) for the fastest flow v and depth H keeps the density error near 1 %; the substep shrinks as c₀ grows. Default 10 m/s (about 10 cm of still water).")]
        [Min(0f)]
        public float speedOfSound = 10f;

        [Tooltip("Weakly compressible: artificial viscosity α (0–1) damping acoustic noise, used only as far as the physical viscosity falls short of its own α·h·c₀/10 (honey, slime and lava get none). Default 0.05.")]
        [Range(0f, 1f)]
        public float artificialViscosity = 0.05f;

        [Tooltip("Weakly compressible: bulk viscosity β (0–1): a pressure −ρ₀·β·c₀·h·∇·v that resists the rate of compression only, so a deep column stops its acoustic 'breathing' within seconds. Explicit: β = 1 at the default CFL number already adds noise. Default 0.5; 0 = off.")]
        [Range(0f, 1f)]
        public float bulkViscosity = 0.5f;

        [Tooltip("Position-based: density-constraint iterations per substep (1–100). Default 4. The substeps also follow the fluid's depth, so that a deep column stays within about 1 % of its rest density.")]
        [Range(1, 100)]
        public int pressureIterations = 4;

        [Tooltip("Position-based: artificial pressure k (0–0.5), a short-range repulsion (Macklin & Müller 2013) that holds the free surface still; k reads as a density error. Larger values spread thin flows (a dam break's density error 4 % at 0.01, 15 % at 0.1). Default 0.01; 0 = off.")]
        [Range(0f, 0.5f)]
        public float artificialPressure = 0.01f;

        [Tooltip("Position-based: the solver's XSPH velocity smoothing (1/s), added to Alignment Rate. It damps what the iterations leave of the density error as motion, so a deep column comes to rest (a 40-layer column over its fourth second: 1.0e-4 J/kg without, 5.1e-6 at 20/s); it conserves momentum but also acts as a viscosity in shear flow. Default 20/s; 0 = off.")]
        [Range(0f, 100f)]
        public float xsphRate = FluidParameters.PositionBasedXsphRate;

        [Tooltip("Custom material: kinematic viscosity ν (m²/s). Water 1e-6, oil 1e-4, honey 7e-3. Implicit: any value is stable.")]
        [Min(0f)]
        public float viscosity = 1e-6f;

        [Tooltip("Custom material: Jacobi iterations of the implicit viscosity per substep, at least (0 = no viscosity pass). A substep whose solve would stop short of 1 % of its solution runs more, up to 50.")]
        [Range(0, 50)]
        public int viscosityIterations = 1;

        [Tooltip("Custom material: cohesion model. Flocking: cheap surface tension by steering rules. Akinci: cohesion and curvature forces (Akinci et al. 2013).")]
        public FluidCohesionModel cohesion = FluidCohesionModel.None;

        [Tooltip("Flocking: acceleration toward the neighbour centroid per metre of offset (1/s²). 0 = off.")]
        [Min(0f)]
        public float cohesionWeight;

        [Tooltip("Flocking: acceleration away from neighbours closer than the spacing per metre of overlap (1/s²). 0 = off.")]
        [Min(0f)]
        public float separationWeight;

        [Tooltip("XSPH velocity smoothing for any solver (the flocking rules' alignment): rate at which a velocity relaxes toward its neighbours' mean (1/s). Position-based fluids add their own XSPH Rate. 0 = off.")]
        [Min(0f)]
        public float alignmentRate;

        [Tooltip("Akinci: surface tension coefficient γ. 0 = off.")]
        [Min(0f)]
        public float surfaceTension;

        [Tooltip("Multiplier of gravity (−9.81 m/s² along world Y) for this fluid. 0 = weightless.")]
        public float gravityScale = 1f;

        [Tooltip("Size of the domain box (m), centred on this GameObject. Particles stay inside; the neighbour grid covers it.")]
        public Vector3 domainSize = new Vector3(2f, 2f, 2f);

        [Tooltip("Most particles the fluid holds (memory: about 370 bytes each plus 4 bytes per grid cell). Taps stall at the budget.")]
        [Min(1)]
        public int particleBudget = 20000;

        [Tooltip("CFL number λ of the adaptive substep (0.05–1). Default 0.4.")]
        [Range(0.05f, 1f)]
        public float cflNumber = 0.4f;

        [Tooltip("Most substeps per fixed step (1–256). When the CFL limit asks for more, the step runs this many and warns.")]
        [Range(1, 256)]
        public int maxSubsteps = 32;

        [Tooltip("Fewest substeps per fixed step (0–256; 0 = the CFL limit alone). More substeps than the CFL limit asks for buy a smaller step; a Particle World raises this to its minimum.")]
        [Range(0, 256)]
        public int minSubsteps = 0;

        [Tooltip("Packed: particles live only in the fluid's buffers (cheapest; 100k+ particles). Entities: one entity per particle, instantiated from the particle prefab, that gameplay code can query, tag and destroy.")]
        public FluidStorage storage = FluidStorage.Packed;

        [Tooltip("Entities storage: the prefab (with a Metaball Particle component) every particle is instantiated from.")]
        public MetaballParticleAuthoring particlePrefab;

        [Tooltip("Where the fluid runs. CPU: Burst jobs. GPU: compute shaders (Packed storage; falls back to the CPU with a warning when the device cannot). Auto: the GPU where it can, the CPU otherwise. Default CPU.")]
        public SoftBodyDynamics.Solvers.FluidBackend backend = SoftBodyDynamics.Solvers.FluidBackend.Cpu;

        [Tooltip("GPU: the fluid kernels, Shaders/FluidSolver.compute of this package.")]
        public ComputeShader computeShader;

        [Tooltip("GPU: when the particles are copied back into the fluid's entity buffers for gameplay code (asynchronously, a frame or two late). Never keeps them on the GPU.")]
        public FluidReadback readback = FluidReadback.Never;

        [Tooltip("GPU, every N frames: fixed steps between read-backs (≥ 1).")]
        [Min(1)]
        public int readbackInterval = 10;

        [Tooltip("Coulomb friction μ against colliders (0 = free slip, at most 1; a particle resting on a collider slides with deceleration μg).")]
        [Min(0f)]
        public float wallFriction;

        [Tooltip("No-slip share of the colliders (0 = free slip, 1 = no slip): in the viscosity solve a collider holds the fluid beside it at rest, like No-Slip Faces for the domain box. Needs a viscosity and at least one viscosity iteration.")]
        [Range(0f, 1f)]
        public float wallNoSlip;

        [Tooltip("Coulomb friction μ of the domain box's faces normal to x, y and z (0 = free slip, at most 1). The floor is y: a particle resting on it slides with deceleration μ.y·g.")]
        public Vector3 domainFriction;

        [Tooltip("No-slip share of the domain box's faces normal to x, y and z (0 = free slip, 1 = no slip): in the viscosity solve the face holds the fluid beside it at rest. Needs a viscosity and at least one viscosity iteration.")]
        public Vector3 domainNoSlip;

        [Tooltip("Periodic along x: a particle leaving through one x face enters through the other, and there is no wall on that axis (a channel standing for an unbounded flow). The extent must be at least 3 kernel radii.")]
        public bool periodicX;

        [Tooltip("Periodic along y (see Periodic X).")]
        public bool periodicY;

        [Tooltip("Periodic along z (see Periodic X).")]
        public bool periodicZ;

        /// <summary>The solver settings these fields describe (the preset's material when one is chosen), in world space.</summary>
        public FluidParameters ToParameters()
        {
            FluidParameters p = preset == FluidAuthoringPreset.Custom ? FluidParameters.Default : FluidPresets.Get(ToPresetKind(preset)).Parameters;
            if (preset == FluidAuthoringPreset.Custom)
            {
                p.RestDensity = restDensity;
                p.Viscosity = viscosity;
                p.ViscosityIterations = viscosityIterations;
                p.Cohesion = cohesion;
                p.CohesionWeight = cohesionWeight;
                p.SeparationWeight = separationWeight;
                p.AlignmentRate = alignmentRate;
                p.SurfaceTension = surfaceTension;
            }
            p.Solver = solver;
            p.ParticleSpacing = particleSpacing;
            p.KernelRadiusRatio = kernelRadiusRatio;
            p.SpeedOfSound = speedOfSound;
            p.ArtificialViscosity = artificialViscosity;
            p.BulkViscosity = bulkViscosity;
            p.PressureIterations = pressureIterations;
            p.ArtificialPressure = artificialPressure;
            p.XsphRate = xsphRate;
            p.Gravity = new Unity.Mathematics.float3(0f, -9.81f * gravityScale, 0f);
            Unity.Mathematics.float3 centre = UnityMathConversions.ToFloat3(transform.position);
            Unity.Mathematics.float3 half = 0.5f * UnityMathConversions.ToFloat3(domainSize);
            p.DomainMin = centre - half;
            p.DomainMax = centre + half;
            p.CflNumber = cflNumber;
            p.MaxSubsteps = maxSubsteps;
            p.MinSubsteps = minSubsteps;
            p.WallFriction = wallFriction;
            p.DomainFriction = UnityMathConversions.ToFloat3(domainFriction);
            p.DomainNoSlip = UnityMathConversions.ToFloat3(domainNoSlip);
            p.WallNoSlip = wallNoSlip;
            p.Periodic = new Unity.Mathematics.bool3(periodicX, periodicY, periodicZ);
            return p;
        }

        /// <summary>The look's base colour of the preset (white for Custom).</summary>
        public Unity.Mathematics.float4 PresetColor =>
            preset == FluidAuthoringPreset.Custom ? new Unity.Mathematics.float4(1f) : FluidPresets.Get(ToPresetKind(preset)).Color;

        /// <summary>The solver preset of an inspector preset (Custom maps to water).</summary>
        public static FluidPresetKind ToPresetKind(FluidAuthoringPreset preset) => preset switch
        {
            FluidAuthoringPreset.Honey => FluidPresetKind.Honey,
            FluidAuthoringPreset.Oil => FluidPresetKind.Oil,
            FluidAuthoringPreset.Slime => FluidPresetKind.Slime,
            FluidAuthoringPreset.Lava => FluidPresetKind.Lava,
            _ => FluidPresetKind.Water,
        };

        void OnDrawGizmos()
        {
            Gizmos.color = new Color(0.2f, 0.6f, 1f, 0.8f);
            Gizmos.DrawWireCube(transform.position, domainSize);
        }
    }
}
