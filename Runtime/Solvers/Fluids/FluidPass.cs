using System;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>One pass of a fluid substep (a <see cref="FluidPasses"/> range function, or a copy between arrays).</summary>
    public enum FluidPass : byte
    {
        /// <summary>Keys, counting sort and permutation (sequential: one batch).</summary>
        Sort,
        /// <summary>The same, also permuting the start-of-substep positions (position-based).</summary>
        SortWithPrevious,
        Density, DensityFromNeighbours, SurfaceNormals,
        /// <summary>Pressure, artificial viscosity, gravity, walls and cohesion into VectorsA.</summary>
        Forces,
        /// <summary>Cohesion only into VectorsA (position-based).</summary>
        CohesionForces,
        CopyAToVelocities, CopyVelocitiesToA, ViscosityAToB, ViscosityBToA, CopyBToVelocities, Alignment, Advect, Predict, Lambda,
        Correction, ApplyCorrection, VelocityFromPositions, Collide,
    }

    /// <summary>
    /// The passes of one substep for a fluid's settings, in order: the single definition of a substep, which
    /// <see cref="FluidSolver"/> runs single-threaded (or batch by batch) and the ECS job chain schedules as parallel jobs.
    /// </summary>
    public static class FluidSubstepPasses
    {
        /// <summary>Most passes one substep can have.</summary>
        public const int MaxPasses = 16 + 4 * FluidParameters.MaxPressureIterations + FluidParameters.MaxViscosityIterations;

        /// <summary>
        /// Writes the passes of one substep of <paramref name="h"/> seconds of the fluid <paramref name="c"/> into
        /// <paramref name="passes"/> (the viscosity iterations follow the substep, <see cref="FluidSolver.ViscosityIterations"/>);
        /// returns how many.
        /// </summary>
        public static int Write(in FluidConstants c, float h, bool colliders, Span<FluidPass> passes)
        {
            FluidParameters p = c.Parameters;
            int viscosityIterations = FluidSolver.ViscosityIterations(c, h);
            int n = 0;
            bool akinci = p.Cohesion == FluidCohesionModel.Akinci && p.SurfaceTension > 0f;
            if (p.Solver == FluidSolverKind.WeaklyCompressible)
            {
                passes[n++] = FluidPass.Sort;
                passes[n++] = FluidPass.Density;
                if (akinci)
                    passes[n++] = FluidPass.SurfaceNormals;
                passes[n++] = FluidPass.Forces;
                passes[n++] = FluidPass.CopyAToVelocities;
                n = Smooth(p, viscosityIterations, passes, n);
                passes[n++] = FluidPass.Advect;
            }
            else
            {
                passes[n++] = FluidPass.Predict;
                passes[n++] = FluidPass.SortWithPrevious;
                for (int it = 0; it < p.PressureIterations; it++)
                {
                    // The neighbour lists come from the first density pass; later ones refresh only the densities.
                    passes[n++] = it == 0 ? FluidPass.Density : FluidPass.DensityFromNeighbours;
                    passes[n++] = FluidPass.Lambda;
                    passes[n++] = FluidPass.Correction;
                    passes[n++] = FluidPass.ApplyCorrection;
                }
                passes[n++] = FluidPass.VelocityFromPositions;
                if (p.Cohesion != FluidCohesionModel.None)
                {
                    if (p.Cohesion == FluidCohesionModel.Akinci)
                        passes[n++] = FluidPass.SurfaceNormals;
                    passes[n++] = FluidPass.CohesionForces;
                    passes[n++] = FluidPass.CopyAToVelocities;
                }
                n = Smooth(p, viscosityIterations, passes, n);
            }
            if (colliders)
                passes[n++] = FluidPass.Collide;
            return n;
        }

        /// <summary>Implicit viscosity (Jacobi iterations ping-ponging through the two vector scratch arrays) and XSPH smoothing.</summary>
        static int Smooth(in FluidParameters p, int iterations, Span<FluidPass> passes, int n)
        {
            if (iterations > 0)
            {
                passes[n++] = FluidPass.CopyVelocitiesToA;
                for (int it = 0; it < iterations; it++)
                    passes[n++] = (it & 1) == 0 ? FluidPass.ViscosityAToB : FluidPass.ViscosityBToA;
                passes[n++] = (iterations & 1) == 1 ? FluidPass.CopyBToVelocities : FluidPass.CopyAToVelocities;
            }
            if (p.VelocitySmoothingRate > 0f)
            {
                passes[n++] = FluidPass.Alignment;
                passes[n++] = FluidPass.CopyAToVelocities;
            }
            return n;
        }
    }
}
