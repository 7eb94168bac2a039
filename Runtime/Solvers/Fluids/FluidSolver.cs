using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One step of a particle fluid, the single-threaded reference that the jobs reproduce pass by pass
    /// (<see cref="FluidPasses"/>). A step of dt runs n = ⌈dt / h_CFL⌉ substeps (at most
    /// <see cref="FluidParameters.MaxSubsteps"/>, reported when capped). Each substep:
    /// <list type="bullet">
    /// <item>weakly compressible: keys → counting sort (drops removed particles) → density and Tait pressure →
    /// forces (pressure, gravity, walls, cohesion) → implicit viscosity → alignment → advect → colliders;</item>
    /// <item>position-based: predict → keys → sort → (density → λ → Δx) × iterations → v = Δx/h → cohesion →
    /// implicit viscosity → alignment → colliders.</item>
    /// </list>
    /// </summary>
    public static class FluidSolver
    {
        /// <summary>
        /// The CFL-limited substep (s) for the fastest speed <paramref name="maxSpeed"/> (m/s) over a step of
        /// <paramref name="dt"/>: weakly compressible λh/(c₀ + v) (sound must not cross a kernel in one substep);
        /// position-based λh/v with v including what gravity adds over the step (a particle moves at most λh per
        /// substep, so the neighbour lists stay valid).
        /// </summary>
        public static float CflSubstep(in FluidConstants c, float maxSpeed, float dt)
        {
            FluidParameters p = c.Parameters;
            float lh = p.CflNumber * p.KernelRadius;
            if (p.Solver == FluidSolverKind.WeaklyCompressible)
                return lh / (p.SpeedOfSound + maxSpeed);
            float v = maxSpeed + math.length(p.Gravity) * dt;
            return v > 0f ? lh / v : dt;
        }

        /// <summary>Substeps for a step of <paramref name="dt"/> at fastest speed <paramref name="maxSpeed"/>: (wanted, used).</summary>
        public static int2 Substeps(in FluidConstants c, float maxSpeed, float dt)
        {
            float limit = CflSubstep(c, maxSpeed, dt);
            float ratio = dt / limit;
            int wanted = ratio < FluidParameters.SubstepLimit * 4f ? math.max(1, (int)math.ceil(ratio)) : FluidParameters.SubstepLimit * 4;
            return new int2(wanted, math.min(wanted, c.Parameters.MaxSubsteps));
        }

        /// <summary>Advances the fluid by <paramref name="dt"/> seconds (see the class comment).</summary>
        /// <param name="colliders">Static colliders in world space (the soft bodies' collider shapes).</param>
        public static FluidStepReport Step(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, float dt,
            FluidParticles p, FluidScratch s, ref FluidStatus status)
        {
            var report = new FluidStepReport();
            int count = math.clamp(status.Count, 0, p.Capacity);
            if (!(dt > 0f) || !math.isfinite(dt))
            {
                report.Count = count;
                return report;
            }
            for (int i = 0; i < count; i++)
                p.Ages[i] += dt;
            float maxSpeed = 0f;
            for (int i = 0; i < count; i++)
            {
                float v2 = math.lengthsq(p.Velocities[i]);
                if (v2 > maxSpeed)
                    maxSpeed = v2;
            }
            // A non-finite speed belongs to a particle the first sort removes; it must not set the substep.
            maxSpeed = math.isfinite(maxSpeed) ? math.min(math.sqrt(maxSpeed), c.Parameters.MaxSpeed) : c.Parameters.MaxSpeed;
            int2 substeps = Substeps(c, maxSpeed, dt);
            report.SubstepsWanted = substeps.x;
            report.Substeps = substeps.y;
            float h = dt / substeps.y;
            var counters = new FluidPassCounters();
            for (int k = 0; k < substeps.y; k++)
            {
                count = c.Parameters.Solver == FluidSolverKind.WeaklyCompressible
                    ? WeaklyCompressibleSubstep(c, colliders, p, s, count, h, ref counters)
                    : PositionBasedSubstep(c, colliders, p, s, count, h, ref counters);
            }
            status.Count = count;
            status.Time += dt;
            status.Killed += counters.Killed;
            status.Expired += counters.Expired;
            status.Invalid += counters.Invalid;
            report.Killed = counters.Killed;
            report.Expired = counters.Expired;
            report.Invalid = counters.Invalid;
            report.SpeedClamped = counters.SpeedClamped;
            report.OverCompressed = counters.OverCompressed;
            report.NeighbourOverflow = counters.NeighbourOverflow;
            report.MaxDensityRatio = counters.MaxDensityRatio;
            report.Contacts = counters.Contacts;
            report.Count = count;
            return report;
        }

        /// <summary>Keys, sort and the permutation of every particle array (and <see cref="FluidScratch.Previous"/> when asked). Returns the live count.</summary>
        public static int SortParticles(in FluidConstants c, FluidParticles p, FluidScratch s, int count, bool previous, ref FluidPassCounters counters)
        {
            FluidPasses.Keys(c, p, s, 0, count, ref counters);
            int live = FluidPasses.Sort(c.Grid, s, count);
            FluidPasses.Permute(p.Positions, s.VectorsA, s.Order, live);
            FluidPasses.Permute(p.Velocities, s.VectorsA, s.Order, live);
            if (previous)
                FluidPasses.Permute(s.Previous, s.VectorsA, s.Order, live);
            FluidPasses.Permute(p.Ages, s.Floats, s.Order, live);
            FluidPasses.Permute(p.Lifetimes, s.Floats, s.Order, live);
            FluidPasses.Permute(p.Attributes, s.Floats, s.Order, live);
            FluidPasses.Permute(p.Ids, s.Ints, s.Order, live);
            return live;
        }

        static int WeaklyCompressibleSubstep(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidParticles p,
            FluidScratch s, int count, float h, ref FluidPassCounters counters)
        {
            count = SortParticles(c, p, s, count, false, ref counters);
            FluidPasses.Density(c, colliders, p, s, 0, count, ref counters);
            if (c.Parameters.Cohesion == FluidCohesionModel.Akinci && c.Parameters.SurfaceTension > 0f)
                FluidPasses.SurfaceNormals(c, p, s, 0, count);
            FluidPasses.Forces(c, colliders, p, s, s.VectorsA, 0, count, h, true);
            s.VectorsA.Slice(0, count).CopyTo(p.Velocities);
            SmoothVelocities(c, p, s, count, h);
            FluidPasses.Advect(c, p, s, 0, count, h, ref counters);
            Collide(c, colliders, p, s, count, h, ref counters);
            return count;
        }

        static int PositionBasedSubstep(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidParticles p,
            FluidScratch s, int count, float h, ref FluidPassCounters counters)
        {
            FluidPasses.Predict(c, p, s, 0, count, h, ref counters);
            count = SortParticles(c, p, s, count, true, ref counters);
            for (int it = 0; it < c.Parameters.PressureIterations; it++)
            {
                // The neighbour lists come from the first density pass; later ones refresh only the densities.
                if (it == 0)
                    FluidPasses.Density(c, colliders, p, s, 0, count, ref counters);
                else
                    FluidPasses.DensityFromNeighbours(c, colliders, p, s, 0, count, ref counters);
                FluidPasses.Lambda(c, colliders, p, s, 0, count);
                FluidPasses.Correction(c, colliders, p, s, 0, count);
                FluidPasses.ApplyCorrection(c, p, s, 0, count);
            }
            FluidPasses.VelocityFromPositions(p, s, 0, count, h);
            bool cohesion = c.Parameters.Cohesion != FluidCohesionModel.None;
            if (cohesion)
            {
                if (c.Parameters.Cohesion == FluidCohesionModel.Akinci)
                    FluidPasses.SurfaceNormals(c, p, s, 0, count);
                FluidPasses.Forces(c, colliders, p, s, s.VectorsA, 0, count, h, false);
                s.VectorsA.Slice(0, count).CopyTo(p.Velocities);
            }
            SmoothVelocities(c, p, s, count, h);
            Collide(c, colliders, p, s, count, h, ref counters);
            return count;
        }

        /// <summary>Implicit viscosity (Jacobi iterations, ping-pong through the two vector scratch arrays) and alignment.</summary>
        static void SmoothVelocities(in FluidConstants c, FluidParticles p, FluidScratch s, int count, float h)
        {
            int iterations = c.Parameters.Viscosity > 0f ? c.Parameters.ViscosityIterations : 0;
            if (iterations > 0)
            {
                p.Velocities.Slice(0, count).CopyTo(s.VectorsA);
                for (int it = 0; it < iterations; it++)
                {
                    bool even = (it & 1) == 0;
                    FluidPasses.ViscosityIteration(c, p, s, even ? s.VectorsA : s.VectorsB, even ? s.VectorsB : s.VectorsA, 0, count, h);
                }
                ((iterations & 1) == 1 ? s.VectorsB : s.VectorsA).Slice(0, count).CopyTo(p.Velocities);
            }
            if (c.Parameters.Cohesion == FluidCohesionModel.Flocking && c.Parameters.AlignmentRate > 0f)
            {
                FluidPasses.Alignment(c, p, s, s.VectorsA, 0, count, h);
                s.VectorsA.Slice(0, count).CopyTo(p.Velocities);
            }
        }

        static void Collide(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidParticles p, FluidScratch s, int count,
            float h, ref FluidPassCounters counters)
        {
            if (colliders.Length == 0 || count == 0)
                return;
            var settings = new ContactProjection.Settings
            {
                Radius = c.WallDistance,
                Friction = c.Parameters.WallFriction,
                Restitution = 0f,
                BounceThreshold = float.PositiveInfinity,
                MaxDepenetration = c.Parameters.MaxSpeed * h,
                Origin = float3.zero,
            };
            counters.Contacts += ContactProjection.Project(s.Previous.Slice(0, count), p.Positions.Slice(0, count),
                p.Velocities.Slice(0, count), s.VectorsA.Slice(0, count), colliders, settings, h);
        }
    }
}
