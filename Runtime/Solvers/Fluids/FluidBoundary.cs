using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The walls as position-based fluids see them (static boundary matter, <see cref="Sample"/>; weakly compressible fluids
    /// see their mirror images instead, <see cref="FluidGhostWalls"/>), and the domain box's last word on a position: particle
    /// centres stay at least <see cref="FluidConstants.WallDistance"/> inside (or wrap on a periodic axis), with Coulomb
    /// friction per axis.
    /// </summary>
    public static class FluidBoundary
    {
        /// <summary>
        /// Position-based: the walls within h of <paramref name="x"/> as static boundary matter at rest density (Akinci et al.
        /// 2012's boundary particles, integrated in closed form over each wall's half-space): <paramref name="densityFraction"/>
        /// = 1 − Πₖ(1 − κΦ(dₖ)), the kernel's share outside the fluid (exact for the octant of a box corner, where a plain sum
        /// would count the corner three times), and <paramref name="push"/> = Σ κG(d)·n with n the unit normal out of the wall
        /// (1/m). κ is <see cref="FluidConstants.WallScale"/>. The faces of the domain box and every collider (its tangent
        /// plane at the closest point) count.
        /// </summary>
        public static void Sample(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, float3 x,
            out float densityFraction, out float3 push)
        {
            SphKernels k = c.Kernels;
            float3 below = x - c.Parameters.DomainMin;
            float3 above = c.Parameters.DomainMax - x;
            float inside = 1f;
            push = float3.zero;
            bool3 periodic = c.Parameters.Periodic;
            if (c.IsPeriodic)
            {
                // A periodic axis has no faces.
                below = math.select(below, new float3(float.PositiveInfinity), periodic);
                above = math.select(above, new float3(float.PositiveInfinity), periodic);
            }
            float nearest = math.min(math.cmin(below), math.cmin(above));
            if (nearest >= k.H && colliders.Length == 0)
            {
                // Interior particle, the common case: no wall within a kernel.
                densityFraction = 0f;
                return;
            }
            for (int axis = 0; axis < 3; axis++)
            {
                float dBelow = axis == 0 ? below.x : axis == 1 ? below.y : below.z;
                float dAbove = axis == 0 ? above.x : axis == 1 ? above.y : above.z;
                float3 n = axis == 0 ? new float3(1f, 0f, 0f) : axis == 1 ? new float3(0f, 1f, 0f) : new float3(0f, 0f, 1f);
                if (dBelow < k.H)
                {
                    inside *= 1f - c.WallScale * k.WallDensityFraction(dBelow);
                    push += c.WallScale * k.WallGradientMagnitude(dBelow) * n;
                }
                if (dAbove < k.H)
                {
                    inside *= 1f - c.WallScale * k.WallDensityFraction(dAbove);
                    push -= c.WallScale * k.WallGradientMagnitude(dAbove) * n;
                }
            }
            for (int w = 0; w < colliders.Length; w++)
            {
                // Penetration with radius h reports depth = h − d for every point closer than h to the surface.
                if (!ParticleCollision.Penetration(colliders[w], x, k.H, out float3 normal, out float depth))
                    continue;
                float d = k.H - depth;
                inside *= 1f - c.WallScale * k.WallDensityFraction(d);
                push += c.WallScale * k.WallGradientMagnitude(d) * normal;
            }
            densityFraction = 1f - inside;
        }

        /// <summary>
        /// Keeps <paramref name="x"/> at least <see cref="FluidConstants.WallDistance"/> inside the domain box and
        /// removes the velocity component into a face it touches; on a periodic axis it wraps <paramref name="x"/> into the box instead. With <see cref="FluidParameters.DomainFriction"/> μ (per
        /// axis) the faces are Coulomb walls like the colliders (<see cref="ContactProjection"/>): the motion along them since
        /// <paramref name="start"/> is cancelled by at most Σ μ_axis × the depth pushed out along that axis, and the velocity
        /// along them by the same share (a particle resting on the floor then slides with deceleration μ.y·g). Returns true
        /// when it moved the particle.
        /// </summary>
        public static bool ClampToDomain(in FluidConstants c, ref float3 x, ref float3 v, float3 start)
        {
            float3 lo = c.Parameters.DomainMin + c.WallDistance;
            float3 hi = c.Parameters.DomainMax - c.WallDistance;
            if (c.IsPeriodic)
            {
                // Periodic axes wrap instead (the motion along them since start is the nearest image's).
                float3 wrapped = c.Wrap(x);
                start += wrapped - x;
                x = wrapped;
                lo = math.select(lo, new float3(float.NegativeInfinity), c.Parameters.Periodic);
                hi = math.select(hi, new float3(float.PositiveInfinity), c.Parameters.Periodic);
            }
            float3 clamped = math.clamp(x, lo, hi);
            if (math.all(clamped == x))
                return false;
            float3 depth = math.max(lo - x, 0f) + math.max(x - hi, 0f);
            // Remove the velocity component into each face the particle was pushed off.
            if (x.x < lo.x) v.x = math.max(v.x, 0f); else if (x.x > hi.x) v.x = math.min(v.x, 0f);
            if (x.y < lo.y) v.y = math.max(v.y, 0f); else if (x.y > hi.y) v.y = math.min(v.y, 0f);
            if (x.z < lo.z) v.z = math.max(v.z, 0f); else if (x.z > hi.z) v.z = math.min(v.z, 0f);
            x = clamped;
            float limit = math.dot(c.Parameters.DomainFriction, depth);
            if (limit > 0f)
            {
                var along = new float3(depth.x > 0f ? 0f : 1f, depth.y > 0f ? 0f : 1f, depth.z > 0f ? 0f : 1f);
                float3 tangential = (x - start) * along;
                float slide = math.length(tangential);
                if (slide > 0f)
                {
                    float cut = math.min(1f, limit / slide);
                    x -= tangential * cut;
                    v -= v * along * cut;
                }
            }
            return true;
        }
    }
}
