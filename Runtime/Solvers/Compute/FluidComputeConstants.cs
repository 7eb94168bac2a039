using System.Runtime.InteropServices;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The constants of the fluid kernels, computed on the CPU from a fluid's <see cref="FluidConstants"/>, the substep h
    /// and the step dt, and uploaded whole as the kernels' constant buffer: the C# side of
    /// <c>Shaders/Kernels/FluidComputeConstants.hlsl</c>, with the same fields in the same order at the same byte offsets
    /// (HLSL constant-buffer packing: 16-byte rows, a float3 and a scalar per row where a vector is needed).
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FluidComputeConstants
    {
        /// <summary>Bytes of the constant buffer: a multiple of 16, as constant buffers require.</summary>
        public const int Bytes = 272;
        /// <summary>The constant buffer's name in HLSL (its shader property).</summary>
        public const string BufferName = "FluidComputeConstants";

        /// <summary>Grid origin (m).</summary>
        public float3 GridOrigin;
        /// <summary>1 / cell size (1/m).</summary>
        public float InverseCellSize;
        /// <summary>Cells along each axis.</summary>
        public int3 GridDimensions;
        /// <summary>Cells in all (the dead key).</summary>
        public uint CellCount;
        public float3 DomainMin;
        public float WallDistance;
        public float3 DomainMax;
        /// <summary>The position-based walls' density scale κ.</summary>
        public float WallScale;
        public float3 Gravity;
        /// <summary>Position-based artificial pressure k·λ₁ (m²).</summary>
        public float ArtificialPressureScale;
        /// <summary>Kernel radius H (m).</summary>
        public float SmoothingLength;
        public float SmoothingLengthSquared;
        public float Poly6Coefficient;
        public float SpikyGradientCoefficient;
        public float CohesionCoefficient;
        public float CohesionOffset;
        public float ViscosityLaplacianCoefficient;
        /// <summary>Gradient correction κ∇.</summary>
        public float GradientCorrection;
        public float ParticleMass;
        /// <summary>ρ₀ (kg/m³).</summary>
        public float RestDensity;
        /// <summary>Tait B (Pa).</summary>
        public float TaitStiffness;
        public float MaxDensityRatio;
        /// <summary>Substep h (s).</summary>
        public float SubstepSeconds;
        public float MaxSpeed;
        /// <summary>2·α·c₀·H.</summary>
        public float ArtificialViscosity;
        /// <summary>Position-based relaxation ε.</summary>
        public float Relaxation;
        public float CohesionWeight;
        public float SeparationWeight;
        public float ParticleSpacing;
        public float SurfaceTension;
        /// <summary>h·ν·2m·(Laplacian coefficient)·(viscosity correction).</summary>
        public float ViscosityScale;
        /// <summary>1 − e^(−rate·h).</summary>
        public float AlignmentBlend;
        /// <summary>Step dt (s).</summary>
        public float StepSeconds;
        public float BulkPressureScale;
        /// <summary>1 for the weakly compressible solver, 0 for position-based.</summary>
        public uint WeaklyCompressible;
        /// <summary>1 when flocking cohesion acts.</summary>
        public uint Flocking;
        /// <summary>1 when Akinci surface tension acts.</summary>
        public uint Akinci;
        /// <summary>Colliders at the start of <see cref="FluidComputeBuffer.Shapes"/> (<see cref="FluidComputeStep.PackShapes"/>).</summary>
        public uint ColliderCount;
        /// <summary>The domain faces' friction μ per axis.</summary>
        public float3 DomainFriction;
        public float ColliderFriction;
        /// <summary>The domain's extent on its periodic axes (m), 0 on the others.</summary>
        public float3 Period;
        /// <summary>1 when any axis is periodic.</summary>
        public float IsPeriodic;
        /// <summary>1 / the period on the periodic axes (1/m), 0 on the others.</summary>
        public float3 InversePeriod;
        /// <summary>Drains in <see cref="FluidComputeBuffer.Shapes"/> after the colliders.</summary>
        public uint DrainCount;
        /// <summary>No-slip share of the domain faces per axis (0 on periodic axes).</summary>
        public float3 FaceNoSlip;
        public float ColliderNoSlip;
        /// <summary><see cref="FluidConstants.GradientTraceScale"/>.</summary>
        public float GradientTraceScale;
        /// <summary><see cref="FluidConstants.MaxGradientRenormalization"/>.</summary>
        public float MaxGradientRenormalization;
        /// <summary><see cref="FluidConstants.ViscosityMomentScale"/>.</summary>
        public float ViscosityMomentScale;
        /// <summary>Unused: fills the last 16-byte row.</summary>
        public float Padding;

        /// <summary>
        /// The constants for substeps of <paramref name="h"/> seconds in a step of <paramref name="dt"/> seconds, with
        /// <paramref name="colliders"/> colliders and <paramref name="drains"/> drains packed in the shape buffer.
        /// </summary>
        public static FluidComputeConstants Of(in FluidConstants c, float h, float dt, int colliders = 0, int drains = 0)
        {
            FluidParameters p = c.Parameters;
            SphKernels k = c.Kernels;
            FluidGrid g = c.Grid;
            bool flocking = p.Cohesion == FluidCohesionModel.Flocking && (p.CohesionWeight > 0f || p.SeparationWeight > 0f);
            bool akinci = p.Cohesion == FluidCohesionModel.Akinci && p.SurfaceTension > 0f;
            return new FluidComputeConstants
            {
                GridOrigin = g.Origin,
                InverseCellSize = g.InverseCellSize,
                GridDimensions = g.Dimensions,
                CellCount = (uint)g.CellCount,
                DomainMin = p.DomainMin,
                WallDistance = c.WallDistance,
                DomainMax = p.DomainMax,
                WallScale = c.WallScale,
                Gravity = p.Gravity,
                ArtificialPressureScale = c.ArtificialPressureScale,
                SmoothingLength = k.H,
                SmoothingLengthSquared = k.H2,
                Poly6Coefficient = k.Poly6Coefficient,
                SpikyGradientCoefficient = k.SpikyGradientCoefficient,
                CohesionCoefficient = k.CohesionCoefficient,
                CohesionOffset = k.CohesionOffset,
                ViscosityLaplacianCoefficient = k.ViscosityLaplacianCoefficient,
                GradientCorrection = c.GradientCorrection,
                ParticleMass = c.Mass,
                RestDensity = p.RestDensity,
                TaitStiffness = c.TaitStiffness,
                MaxDensityRatio = p.MaxDensityRatio,
                SubstepSeconds = h,
                MaxSpeed = p.MaxSpeed,
                ArtificialViscosity = 2f * c.EffectiveArtificialViscosity * p.SpeedOfSound * k.H,
                Relaxation = c.Relaxation,
                CohesionWeight = p.CohesionWeight,
                SeparationWeight = p.SeparationWeight,
                ParticleSpacing = p.ParticleSpacing,
                SurfaceTension = p.SurfaceTension,
                // The same expressions as FluidPasses.ViscosityIteration and Alignment, so the GPU gets the CPU's bits.
                ViscosityScale = h * p.Viscosity * 2f * c.Mass * k.ViscosityLaplacianCoefficient * c.ViscosityCorrection,
                AlignmentBlend = 1f - math.exp(-p.VelocitySmoothingRate * h),
                StepSeconds = dt,
                BulkPressureScale = c.BulkPressureScale,
                WeaklyCompressible = p.Solver == FluidSolverKind.WeaklyCompressible ? 1u : 0u,
                Flocking = flocking ? 1u : 0u,
                Akinci = akinci ? 1u : 0u,
                ColliderCount = (uint)colliders,
                DomainFriction = p.DomainFriction,
                ColliderFriction = p.WallFriction,
                Period = c.Period,
                IsPeriodic = c.IsPeriodic ? 1f : 0f,
                InversePeriod = c.InversePeriod,
                DrainCount = (uint)drains,
                FaceNoSlip = c.FaceNoSlip,
                ColliderNoSlip = p.WallNoSlip,
                GradientTraceScale = c.GradientTraceScale,
                MaxGradientRenormalization = FluidConstants.MaxGradientRenormalization,
                ViscosityMomentScale = c.ViscosityMomentScale,
            };
        }
    }
}
