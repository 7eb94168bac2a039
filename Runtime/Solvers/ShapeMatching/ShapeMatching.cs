using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Goal positions of meshless shape matching (Müller, Heidelberger, Teschner &amp; Gross 2005):
    /// gᵢ = T (x⁰ᵢ − x⁰_cm) + x_cm, with T the rotation R of A_pq (§4.1) or the blend
    /// β·A + (1 − β)·R of the linear transform A = A_pq A_qq⁻¹ with a volume energy's gradient in place of the paper's
    /// normalisation A / ∛det A (§4.3; see <see cref="VolumePreservation.ConservativeLinearGoalTransform"/>).
    /// Pure functions on spans; no allocation.
    /// </summary>
    public static class ShapeMatching
    {
        /// <summary>det A_qq relative to (tr A_qq / 3)³ below which the rest shape counts as planar.</summary>
        public const float PlanarRestShapeThreshold = 1e-6f;

        /// <summary>Mass-weighted centre Σ mᵢ xᵢ / Σ mᵢ (eq. 4 and 5). Returns zero for zero total mass.</summary>
        public static float3 CenterOfMass(ReadOnlySpan<float3> x, ReadOnlySpan<float> mass)
        {
            float3 sum = float3.zero;
            float m = 0f;
            for (int i = 0; i < x.Length; i++)
            {
                sum += mass[i] * x[i];
                m += mass[i];
            }
            return m > 0f ? sum / m : float3.zero;
        }

        /// <summary>Rest-shape data of a cluster: centre, mass, A_qq⁻¹ (eq. 7) and the length scale L. <see cref="ClusterRestData.QuadraticValid"/> is left false (see <see cref="QuadraticShapeMatching"/>).</summary>
        public static ClusterRestData ComputeRestData(ReadOnlySpan<float3> rest, ReadOnlySpan<float> mass)
        {
            var data = new ClusterRestData { RestCenter = CenterOfMass(rest, mass), AqqInverse = float3x3.identity };
            float3x3 aqq = float3x3.zero;
            for (int i = 0; i < rest.Length; i++)
            {
                float3 q = rest[i] - data.RestCenter;
                aqq += mass[i] * Matrix3.Outer(q, q);
                data.TotalMass += mass[i];
            }
            FinishRestData(ref data, aqq);
            return data;
        }

        /// <summary>Rest data of the cluster <paramref name="indices"/> of <paramref name="rest"/> with one weight per member.</summary>
        public static ClusterRestData ComputeRestData(ReadOnlySpan<float3> rest, ReadOnlySpan<int> indices, ReadOnlySpan<float> weights)
        {
            float3 sum = float3.zero;
            float m = 0f;
            for (int k = 0; k < indices.Length; k++)
            {
                sum += weights[k] * rest[indices[k]];
                m += weights[k];
            }
            var data = new ClusterRestData { RestCenter = m > 0f ? sum / m : float3.zero, AqqInverse = float3x3.identity };
            float3x3 aqq = float3x3.zero;
            for (int k = 0; k < indices.Length; k++)
            {
                float3 q = rest[indices[k]] - data.RestCenter;
                aqq += weights[k] * Matrix3.Outer(q, q);
            }
            data.TotalMass = m;
            FinishRestData(ref data, aqq);
            return data;
        }

        /// <summary>Sets L, the planar flag and A_qq⁻¹ from A_qq (and <see cref="ClusterRestData.TotalMass"/>).</summary>
        public static void FinishRestData(ref ClusterRestData data, in float3x3 aqq)
        {
            float meanDiagonal = (aqq.c0.x + aqq.c1.y + aqq.c2.z) / 3f;
            data.LengthScale = data.TotalMass > 0f ? math.sqrt(3f * meanDiagonal / data.TotalMass) : 0f;
            float det = math.determinant(aqq);
            data.LinearValid = meanDiagonal > 0f
                               && det > PlanarRestShapeThreshold * meanDiagonal * meanDiagonal * meanDiagonal;
            data.AqqInverse = data.LinearValid ? math.inverse(aqq) : float3x3.identity;
        }

        /// <summary>A_pq = Σ mᵢ pᵢ qᵢᵀ with pᵢ = xᵢ − x_cm and qᵢ = x⁰ᵢ − x⁰_cm (eq. 7).</summary>
        public static float3x3 Apq(ReadOnlySpan<float3> x, ReadOnlySpan<float> mass, float3 center,
            ReadOnlySpan<float3> rest, float3 restCenter)
        {
            float3x3 apq = float3x3.zero;
            for (int i = 0; i < x.Length; i++)
                apq += mass[i] * Matrix3.Outer(x[i] - center, rest[i] - restCenter);
            return apq;
        }

        /// <summary>
        /// The goal transform T of a cluster (goals gᵢ = T qᵢ + x_cm) for the rigid or linear mode.
        /// <paramref name="rotation"/> is the warm start in and the extracted rotation out.
        /// <paramref name="rigidFallback"/> is set when the linear mode had to use R (planar rest shape,
        /// or a degenerate or inverted Ã).
        /// </summary>
        public static float3x3 GoalTransform(in float3x3 apq, in ClusterRestData rest, ShapeMatchingMode mode, float beta,
            ref quaternion rotation, out bool rigidFallback) =>
            GoalTransform(apq, rest, mode, beta, ref rotation, RotationExtraction.DefaultMaxIterations, out _, out rigidFallback);

        /// <summary>As above, with the rotation's iteration cap and the iterations it took.</summary>
        public static float3x3 GoalTransform(in float3x3 apq, in ClusterRestData rest, ShapeMatchingMode mode, float beta,
            ref quaternion rotation, int maxIterations, out int iterations, out bool rigidFallback)
        {
            iterations = RotationExtraction.Extract(apq, ref rotation, maxIterations);
            float3x3 r = new float3x3(rotation);
            rigidFallback = false;
            if (mode == ShapeMatchingMode.Rigid)
                return r;
            if (!rest.LinearValid)
            {
                rigidFallback = true;
                return r;
            }
            float3x3 aLinear = math.mul(apq, rest.AqqInverse);
            return VolumePreservation.ConservativeLinearGoalTransform(aLinear, r, beta, rest.TotalMass, rest.LengthScale, rest.AqqInverse,
                out rigidFallback);
        }
    }
}
