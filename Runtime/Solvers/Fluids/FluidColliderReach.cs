using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The colliders one weakly compressible substep can touch: those whose bounds come within h_kernel + v_max·h of the
    /// particles' bounding box at the substep's start. Every pass before the advection reads the start positions, the
    /// advection moves a particle by at most v_max·h (<see cref="FluidParameters.MaxSpeed"/> bounds its speed), and a
    /// collider acts on a particle only within the kernel radius of its surface, so a collider outside that reach
    /// contributes exactly nothing and leaving it out changes no bit. The position-based solver's corrections have no
    /// such bound: it keeps every collider.
    /// </summary>
    public static class FluidColliderReach
    {
        /// <summary>Most colliders a step culls on the stack; with more, every collider is kept.</summary>
        public const int MaxCulled = 128;

        /// <summary>Whether a substep of <paramref name="c"/> has a reach to cull by: weakly compressible only.</summary>
        public static bool Culls(in FluidConstants c) => c.Parameters.Solver == FluidSolverKind.WeaklyCompressible;

        /// <summary>
        /// Copies into <paramref name="near"/> (length ≥ <paramref name="colliders"/>' length) the colliders a substep of
        /// <paramref name="h"/> seconds can touch, in their order, and returns how many. Non-finite positions (particles the
        /// substep's sort removes) do not count.
        /// </summary>
        public static int Near(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, ReadOnlySpan<float3> positions, float h,
            Span<ColliderShape> near)
        {
            if (!Culls(c))
            {
                colliders.CopyTo(near);
                return colliders.Length;
            }
            float3 lo = new float3(float.PositiveInfinity), hi = new float3(float.NegativeInfinity);
            for (int i = 0; i < positions.Length; i++)
            {
                float3 x = positions[i];
                if (!math.all(math.isfinite(x)))
                    continue;
                lo = math.min(lo, x);
                hi = math.max(hi, x);
            }
            if (math.any(lo > hi))
                return 0;
            float reach = c.Kernels.H + c.Parameters.MaxSpeed * h;
            lo -= reach;
            hi += reach;
            int n = 0;
            for (int k = 0; k < colliders.Length; k++)
                if (Touches(colliders[k], lo, hi))
                    near[n++] = colliders[k];
            return n;
        }

        /// <summary>Whether the solid of <paramref name="shape"/> may meet the box [<paramref name="lo"/>, <paramref name="hi"/>] (its bounds do).</summary>
        public static bool Touches(in ColliderShape shape, float3 lo, float3 hi)
        {
            float3 center = 0.5f * (lo + hi), half = 0.5f * (hi - lo);
            switch (shape.Type)
            {
                case ColliderShapeType.Plane:
                    // The solid is the half-space behind the normal: some corner of the box lies behind the plane.
                    return math.dot(shape.Axis, center - shape.Center) - math.dot(math.abs(shape.Axis), half) <= 0f;
                case ColliderShapeType.Sphere:
                    return Overlap(shape.Center - shape.Radius, shape.Center + shape.Radius, lo, hi);
                case ColliderShapeType.Capsule:
                    return Overlap(math.min(shape.Center, shape.Axis) - shape.Radius, math.max(shape.Center, shape.Axis) + shape.Radius, lo, hi);
                case ColliderShapeType.Box:
                {
                    // Half extents of the rotated box along the world axes: |R|·e.
                    float3x3 r = new float3x3(shape.Rotation);
                    float3 e = math.abs(r.c0) * shape.HalfExtents.x + math.abs(r.c1) * shape.HalfExtents.y + math.abs(r.c2) * shape.HalfExtents.z;
                    return Overlap(shape.Center - e, shape.Center + e, lo, hi);
                }
                default:
                    return true;
            }
        }

        static bool Overlap(float3 aLo, float3 aHi, float3 bLo, float3 bHi) => math.all(aLo <= bHi) && math.all(bLo <= aHi);
    }
}
