using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One step of a particle fluid, the single-threaded reference that the jobs reproduce pass by pass
    /// (<see cref="FluidPasses"/>). A step of dt runs n = ⌈dt / h_max⌉ substeps of h = dt / n, h_max the CFL limit (and,
    /// position-based, the depth limit <see cref="DepthSubstep"/>). When n is above
    /// <see cref="FluidParameters.MaxSubsteps"/> the step runs the cap's substeps of the same h and so simulates less than dt
    /// (slow motion, reported in <see cref="FluidStepReport.SimulatedTime"/>): stretching them to dt would break the CFL
    /// limit and compress the fluid many times over. Each substep:
    /// <list type="bullet">
    /// <item>weakly compressible: keys → counting sort (drops removed particles) → density and Tait pressure →
    /// forces (pressure, gravity, walls, cohesion) → implicit viscosity → alignment → advect → colliders;</item>
    /// <item>position-based: predict → keys → sort → (density → λ → Δx) × iterations → v = Δx/h → cohesion →
    /// implicit viscosity → alignment → colliders.</item>
    /// </list>
    /// The list of passes is <see cref="FluidSubstepPasses.Write"/>, run by <see cref="FluidPasses.Run"/> here and in the
    /// ECS job chain.
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

        /// <summary>
        /// Constant A of the density error a position-based column D metres deep settles to with substeps of h seconds,
        /// ε ≈ A·g·h²·D / (Δx²·iterations): each substep gravity presses the column by g·h², and the Jacobi iterations lift
        /// it back only a few layers per iteration, so the error grows with the layers D/Δx over the iterations. Fitted on
        /// 10-, 20- and 40-layer columns at Δx = 2 cm, h = 2Δx, 8 to 32 iterations × substeps per 1/60 s frame: 0.22–0.26
        /// where ε was 1–4 % (0.38 at 0.8 %; docs: fluids.md).
        /// </summary>
        public const float PositionBasedDepthErrorFactor = 0.23f;

        /// <summary>Position-based: the density error the depth rule of <see cref="Substeps"/> allows (1 %).</summary>
        public const float PositionBasedDepthTolerance = 0.01f;

        /// <summary>
        /// Position-based: the longest substep (s) that keeps the settled density error of a column <paramref name="depth"/>
        /// metres deep (<see cref="PositionBasedDepthErrorFactor"/>) within <see cref="PositionBasedDepthTolerance"/>:
        /// h = Δx·√(ε·iterations / (A·g·D)); infinity without depth or gravity.
        /// </summary>
        public static float DepthSubstep(in FluidConstants c, float depth)
        {
            FluidParameters p = c.Parameters;
            float g = math.length(p.Gravity);
            if (p.Solver != FluidSolverKind.PositionBased || !(depth > 0f) || !(g > 0f))
                return float.PositiveInfinity;
            float dx = p.ParticleSpacing;
            return dx * math.sqrt(PositionBasedDepthTolerance * p.PressureIterations / (PositionBasedDepthErrorFactor * g * depth));
        }

        /// <summary>Share of the implicit viscosity's smooth part a substep's Jacobi iterations may leave (1 %).</summary>
        public const float ViscosityTolerance = 0.01f;

        /// <summary>
        /// Jacobi iterations that bring the smooth (steady) part of the implicit viscosity to <see cref="ViscosityTolerance"/>
        /// of its solution at a substep of <paramref name="h"/> seconds: each iteration removes the share 1/(1 + a) of it,
        /// a = hν·Σw the solve's diagonal over the rest lattice ≈ 15·hν·κ_ν/h_kernel², so n = ln 0.01 / ln(a/(1 + a)); 1 when a
        /// is tiny, 10⁶ when it is huge.
        /// </summary>
        public static int ViscosityIterationsNeeded(in FluidConstants c, float h)
        {
            float kernel = c.Kernels.H;
            float a = 15f * h * c.Parameters.Viscosity * c.ViscosityCorrection / (kernel * kernel);
            if (!(a > 0f))
                return 1;
            float n = math.log(ViscosityTolerance) / math.log(a / (1f + a));
            return n < 1e6f ? math.max(1, (int)math.ceil(n)) : 1000000;
        }

        /// <summary>
        /// The viscosity iterations a substep of <paramref name="h"/> seconds runs: <see cref="FluidParameters.ViscosityIterations"/>,
        /// raised up to <see cref="FluidParameters.MaxViscosityIterations"/> when <see cref="ViscosityIterationsNeeded"/> asks for
        /// more (a truncated solve lets a steady shear flow run faster than the viscosity allows); 0 without viscosity or
        /// with 0 iterations asked for.
        /// </summary>
        public static int ViscosityIterations(in FluidConstants c, float h)
        {
            FluidParameters p = c.Parameters;
            if (!(p.Viscosity > 0f) || p.ViscosityIterations <= 0)
                return 0;
            return math.max(p.ViscosityIterations, math.min(ViscosityIterationsNeeded(c, h), FluidParameters.MaxViscosityIterations));
        }

        /// <summary>
        /// Substeps for a step of <paramref name="dt"/> at fastest speed <paramref name="maxSpeed"/> (m/s) of a fluid
        /// <paramref name="depth"/> metres deep along gravity (position-based only: <see cref="DepthSubstep"/>): (wanted, used).
        /// At least <see cref="FluidParameters.MinSubsteps"/> are wanted, up to the cap.
        /// </summary>
        public static int2 Substeps(in FluidConstants c, float maxSpeed, float depth, float dt)
        {
            float limit = math.min(CflSubstep(c, maxSpeed, dt), DepthSubstep(c, depth));
            float ratio = dt / limit;
            int wanted = ratio < FluidParameters.SubstepLimit * 4f ? math.max(1, (int)math.ceil(ratio)) : FluidParameters.SubstepLimit * 4;
            wanted = math.max(wanted, math.min(c.Parameters.MinSubsteps, c.Parameters.MaxSubsteps));
            return new int2(wanted, math.min(wanted, c.Parameters.MaxSubsteps));
        }

        /// <summary>
        /// The plan of a step of <paramref name="dt"/> with (wanted, used) <paramref name="substeps"/>: substeps of
        /// h = dt / wanted, so that a capped step simulates used · h &lt; dt instead of breaking the CFL limit.
        /// </summary>
        public static Plan PlanOf(float dt, int2 substeps)
        {
            float h = dt / substeps.x;
            return new Plan
            {
                Substeps = substeps.y, SubstepsWanted = substeps.x, H = h,
                SimulatedTime = substeps.y < substeps.x ? substeps.y * h : dt,
            };
        }

        /// <summary>The substeps of one step, fixed at its start (<see cref="Begin"/>).</summary>
        public struct Plan
        {
            /// <summary>Substeps to run.</summary>
            public int Substeps;
            /// <summary>Substeps the limits asked for: CFL, and position-based the depth rule (above <see cref="Substeps"/> when capped).</summary>
            public int SubstepsWanted;
            /// <summary>Substep length h = dt / <see cref="SubstepsWanted"/> (s); 0 when the step does nothing.</summary>
            public float H;
            /// <summary>Time the step simulates (s): dt, or Substeps · H when the cap held it back (slow motion).</summary>
            public float SimulatedTime;
        }

        /// <summary>
        /// Starts a step of <paramref name="dt"/>: ages the live particles and fixes the substeps from the fastest
        /// speed (a non-finite one belongs to a particle the first sort removes and does not count). The substeps are
        /// then the passes of <see cref="FluidSubstepPasses.Write"/> (here or as jobs), and <see cref="Finish"/> closes the step.
        /// </summary>
        public static Plan Begin(in FluidConstants c, float dt, FluidParticles p, ref FluidStatus status)
        {
            int count = math.clamp(status.Count, 0, p.Capacity);
            status.Count = count;
            if (!(dt > 0f) || !math.isfinite(dt))
                return new Plan();
            // A non-finite speed belongs to a particle the first sort removes: it must not set the substeps.
            float maxSpeed = 0f;
            for (int i = 0; i < count; i++)
            {
                float v2 = math.lengthsq(p.Velocities[i]);
                if (v2 > maxSpeed && v2 < float.PositiveInfinity)
                    maxSpeed = v2;
            }
            maxSpeed = math.min(math.sqrt(maxSpeed), c.Parameters.MaxSpeed);
            Plan plan = PlanOf(dt, Substeps(c, maxSpeed, Depth(c, p.Positions.Slice(0, count)), dt));
            for (int i = 0; i < count; i++)
                p.Ages[i] += plan.SimulatedTime;
            return plan;
        }

        /// <summary>
        /// Position-based: the depth the substep rule plans for (m), the extent of the particles along gravity plus one
        /// spacing (a splash above the pool counts as depth: the rule errs toward more substeps). Positions count clamped
        /// into the domain box (the step puts them there), so a stray 1e20 m cannot ask for every substep; non-finite ones
        /// are skipped. 0 for the weakly compressible solver, whose substep does not depend on it.
        /// </summary>
        public static float Depth(in FluidConstants c, ReadOnlySpan<float3> positions)
        {
            FluidParameters p = c.Parameters;
            float g = math.length(p.Gravity);
            if (p.Solver != FluidSolverKind.PositionBased || positions.Length == 0 || !(g > 0f))
                return 0f;
            float3 up = -p.Gravity / g;
            float lo = float.PositiveInfinity, hi = float.NegativeInfinity;
            for (int i = 0; i < positions.Length; i++)
            {
                float3 x = positions[i];
                if (!math.all(math.isfinite(x)))
                    continue;
                float y = math.dot(math.clamp(x, p.DomainMin, p.DomainMax) - p.DomainMin, up);
                lo = math.min(lo, y);
                hi = math.max(hi, y);
            }
            return hi >= lo ? hi - lo + p.ParticleSpacing : 0f;
        }

        /// <summary>Closes a step: the live count, time and removal totals into the status, the counters into the report.</summary>
        public static FluidStepReport Finish(in Plan plan, in FluidPassCounters counters, float dt, int count, ref FluidStatus status)
        {
            status.Count = count;
            if (plan.Substeps > 0)
                status.Time += plan.SimulatedTime;
            status.Killed += counters.Killed;
            status.Expired += counters.Expired;
            status.Invalid += counters.Invalid;
            return new FluidStepReport
            {
                Substeps = plan.Substeps,
                SubstepsWanted = plan.SubstepsWanted,
                SimulatedTime = plan.SimulatedTime,
                Killed = counters.Killed,
                Expired = counters.Expired,
                Invalid = counters.Invalid,
                SpeedClamped = counters.SpeedClamped,
                OverCompressed = counters.OverCompressed,
                NeighbourOverflow = counters.NeighbourOverflow,
                MaxDensityRatio = counters.MaxDensityRatio,
                Contacts = counters.Contacts,
                Count = count,
            };
        }

        /// <summary>Advances the fluid by <paramref name="dt"/> seconds (see the class comment).</summary>
        /// <param name="colliders">Static colliders in world space (the soft bodies' collider shapes).</param>
        public static FluidStepReport Step(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, float dt,
            FluidParticles p, FluidScratch s, ref FluidStatus status) => Step(c, colliders, dt, p, s, ref status, 1);

        /// <summary>
        /// As <see cref="Step(in FluidConstants, ReadOnlySpan{ColliderShape}, float, FluidParticles, FluidScratch, ref FluidStatus)"/>,
        /// with every range pass run in <paramref name="batches"/> equal batches, one after the other: the split the ECS job
        /// chain makes. The result has the same bits for every batch count.
        /// </summary>
        public static FluidStepReport Step(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, float dt,
            FluidParticles p, FluidScratch s, ref FluidStatus status, int batches)
        {
            Plan plan = Begin(c, dt, p, ref status);
            int count = status.Count;
            var counters = new FluidPassCounters();
            Span<FluidPass> passes = stackalloc FluidPass[FluidSubstepPasses.MaxPasses];
            int passCount = FluidSubstepPasses.Write(c, plan.H, colliders.Length > 0, passes);
            batches = math.max(1, batches);
            // Each substep sees only the colliders it can touch (FluidColliderReach): the same bits, less work.
            bool cull = colliders.Length > 0 && colliders.Length <= FluidColliderReach.MaxCulled && FluidColliderReach.Culls(c);
            Span<ColliderShape> near = stackalloc ColliderShape[cull ? colliders.Length : 0];
            for (int k = 0; k < plan.Substeps; k++)
            {
                ReadOnlySpan<ColliderShape> reach = cull
                    ? near.Slice(0, FluidColliderReach.Near(c, colliders, p.Positions.Slice(0, count), plan.H, near))
                    : colliders;
                for (int q = 0; q < passCount; q++)
                    for (int b = 0; b < batches; b++)
                        FluidPasses.Run(passes[q], c, reach, p, s, b, batches, ref count, plan.H, ref counters);
            }
            return Finish(plan, counters, dt, count, ref status);
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
    }
}
