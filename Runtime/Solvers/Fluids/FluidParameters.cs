using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Per-fluid tunables (a component in ECS). Units are in each doc comment. Every value means the same at any frame
    /// rate: the step splits a frame into CFL-limited substeps, viscosity is implicit and the flocking rules are rates.
    /// </summary>
    public struct FluidParameters
    {
        /// <summary>Pressure solver (<see cref="FluidSolverKind"/>). Default: weakly compressible SPH.</summary>
        public FluidSolverKind Solver;
        /// <summary>Rest distance Δx between particles (m): sets particle mass and the spawn lattice. Default 0.02 m.</summary>
        public float ParticleSpacing;
        /// <summary>Kernel radius h as a multiple of <see cref="ParticleSpacing"/> (1.5–4). Default 2 (about 30 neighbours).</summary>
        public float KernelRadiusRatio;
        /// <summary>Rest density ρ₀ (kg/m³). Water 1000.</summary>
        public float RestDensity;
        /// <summary>
        /// Weakly compressible: numerical speed of sound c₀ (m/s); the Tait stiffness is B = ρ₀c₀²/γ. Density error is
        /// about (v_max² + gH)/c₀² for flow speed v_max and depth H, so c₀ = 10·√(v_max² + gH) keeps it near 1 % (the default
        /// 10 m/s: water about 10 cm deep at rest). The substep is at most
        /// <see cref="CflNumber"/>·h / (c₀ + v_max), so a stiffer fluid costs more substeps. Default 10 m/s.
        /// </summary>
        public float SpeedOfSound;
        /// <summary>
        /// Weakly compressible: Monaghan's artificial viscosity α (dimensionless, Becker &amp; Teschner 2007, eq. 11),
        /// acting only between approaching particles. It damps the acoustic noise of the stiff equation of state; it
        /// also adds an effective viscosity of about α·h·c₀/10 (m²/s). The step uses it only as far as <see cref="Viscosity"/>
        /// falls short of that (<see cref="FluidConstants.EffectiveArtificialViscosity"/>). 0–1, default 0.05.
        /// </summary>
        public float ArtificialViscosity;
        /// <summary>
        /// Weakly compressible: bulk viscosity β (dimensionless): a pressure −ρ₀ζ·∇·v with ζ = β·c₀·h (m²/s) that resists
        /// the rate of compression only (shear is untouched, and the total pressure stays ≥ 0). It damps the column's
        /// acoustic "breathing", which a shear viscosity that small cannot reach. Integrated explicitly: β = 1 at the default
        /// <see cref="CflNumber"/> already leaves acoustic noise (measured on a 0.4 m column). 0–1, default 0.5 (0 = off).
        /// </summary>
        public float BulkViscosity;
        /// <summary>
        /// Position-based: artificial pressure k (dimensionless; Macklin &amp; Müller 2013, eqs. 13–14): a short-range
        /// repulsion s_corr = −k·λ₁·(W(r)/W(0.2h))⁴, λ₁ the constraint's λ for a unit density error, so k reads as a
        /// density error. It holds the free surface, where the clamped constraint is inactive and 4 Jacobi iterations left
        /// the top layers of a deep column jittering (a 40-layer column kept 7·10⁻³ J/kg after 3 s without it, 0.45–1.3·10⁻⁴ with
        /// 0.01, 3·10⁻⁶ with 0.1). Its repulsion also spreads thin flows: at 0.1 the dam break's density error rose from 4 to
        /// 15 % (2 iterations), at 0.01 to 4.3 %. 0–0.5, default 0.01 (0 = off).
        /// </summary>
        public float ArtificialPressure;
        /// <summary>Position-based: density-constraint iterations per substep (1–100). Default 4.</summary>
        public int PressureIterations;
        /// <summary>
        /// Position-based: the solver's XSPH velocity smoothing (Macklin &amp; Müller 2013, eq. 17, as a rate like
        /// <see cref="AlignmentRate"/>, to which it adds), 1/s. The velocity update turns what 4 Jacobi iterations leave of the
        /// density constraint into motion of that size over the substep; relaxing each velocity toward its neighbours' mean
        /// damps that relative motion, so a 40-layer column comes to rest (mean over the fourth second: 1.0·10⁻⁴ J/kg without,
        /// 1.3·10⁻⁵ at 10/s, 5.1·10⁻⁶ at 20/s, 2.1·10⁻⁶ at 40/s). It conserves momentum, but it is also a viscosity for shear
        /// flow. Weakly compressible fluids ignore it. 0–100, default <see cref="PositionBasedXsphRate"/> (0 = off).
        /// </summary>
        public float XsphRate;
        /// <summary>Kinematic viscosity ν (m²/s): water 1e-6, oil 1e-4, honey 5e-3. Integrated implicitly, so any value is stable.</summary>
        public float Viscosity;
        /// <summary>
        /// Jacobi iterations of the implicit viscosity solve per substep, at least (0–50; 0 = no viscosity pass): a substep
        /// whose solve would stop short of 1 % of its solution runs more, up to 50 (<see cref="FluidSolver.ViscosityIterations"/>).
        /// Default 4.
        /// </summary>
        public int ViscosityIterations;
        /// <summary>Cohesion model (<see cref="FluidCohesionModel"/>). Default: none.</summary>
        public FluidCohesionModel Cohesion;
        /// <summary>Flocking: acceleration toward the neighbour centroid per metre of offset (1/s²). 0 = off.</summary>
        public float CohesionWeight;
        /// <summary>Flocking: acceleration away from neighbours closer than the spacing, per metre of overlap (1/s²). 0 = off.</summary>
        public float SeparationWeight;
        /// <summary>
        /// XSPH velocity smoothing (Monaghan 1989; the flocking rules' alignment): rate at which a velocity relaxes toward the
        /// neighbours' kernel-weighted mean, 1/s, for any solver and cohesion model. Position-based fluids add their solver's
        /// <see cref="XsphRate"/>. Default 0 (off).
        /// </summary>
        public float AlignmentRate;
        /// <summary>
        /// Akinci et al. 2013: coefficient γ of the cohesion and curvature forces, aᵢ = −γ·Σⱼ Kᵢⱼ(m·C(r)·r̂ + nᵢ − nⱼ) (the
        /// paper's γ: it multiplies a mass density for cohesion and a dimensionless normal difference for curvature, so it
        /// has no single SI unit). 0 = off. The droplet study uses 0.2 at 1 cm spacing, which squeezes the drop (Documentation~/fluids.md).
        /// </summary>
        public float SurfaceTension;
        /// <summary>Uniform acceleration on every particle: gravity times the fluid's gravity scale (m/s²).</summary>
        public float3 Gravity;
        /// <summary>Lower corner of the domain box (m, world). Particles stay inside; the grid covers it.</summary>
        public float3 DomainMin;
        /// <summary>Upper corner of the domain box (m, world).</summary>
        public float3 DomainMax;
        /// <summary>
        /// No-slip share of the colliders (0 = free slip, 1 = no slip), the domain faces' rule (<see cref="DomainNoSlip"/>) at
        /// each collider's tangent plane: in the viscosity solve the collider holds the fluid beside it at rest. Default 0.
        /// </summary>
        public float WallNoSlip;
        /// <summary>Coulomb friction coefficient μ at the colliders (0 = free slip, at most 1): a contact cancels tangential motion up to μ × its depth (a particle resting on a collider slides with deceleration μg).</summary>
        public float WallFriction;
        /// <summary>
        /// Coulomb μ of the domain box's faces normal to x, y and z (0 = free slip, at most 1), the colliders' rule: a
        /// particle resting on the floor slides with deceleration μ.y·g. Per axis, so a slab between two faces can keep them
        /// free-slip (symmetry planes) while its floor grips. Default 0.
        /// </summary>
        public float3 DomainFriction;
        /// <summary>
        /// No-slip share of the domain box's faces normal to x, y and z (0 = free slip, 1 = no slip, between: partial slip),
        /// acting in the viscosity solve: each particle near a face sees itself and its neighbours mirrored through it, moving
        /// with its own velocity reversed and scaled by their depth (Morris et al. 1997), which pulls it toward zero velocity at
        /// the face (<see cref="FluidPasses.ViscosityIteration"/>). Needs <see cref="Viscosity"/> and at least one viscosity
        /// iteration. Default 0.
        /// </summary>
        public float3 DomainNoSlip;
        /// <summary>
        /// Periodic axes of the domain box: a particle leaving through one face enters through the opposite one, and the
        /// particles near the two faces are neighbours (no wall on that axis), so a channel or a slab can stand for an
        /// unbounded flow. An axis needs an extent of at least 3h (shorter: not periodic). Default none.
        /// </summary>
        public bool3 Periodic;
        /// <summary>CFL number λ of the adaptive substep: h·λ / (c₀ + v_max) (weakly compressible) or h·λ / v_max (position-based). Default 0.4.</summary>
        public float CflNumber;
        /// <summary>Most substeps per step (1–256). When the CFL limit asks for more, the step reports it and runs this many. Default 32.</summary>
        public int MaxSubsteps;
        /// <summary>
        /// Fewest substeps per step (0–256, at most <see cref="MaxSubsteps"/> take effect): more than the CFL limit asks for
        /// buy a smaller h. 0 = the CFL limit alone (default). A <c>ParticleWorldSettings</c> singleton raises it to its minimum.
        /// </summary>
        public int MinSubsteps;
        /// <summary>Speed bound (m/s): faster particles are slowed to it and counted in the report. Default 50 m/s.</summary>
        public float MaxSpeed;
        /// <summary>Density ratio ρ/ρ₀ above which a particle is counted as over-compressed in the report. Default 1.5.</summary>
        public float MaxDensityRatio;

        /// <summary>
        /// Default <see cref="XsphRate"/> (1/s): the least of 10, 20, 40/s at which a 40-layer column stays under 10⁻⁵ J/kg from
        /// 2.5 s on (2–3× under it through the fourth second). The energy at one instant moves ×5 and more with small changes
        /// of the setup, so a rate that met the bound once at one instant (5/s) is not taken.
        /// </summary>
        public const float PositionBasedXsphRate = 20f;
        /// <summary>Largest <see cref="XsphRate"/> (1/s): at a 1/60 s substep the blend 1 − e^(−rate·h) is then 0.8 of the way to the mean.</summary>
        public const float MaxXsphRate = 100f;
        /// <summary>Most substeps a step may take.</summary>
        public const int SubstepLimit = 256;
        /// <summary>Most position-based iterations per substep.</summary>
        public const int MaxPressureIterations = 100;
        /// <summary>Most viscosity Jacobi iterations per substep.</summary>
        public const int MaxViscosityIterations = 50;
        /// <summary>Shortest extent of a periodic axis in kernel radii: two images of a particle never both lie within h of another.</summary>
        public const float MinPeriodicExtentRatio = 3f;
        /// <summary>Tait exponent γ (Becker &amp; Teschner 2007).</summary>
        public const float TaitExponent = 7f;

        /// <summary>Kernel radius h (m).</summary>
        public float KernelRadius => ParticleSpacing * KernelRadiusRatio;

        /// <summary>Rate of the XSPH pass (1/s): <see cref="AlignmentRate"/>, plus <see cref="XsphRate"/> for a position-based fluid.</summary>
        public float VelocitySmoothingRate => AlignmentRate + (Solver == FluidSolverKind.PositionBased ? XsphRate : 0f);

        /// <summary>Water at 2 cm spacing in a 1 m box above the origin.</summary>
        public static FluidParameters Default => new FluidParameters
        {
            Solver = FluidSolverKind.WeaklyCompressible,
            ParticleSpacing = 0.02f,
            KernelRadiusRatio = 2f,
            RestDensity = 1000f,
            SpeedOfSound = 10f,
            ArtificialViscosity = 0.05f,
            BulkViscosity = 0.5f,
            ArtificialPressure = 0.01f,
            PressureIterations = 4,
            XsphRate = PositionBasedXsphRate,
            Viscosity = 1e-6f,
            ViscosityIterations = 4,
            Cohesion = FluidCohesionModel.None,
            CohesionWeight = 0f,
            SeparationWeight = 0f,
            AlignmentRate = 0f,
            SurfaceTension = 0f,
            Gravity = new float3(0f, -9.81f, 0f),
            DomainMin = new float3(-0.5f, 0f, -0.5f),
            DomainMax = new float3(0.5f, 1f, 0.5f),
            WallFriction = 0f,
            WallNoSlip = 0f,
            DomainFriction = float3.zero,
            DomainNoSlip = float3.zero,
            Periodic = new bool3(false, false, false),
            CflNumber = 0.4f,
            MaxSubsteps = 32,
            MaxSpeed = 50f,
            MaxDensityRatio = 1.5f,
        };

        /// <summary>A Coulomb coefficient or no-slip share in [0, 1]; NaN is free slip.</summary>
        static float Friction(float mu) => math.isnan(mu) ? 0f : math.saturate(mu);

        /// <summary>A copy the step can trust: NaN or out-of-range values replaced by the nearest valid value (or the default).</summary>
        public FluidParameters Sanitized()
        {
            FluidParameters d = Default;
            FluidParameters p = this;
            if ((uint)Solver > (uint)FluidSolverKind.PositionBased)
                p.Solver = d.Solver;
            if ((uint)Cohesion > (uint)FluidCohesionModel.Akinci)
                p.Cohesion = d.Cohesion;
            p.ParticleSpacing = Finite.Positive(ParticleSpacing, d.ParticleSpacing);
            p.KernelRadiusRatio = math.isfinite(KernelRadiusRatio) ? math.clamp(KernelRadiusRatio, 1.5f, 4f) : d.KernelRadiusRatio;
            p.RestDensity = Finite.Positive(RestDensity, d.RestDensity);
            p.SpeedOfSound = Finite.Positive(SpeedOfSound, d.SpeedOfSound);
            p.ArtificialViscosity = math.isfinite(ArtificialViscosity) ? math.clamp(ArtificialViscosity, 0f, 1f) : d.ArtificialViscosity;
            p.BulkViscosity = math.isfinite(BulkViscosity) ? math.clamp(BulkViscosity, 0f, 1f) : d.BulkViscosity;
            p.ArtificialPressure = math.isfinite(ArtificialPressure) ? math.clamp(ArtificialPressure, 0f, 0.5f) : d.ArtificialPressure;
            p.PressureIterations = math.clamp(PressureIterations, 1, MaxPressureIterations);
            p.XsphRate = math.isfinite(XsphRate) ? math.clamp(XsphRate, 0f, MaxXsphRate) : d.XsphRate;
            p.Viscosity = Finite.NonNegative(Viscosity);
            p.ViscosityIterations = math.clamp(ViscosityIterations, 0, MaxViscosityIterations);
            p.CohesionWeight = Finite.NonNegative(CohesionWeight);
            p.SeparationWeight = Finite.NonNegative(SeparationWeight);
            p.AlignmentRate = Finite.NonNegative(AlignmentRate);
            p.SurfaceTension = Finite.NonNegative(SurfaceTension);
            p.Gravity = math.all(math.isfinite(Gravity)) ? Gravity : float3.zero;
            if (!math.all(math.isfinite(DomainMin)) || !math.all(math.isfinite(DomainMax)) || math.any(DomainMax - DomainMin < p.KernelRadius))
            {
                p.DomainMin = d.DomainMin;
                p.DomainMax = d.DomainMax;
            }
            p.WallFriction = Friction(WallFriction);
            p.WallNoSlip = Friction(WallNoSlip);
            p.DomainFriction = new float3(Friction(DomainFriction.x), Friction(DomainFriction.y), Friction(DomainFriction.z));
            p.DomainNoSlip = new float3(Friction(DomainNoSlip.x), Friction(DomainNoSlip.y), Friction(DomainNoSlip.z));
            float3 extent = p.DomainMax - p.DomainMin;
            float shortest = MinPeriodicExtentRatio * p.KernelRadius;
            p.Periodic = new bool3(Periodic.x && extent.x >= shortest, Periodic.y && extent.y >= shortest, Periodic.z && extent.z >= shortest);
            p.CflNumber = math.isfinite(CflNumber) ? math.clamp(CflNumber, 0.05f, 1f) : d.CflNumber;
            p.MaxSubsteps = math.clamp(MaxSubsteps, 1, SubstepLimit);
            p.MinSubsteps = math.clamp(MinSubsteps, 0, SubstepLimit);
            p.MaxSpeed = Finite.Positive(MaxSpeed, d.MaxSpeed);
            p.MaxDensityRatio = math.isfinite(MaxDensityRatio) && MaxDensityRatio > 1f ? MaxDensityRatio : d.MaxDensityRatio;
            return p;
        }
    }
}
