using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The constants of the fluid kernels (the float4 / uint4 globals of FluidCommon.hlsl), computed on the CPU from a
    /// fluid's <see cref="FluidConstants"/>, the substep h and the step dt.
    /// </summary>
    public struct FluidComputeConstants
    {
        public float4 GridOrigin, DomainMin, DomainMax, Gravity, Kernel, Kernel2, Material, Motion, Cohesion, Smoothing, Colliding;
        /// <summary>xyz the periodic axes' periods (0 elsewhere), w 1 when any axis is periodic; xyz their inverses; xyz the faces' no-slip shares (0 on periodic axes).</summary>
        public float4 Period, InversePeriod, NoSlip;
        /// <summary>x <see cref="FluidConstants.GradientTraceScale"/>, y <see cref="FluidConstants.GradientWallScale"/>, z <see cref="FluidConstants.MaxGradientRenormalization"/>.</summary>
        public float4 Renormalization;
        /// <summary>x colliders, y drains in <see cref="FluidComputeBuffer.Shapes"/> (<see cref="FluidComputeStep.PackShapes"/>).</summary>
        public int4 GridDims, Flags, ShapeCounts;

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
                GridOrigin = new float4(g.Origin, g.InverseCellSize),
                GridDims = new int4(g.Dimensions.x, g.Dimensions.y, g.Dimensions.z, g.CellCount),
                DomainMin = new float4(p.DomainMin, c.WallDistance),
                DomainMax = new float4(p.DomainMax, c.WallScale),
                Gravity = new float4(p.Gravity, c.ArtificialPressureScale),
                Kernel = new float4(k.H, k.H2, k.Poly6Coefficient, k.SpikyGradientCoefficient),
                Kernel2 = new float4(k.CohesionCoefficient, k.CohesionOffset, k.ViscosityLaplacianCoefficient, c.GradientCorrection),
                Material = new float4(c.Mass, p.RestDensity, c.TaitStiffness, p.MaxDensityRatio),
                Motion = new float4(h, p.MaxSpeed, 2f * p.ArtificialViscosity * p.SpeedOfSound * k.H, c.Relaxation),
                Cohesion = new float4(p.CohesionWeight, p.SeparationWeight, p.ParticleSpacing, p.SurfaceTension),
                // The same expressions as FluidPasses.ViscosityIteration and Alignment, so the GPU gets the CPU's bits.
                Smoothing = new float4(h * p.Viscosity * 2f * c.Mass * k.ViscosityLaplacianCoefficient * c.ViscosityCorrection,
                    1f - math.exp(-p.AlignmentRate * h), dt, c.BulkPressureScale),
                Flags = new int4(p.Solver == FluidSolverKind.WeaklyCompressible ? 1 : 0, flocking ? 1 : 0, akinci ? 1 : 0, 0),
                ShapeCounts = new int4(colliders, drains, 0, 0),
                Colliding = new float4(p.WallFriction, p.DomainFriction.x, p.DomainFriction.y, p.DomainFriction.z),
                Period = new float4(c.Period, c.IsPeriodic ? 1f : 0f),
                InversePeriod = new float4(c.InversePeriod, 0f),
                NoSlip = new float4(c.FaceNoSlip, p.WallNoSlip),
                Renormalization = new float4(c.GradientTraceScale, c.GradientWallScale, FluidConstants.MaxGradientRenormalization, 0f),
            };
        }

        /// <summary>Sets every constant on <paramref name="commands"/>.</summary>
        public void Set<T>(ref T commands) where T : IFluidComputeCommands
        {
            commands.SetVector(FluidComputeGlobal.GridOrigin, GridOrigin);
            commands.SetInts(FluidComputeGlobal.GridDims, GridDims);
            commands.SetVector(FluidComputeGlobal.DomainMin, DomainMin);
            commands.SetVector(FluidComputeGlobal.DomainMax, DomainMax);
            commands.SetVector(FluidComputeGlobal.Gravity, Gravity);
            commands.SetVector(FluidComputeGlobal.Kernel, Kernel);
            commands.SetVector(FluidComputeGlobal.Kernel2, Kernel2);
            commands.SetVector(FluidComputeGlobal.Material, Material);
            commands.SetVector(FluidComputeGlobal.Motion, Motion);
            commands.SetVector(FluidComputeGlobal.Cohesion, Cohesion);
            commands.SetVector(FluidComputeGlobal.Smoothing, Smoothing);
            commands.SetInts(FluidComputeGlobal.Flags, Flags);
            commands.SetInts(FluidComputeGlobal.ShapeCounts, ShapeCounts);
            commands.SetVector(FluidComputeGlobal.Colliding, Colliding);
            commands.SetVector(FluidComputeGlobal.Period, Period);
            commands.SetVector(FluidComputeGlobal.InversePeriod, InversePeriod);
            commands.SetVector(FluidComputeGlobal.NoSlip, NoSlip);
            commands.SetVector(FluidComputeGlobal.Renormalization, Renormalization);
        }
    }
}
