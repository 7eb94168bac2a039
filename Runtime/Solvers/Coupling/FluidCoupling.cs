using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Fluid and bodies acting on each other, two ways: a fluid step in which each body is a moving wall
    /// (<see cref="FluidBodyProxy"/>). Every substep the colliders are the static ones and the proxies at their current
    /// placement; the weakly compressible walls' ghosts take the proxy's surface velocity; after the forces the fluid's
    /// push on each proxy is summed (<see cref="FluidPasses.MovingColliderLoads"/>), after the colliders a particle inside a
    /// proxy is put back on its surface (<see cref="FluidPasses.CollideMoving"/>, its momentum change counted too); then
    /// each proxy moves one substep under gravity and that load. The body takes the summed impulse in its next step,
    /// so the fluid's and the bodies' momentum change by opposite amounts (a pair of forces per ghost, to float round-off).
    /// Sums run in slot order, one thread: the same bits for every batch count.
    /// Position-based fluids see the proxies as moving walls and pass on only the contact impulses (their wall push has no
    /// ghosts to sum): no buoyancy.
    /// </summary>
    public static class FluidCoupling
    {
        /// <summary>Most proxies one step takes (the loads are summed on the stack).</summary>
        public const int MaxBodies = 64;

        /// <summary>
        /// Advances the fluid by <paramref name="dt"/> with <paramref name="bodies"/> as moving walls, as
        /// <see cref="FluidSolver.Step(in FluidConstants, ReadOnlySpan{ColliderShape}, float, FluidParticles, FluidScratch, ref FluidStatus, int)"/>
        /// does without them. Each proxy leaves with its placement at the step's end and its <see cref="FluidBodyProxy.Impulse"/>
        /// and <see cref="FluidBodyProxy.AngularImpulse"/> over the step; past <see cref="MaxBodies"/> the rest are not seen.
        /// </summary>
        public static FluidStepReport Step(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, Span<FluidBodyProxy> bodies,
            float dt, FluidParticles p, FluidScratch s, ref FluidStatus status, int batches = 1)
        {
            for (int b = 0; b < bodies.Length; b++)
            {
                bodies[b].Impulse = float3.zero;
                bodies[b].AngularImpulse = float3.zero;
            }
            int bodyCount = math.min(bodies.Length, MaxBodies);
            if (bodyCount == 0)
                return FluidSolver.Step(c, colliders, dt, p, s, ref status, batches);
            FluidSolver.Plan plan = FluidSolver.Begin(c, dt, p, ref status);
            int count = status.Count;
            var counters = new FluidPassCounters();
            Span<FluidPass> passes = stackalloc FluidPass[FluidSubstepPasses.MaxPasses];
            int passCount = FluidSubstepPasses.Write(c, plan.H, colliders.Length > 0, passes);
            batches = math.max(1, batches);
            bool cull = colliders.Length > 0 && colliders.Length <= FluidColliderReach.MaxCulled && FluidColliderReach.Culls(c);
            Span<ColliderShape> world = stackalloc ColliderShape[colliders.Length + bodyCount];
            Span<float3> forces = stackalloc float3[bodyCount];
            Span<float3> torques = stackalloc float3[bodyCount];
            float3 gravity = c.Parameters.Gravity;
            for (int k = 0; k < plan.Substeps; k++)
            {
                int statics = cull
                    ? FluidColliderReach.Near(c, colliders, p.Positions.Slice(0, count), plan.H, world)
                    : Copy(colliders, world);
                for (int b = 0; b < bodyCount; b++)
                    world[statics + b] = bodies[b].Shape;
                ReadOnlySpan<ColliderShape> all = world.Slice(0, statics + bodyCount);
                forces.Clear();
                torques.Clear();
                for (int q = 0; q < passCount; q++)
                {
                    // The static colliders' contacts stay the shared pass; the proxies' follow it.
                    ReadOnlySpan<ColliderShape> seen = passes[q] == FluidPass.Collide ? all.Slice(0, statics) : all;
                    for (int b = 0; b < batches; b++)
                        FluidPasses.Run(passes[q], c, seen, p, s, b, batches, ref count, plan.H, ref counters);
                    if (passes[q] == FluidPass.Forces)
                        FluidPasses.MovingColliderLoads(c, all, statics, p, s, 0, count, forces, torques);
                }
                FluidPasses.CollideMoving(c, all, statics, p, 0, count, plan.H, forces, torques, ref counters);
                for (int b = 0; b < bodyCount; b++)
                    bodies[b].Advance(forces[b], torques[b], gravity, plan.H);
            }
            return FluidSolver.Finish(plan, counters, dt, count, ref status);
        }

        static int Copy(ReadOnlySpan<ColliderShape> from, Span<ColliderShape> to)
        {
            from.CopyTo(to);
            return from.Length;
        }
    }
}
