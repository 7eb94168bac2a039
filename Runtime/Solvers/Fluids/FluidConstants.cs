using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Everything a fluid step derives from its (sanitized) parameters, computed once on the CPU: kernels, grid,
    /// particle mass, Tait stiffness, wall distance. The GPU backend uploads the same values as constants.
    /// </summary>
    public readonly struct FluidConstants
    {
        public readonly FluidParameters Parameters;
        public readonly SphKernels Kernels;
        public readonly FluidGrid Grid;
        /// <summary>Particle mass m (kg): ρ₀ over the poly6 sum of a particle in a full cubic lattice at the spacing, so that the lattice is at rest density.</summary>
        public readonly float Mass;
        /// <summary>Tait stiffness B = ρ₀c₀²/γ (Pa).</summary>
        public readonly float TaitStiffness;
        /// <summary>Closest a particle centre comes to a wall or collider surface (m): half the spacing.</summary>
        public readonly float WallDistance;
        /// <summary>
        /// Position-based: scale κ on the continuous wall integrals (<see cref="FluidBoundary.Sample"/>) so that a particle of a
        /// rest lattice half a spacing off a wall gets exactly the density the missing lattice layers would give it (the
        /// continuum integral differs from the lattice sum by a few per cent).
        /// </summary>
        public readonly float WallScale;
        /// <summary>
        /// Scale κ∇ on the spiky pressure gradient so that the lattice at rest differentiates a linear field exactly:
        /// the continuum identity ∫ x·∇W dV = −3 fails on the discrete lattice by a few tens of per cent for h = 2Δx, and the
        /// hydrostatic pressure a column settles to would be off by the same factor. κ∇ = −3 / (V·Σⱼ rⱼ·∇W(rⱼ)) over the
        /// lattice neighbours (V = m/ρ₀).
        /// </summary>
        public readonly float GradientCorrection;
        /// <summary>
        /// −κ∇·m·C_spiky (kg/m⁶), C_spiky = −45/(πh⁶): tᵢ = this·Σⱼ (h − r)²·r / ρᵢ is the corrected trace
        /// κ∇·Σⱼ (m/ρᵢ)·(−rᵢⱼ·∇W), 3 for a particle of the rest lattice (<see cref="GradientRenormalization"/>).
        /// </summary>
        public readonly float GradientTraceScale;
        /// <summary>
        /// Largest <see cref="GradientRenormalization"/> (and smallest, its inverse): a few per cent covers the settled
        /// disorder of a fluid's interior (about 2.7 %, ±0.9 % between particles, on a 0.4 m column), while a particle at a free surface, whose missing
        /// neighbours would ask for far more, gets only this.
        /// </summary>
        public const float MaxGradientRenormalization = 1.05f;
        /// <summary>
        /// Scale κ_ν on the viscosity Laplacian Σⱼ (m/ρ)·∇²W_visc(rᵢⱼ)·(vⱼ − vᵢ) so that the rest lattice differentiates a
        /// quadratic field exactly: the continuum identity ∫ z²·∇²W dV = 2 holds on the discrete lattice only to a per cent or
        /// so at h = 2Δx, which a steady shear flow would show as that error in its viscosity whatever the resolution.
        /// κ_ν = 2 / (V·Σⱼ zⱼ²·∇²W(rⱼ)) over the lattice neighbours (V = m/ρ₀).
        /// </summary>
        public readonly float ViscosityCorrection;
        /// <summary>
        /// 3/(m·C_visc·κ_ν) (m⁶/kg), C_visc = 45/(πh⁶): with wᵢⱼ = (h − r)/(ρᵢ + ρⱼ),
        /// 2m·C_visc·κ_ν·Σⱼ wᵢⱼ·rᵢⱼ² is κ_ν·Σⱼ (m/ρ)·∇²W·r², 6 on the rest lattice (the trace of Σⱼ (m/ρ)·∇²W·rᵢⱼ⊗rᵢⱼ = 2I),
        /// so this over the particle's Σⱼ wᵢⱼ·rᵢⱼ² is 1 there.
        /// </summary>
        public readonly float ViscosityMomentScale;
        /// <summary>
        /// Largest <see cref="ViscosityRenormalization"/> (and smallest, its inverse): lattice layers sliding past each other in a
        /// shear flow fall a few per cent short of the aligned lattice's moment, and so does a settled fluid's disorder, while a
        /// particle at a free surface or a free-slip wall, whose missing neighbours would ask for far more, gets only this.
        /// </summary>
        public const float MaxViscosityRenormalization = 1.1f;
        /// <summary>
        /// Weakly compressible: the bulk-viscous pressure −ρ₀ζ·∇·vᵢ is this times D/ρᵢ, D = Σⱼ (vᵢ − vⱼ)·xᵢⱼ·(h² − r²)²
        /// (the Density pass's sum): ∇·vᵢ = (m/ρᵢ)·Σⱼ (vⱼ − vᵢ)·∇W_poly6 = −6C·κ₆·(m/ρᵢ)·D with the poly6 gradient
        /// ∇W = −6C(h² − r²)²·xᵢⱼ, no square root, and κ₆ its lattice correction (as <see cref="GradientCorrection"/>),
        /// so the scale is ρ₀ζ·6C·κ₆·m with ζ = <see cref="FluidParameters.BulkViscosity"/>·c₀·h. 0 = off.
        /// </summary>
        public readonly float BulkPressureScale;
        /// <summary>
        /// Position-based: k·λ₁ (m²), the artificial pressure's scale: k = <see cref="FluidParameters.ArtificialPressure"/> and
        /// λ₁ = 1/Σ|∇Cₖ|² over a rest lattice, the λ of a unit density error, so k reads as a density error (0.01: 1 % at r = Δq).
        /// </summary>
        public readonly float ArtificialPressureScale;
        /// <summary>True when the domain has a periodic axis (<see cref="FluidParameters.Periodic"/>).</summary>
        public readonly bool IsPeriodic;
        /// <summary>The domain's extent on its periodic axes, 0 on the others (m).</summary>
        public readonly float3 Period;
        /// <summary>1 / <see cref="Period"/> on the periodic axes, 0 on the others (1/m).</summary>
        public readonly float3 InversePeriod;
        /// <summary>The no-slip share of the domain faces per axis (<see cref="FluidParameters.DomainNoSlip"/>), 0 on periodic axes (they have no faces).</summary>
        public readonly float3 FaceNoSlip;
        /// <summary>Position-based: constraint-force mixing ε added to the gradient sum (1/m²), 1e-3/Δx², about 1 % of the sum at rest.</summary>
        public readonly float Relaxation;
        /// <summary>
        /// Weakly compressible: the artificial viscosity α' the pressure term uses, <see cref="FluidParameters.ArtificialViscosity"/>
        /// α less what the physical viscosity ν already supplies: α' = α·max(0, 1 − ν/ν_α) with ν_α = α·h·c₀/10, α's shear
        /// viscosity, so that ν + α'·h·c₀/10 ≥ ν_α. A material whose own viscosity damps the acoustic noise (honey, slime,
        /// lava at game spacings) gets none; water keeps α.
        /// </summary>
        public readonly float EffectiveArtificialViscosity;

        public FluidConstants(in FluidParameters parameters)
        {
            Parameters = parameters.Sanitized();
            float h = Parameters.KernelRadius;
            Kernels = new SphKernels(h);
            Grid = GridOf(Parameters);
            Mass = Parameters.RestDensity / LatticeKernelSum(Kernels, Parameters.ParticleSpacing);
            TaitStiffness = Parameters.RestDensity * Parameters.SpeedOfSound * Parameters.SpeedOfSound / FluidParameters.TaitExponent;
            WallDistance = 0.5f * Parameters.ParticleSpacing;
            float artificialShear = Parameters.ArtificialViscosity * h * Parameters.SpeedOfSound / 10f;
            float continuum = Kernels.WallDensityFraction(WallDistance);
            WallScale = continuum > 0f ? MissingLayersSum(Kernels, Parameters.ParticleSpacing) / (LatticeKernelSum(Kernels, Parameters.ParticleSpacing) * continuum) : 1f;
            EffectiveArtificialViscosity = artificialShear > 0f
                ? Parameters.ArtificialViscosity * math.max(0f, 1f - Parameters.Viscosity / artificialShear)
                : 0f;
            GradientCorrection = -3f / (Mass / Parameters.RestDensity * LatticeGradientSum(Kernels, Parameters.ParticleSpacing));
            GradientTraceScale = -GradientCorrection * Mass * Kernels.SpikyGradientCoefficient;
            ViscosityCorrection = 2f / (Mass / Parameters.RestDensity * LatticeSum(Kernels, Parameters.ParticleSpacing, LatticeTerm.ViscosityLaplacianZ2));
            ViscosityMomentScale = 3f / (Mass * Kernels.ViscosityLaplacianCoefficient * ViscosityCorrection);
            float poly6Correction = -3f / (Mass / Parameters.RestDensity * LatticeSum(Kernels, Parameters.ParticleSpacing, LatticeTerm.Poly6GradientDotOffset));
            BulkPressureScale = Parameters.RestDensity * Parameters.BulkViscosity * Parameters.SpeedOfSound * h
                * 6f * Kernels.Poly6Coefficient * poly6Correction * Mass;
            float gradientSquares = (Mass / Parameters.RestDensity) * (Mass / Parameters.RestDensity)
                * LatticeSum(Kernels, Parameters.ParticleSpacing, LatticeTerm.GradientSquared);
            ArtificialPressureScale = Parameters.Solver == FluidSolverKind.PositionBased && gradientSquares > 0f
                ? Parameters.ArtificialPressure / gradientSquares : 0f;
            Relaxation = 1e-3f / (Parameters.ParticleSpacing * Parameters.ParticleSpacing);
            bool3 periodic = Parameters.Periodic;
            IsPeriodic = math.any(periodic);
            float3 extent = Parameters.DomainMax - Parameters.DomainMin;
            Period = new float3(periodic.x ? extent.x : 0f, periodic.y ? extent.y : 0f, periodic.z ? extent.z : 0f);
            InversePeriod = new float3(periodic.x ? 1f / extent.x : 0f, periodic.y ? 1f / extent.y : 0f, periodic.z ? 1f / extent.z : 0f);
            FaceNoSlip = math.select(Parameters.DomainNoSlip, float3.zero, periodic);
        }

        /// <summary>
        /// xᵢ − xⱼ, between the nearest images on the periodic axes (<see cref="NearestImageOffset"/>); the hot passes take the
        /// offset as a type parameter instead.
        /// </summary>
        public float3 Offset(float3 xi, float3 xj) => IsPeriodic ? NearestImageOffset.Apply(xi - xj, Period, InversePeriod) : xi - xj;

        /// <summary>
        /// Tait pressure p = B·((ρ/ρ₀)^γ − 1), γ = 7 (Becker &amp; Teschner 2007, eq. 6), of the density clamped to at
        /// least ρ₀ (Pa): zero at and below rest density.
        /// </summary>
        public float TaitPressure(float density)
        {
            float qr = math.max(density, Parameters.RestDensity) / Parameters.RestDensity;
            float q2 = qr * qr;
            return TaitStiffness * (q2 * q2 * q2 * qr - 1f);
        }

        /// <summary>
        /// Weakly compressible: the factor κᵢ/κ∇ on particle i's pressure, 3 / tᵢ clamped to
        /// 1/<see cref="MaxGradientRenormalization"/>…<see cref="MaxGradientRenormalization"/>, with tᵢ = κ∇·Σⱼ (m/ρᵢ)·(−rᵢⱼ·∇W)
        /// over the neighbours and the walls' ghosts: the trace of Bonet &amp; Lok 1999's gradient renormalization matrix, so
        /// that the settled, slightly disordered particles differentiate a linear pressure as the rest lattice does. Applied
        /// per particle inside the symmetric pair term (κᵢpᵢ/ρᵢ² + κⱼpⱼ/ρⱼ²), momentum stays conserved.
        /// <paramref name="spikySum"/> is Σⱼ (h − r)²·r (m³).
        /// </summary>
        public float GradientRenormalization(float spikySum, float density)
        {
            float trace = GradientTraceScale * spikySum / density;
            return math.clamp(3f / trace, 1f / MaxGradientRenormalization, MaxGradientRenormalization);
        }

        /// <summary>
        /// The factor sᵢ on particle i's viscosity, <see cref="ViscosityMomentScale"/> / Σⱼ wᵢⱼ·rᵢⱼ² clamped to
        /// 1/<see cref="MaxViscosityRenormalization"/>…<see cref="MaxViscosityRenormalization"/>, wᵢⱼ = (h − r)/(ρᵢ + ρⱼ) over the
        /// neighbours and the no-slip walls' mirrored ghosts: the trace of the viscosity Laplacian's second-moment matrix, renormalized
        /// to the rest lattice's (as <see cref="GradientRenormalization"/> does for the gradient), so that layers sheared off the
        /// lattice, whose kernel sums fall short of the aligned lattice's κ_ν was calibrated on, keep the fluid's viscosity.
        /// </summary>
        public float ViscosityRenormalization(float moment) =>
            math.clamp(ViscosityMomentScale / moment, 1f / MaxViscosityRenormalization, MaxViscosityRenormalization);

        /// <summary>
        /// <paramref name="x"/> moved by whole periods into [DomainMin, DomainMax) on the periodic axes; the other axes are
        /// unchanged.
        /// </summary>
        public float3 Wrap(float3 x)
        {
            float3 min = Parameters.DomainMin;
            bool3 periodic = Parameters.Periodic;
            if (periodic.x) x.x -= Period.x * math.floor((x.x - min.x) * InversePeriod.x);
            if (periodic.y) x.y -= Period.y * math.floor((x.y - min.y) * InversePeriod.y);
            if (periodic.z) x.z -= Period.z * math.floor((x.z - min.z) * InversePeriod.z);
            return x;
        }

        /// <summary>The grid of a fluid: its domain box in cells of the kernel radius.</summary>
        public static FluidGrid GridOf(in FluidParameters sanitized) =>
            new FluidGrid(sanitized.DomainMin, sanitized.DomainMax, sanitized.KernelRadius, sanitized.Periodic);

        /// <summary>Σ rₖ·∇W(rₖ) = Σ SpikyGradientScale(r)·r² over the lattice neighbours k ≠ 0 (1/m³; negative).</summary>
        public static float LatticeGradientSum(in SphKernels kernels, float spacing) => LatticeSum(kernels, spacing, LatticeTerm.GradientDotOffset);

        /// <summary>Σ W(|k|·Δx) over the integer lattice points k (the particle itself included), 1/m³.</summary>
        public static float LatticeKernelSum(in SphKernels kernels, float spacing) => LatticeSum(kernels, spacing, LatticeTerm.Poly6);

        /// <summary>Σ W(|k|·Δx) over the lattice points k with k.z ≥ 1: what a particle of a lattice half a spacing off a wall lacks (1/m³).</summary>
        public static float MissingLayersSum(in SphKernels kernels, float spacing) => LatticeSum(kernels, spacing, LatticeTerm.Poly6, true);

        enum LatticeTerm { Poly6, GradientDotOffset, Poly6GradientDotOffset, GradientSquared, ViscosityLaplacianZ2 }

        /// <summary>A kernel term summed in double over the cubic lattice around a particle (only the layers k.z ≥ 1 when <paramref name="beyondWall"/>).</summary>
        static float LatticeSum(in SphKernels kernels, float spacing, LatticeTerm term, bool beyondWall = false)
        {
            int n = (int)math.ceil(kernels.H / spacing);
            double sum = 0;
            for (int z = beyondWall ? 1 : -n; z <= n; z++)
            for (int y = -n; y <= n; y++)
            for (int x = -n; x <= n; x++)
            {
                float r2 = spacing * spacing * (x * x + y * y + z * z);
                double q = math.max(kernels.H2 - r2, 0f);
                double spiky = kernels.SpikyGradientScale(math.sqrt(r2));
                sum += term switch
                {
                    LatticeTerm.Poly6 => kernels.Poly6(r2),
                    LatticeTerm.GradientDotOffset => spiky * r2,
                    // |∇W|² = (SpikyGradientScale(r)·r)².
                    LatticeTerm.GradientSquared => spiky * spiky * r2,
                    LatticeTerm.ViscosityLaplacianZ2 => (double)spacing * spacing * z * z * kernels.ViscosityLaplacian(math.sqrt(r2)),
                    // r·∇W_poly6 = −6C(h² − r²)²·r².
                    _ => -6.0 * kernels.Poly6Coefficient * q * q * r2,
                };
            }
            return (float)sum;
        }
    }
}
