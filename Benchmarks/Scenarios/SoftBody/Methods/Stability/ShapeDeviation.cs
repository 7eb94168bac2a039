using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// How far a body is from its rest shape once its rigid motion is removed: max over the particles of
    /// |xᵢ − (R (x⁰ᵢ − c⁰) + c)|, with c and c⁰ the centres of mass now and at rest and R the proper rotation closest to
    /// A_pq = Σ mᵢ (xᵢ − c)(x⁰ᵢ − c⁰)ᵀ (<see cref="RotationExtraction"/>; a mirrored body gets a rotation, never a
    /// reflection, so it stays far from its rest shape).
    /// </summary>
    public static class ShapeDeviation
    {
        /// <summary>Iterations of the rotation extraction from the warm start (it converges in a few near the optimum).</summary>
        const int k_Iterations = 40;

        /// <summary>
        /// The largest distance (m) of a particle from the best-fit rigidly moved rest shape; +∞ when a position is not
        /// finite. <paramref name="rotation"/> is the warm start in and the best-fit rotation out.
        /// </summary>
        public static double Max(IMethodBody body, ref quaternion rotation)
        {
            ReadOnlySpan<float3> x = body.Positions, rest = body.RestPositions;
            ReadOnlySpan<float> m = body.Masses;
            for (int i = 0; i < x.Length; i++)
                if (!math.all(math.isfinite(x[i])))
                    return double.PositiveInfinity;
            float3 c = ShapeMatching.CenterOfMass(x, m), c0 = ShapeMatching.CenterOfMass(rest, m);
            RotationExtraction.Extract(ShapeMatching.Apq(x, m, c, rest, c0), ref rotation, k_Iterations);
            float3x3 r = new float3x3(rotation);
            double worst = 0;
            for (int i = 0; i < x.Length; i++)
                worst = Math.Max(worst, math.length(x[i] - c - math.mul(r, rest[i] - c0)));
            return worst;
        }

        /// <summary>Longest side of the axis-aligned bounds of the rest shape (m): the length deviations are measured against.</summary>
        public static float Size(IMethodBody body)
        {
            float3 lo = body.RestPositions[0], hi = lo;
            foreach (float3 p in body.RestPositions)
            {
                lo = math.min(lo, p);
                hi = math.max(hi, p);
            }
            return math.cmax(hi - lo);
        }
    }
}
