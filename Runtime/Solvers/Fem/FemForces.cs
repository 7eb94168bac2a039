using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The element passes of the finite-element step, written as range functions (start, end) so a job can run them
    /// per batch: each element writes its four nodal values to its slots (4e + corner), and
    /// <see cref="ElementIncidence.Gather"/> sums them per node in a fixed order. The result has the same bits for any
    /// split of either pass among workers and any order of the batches. Quadratic elements (<see cref="FemModel.IsQuadratic"/>)
    /// run the same per-point material laws at their 4 integration points (<see cref="FemForces"/> in QuadraticFemForces.cs).
    /// </summary>
    public static partial class FemForces
    {
        /// <summary>
        /// Elastic plus damping forces of elements [<paramref name="start"/>, <paramref name="end"/>) into their slots:
        /// P(F) of the model (co-rotational: the element's rotation R is first re-extracted from F, warm-started at
        /// <paramref name="rotations"/>[e], which it updates), plus the stiffness-proportional damping stress of the
        /// velocities <paramref name="v"/> with coefficient <paramref name="beta"/> (s) (co-rotational: β K_R;
        /// Neo-Hookean: <see cref="FemElasticity.StrainRateDampingStress"/>); nodal forces H = −V P Dm⁻ᵀ. Returns the
        /// number of elements of the range with det F ≤ 0.
        /// </summary>
        public static int Elastic(in FemModel model, FemMaterialModel materialModel, ReadOnlySpan<float3> x, ReadOnlySpan<float3> v,
            float beta, Span<quaternion> rotations, int rotationIterations, Span<float3> slots, int start, int end)
        {
            if (model.IsQuadratic)
                return QuadraticElastic(model, materialModel, x, v, beta, rotations, rotationIterations, slots, start, end);
            bool damped = beta > 0f;
            int inverted = 0;
            for (int e = start; e < end; e++)
            {
                TetElement element = model.Elements[e];
                int4 n = element.Nodes;
                float3x3 f = FemElasticity.DeformationGradient(x[n.x], x[n.y], x[n.z], x[n.w], element.InverseRestShape);
                if (!(math.determinant(f) > 0f))
                    inverted++;
                float3x3 fDot = damped
                    ? FemElasticity.DeformationGradient(v[n.x], v[n.y], v[n.z], v[n.w], element.InverseRestShape)
                    : float3x3.zero;
                float3x3 p = PointStress(model, materialModel, f, fDot, beta, ref rotations[e], rotationIterations);
                FemElasticity.NodalForces(p, element, slots.Slice(4 * e, 4));
            }
            return inverted;
        }

        /// <summary>
        /// The stress P (Pa) of one integration point with deformation gradient <paramref name="f"/> and its rate
        /// <paramref name="fDot"/> (read when <paramref name="beta"/> &gt; 0): co-rotational, the rotation re-extracted
        /// (warm-started at <paramref name="rotation"/>, which it updates) and β K_R damping; Neo-Hookean, the strain-rate damping.
        /// </summary>
        static float3x3 PointStress(in FemModel model, FemMaterialModel materialModel, in float3x3 f, in float3x3 fDot, float beta,
            ref quaternion rotation, int rotationIterations)
        {
            float mu = model.Mu, lambda = model.Lambda;
            bool damped = beta > 0f;
            if (materialModel == FemMaterialModel.CoRotational)
            {
                RotationExtraction.Extract(f, ref rotation, rotationIterations);
                var r = new float3x3(rotation);
                float3x3 p = FemElasticity.CoRotationalStress(f, r, mu, lambda);
                return damped ? p + beta * FemElasticity.WarpedStressDifferential(r, fDot, mu, lambda) : p;
            }
            float3x3 pn = FemElasticity.NeoHookeanStress(f, mu, FemElasticity.NeoHookeanLambda(mu, lambda));
            return damped ? pn + FemElasticity.StrainRateDampingStress(f, fDot, beta, mu, lambda) : pn;
        }

        /// <summary>
        /// −K_R u of elements [<paramref name="start"/>, <paramref name="end"/>) into their slots: the force change of a
        /// displacement <paramref name="u"/> under the warped stiffness K_R = R K₀ Rᵀ with the rotations of
        /// <paramref name="rotations"/> held fixed (Müller &amp; Gross 2004). Symmetric positive semi-definite.
        /// </summary>
        public static void WarpedStiffness(in FemModel model, ReadOnlySpan<quaternion> rotations, ReadOnlySpan<float3> u,
            Span<float3> slots, int start, int end)
        {
            if (model.IsQuadratic)
            {
                QuadraticWarpedStiffness(model, rotations, u, slots, start, end);
                return;
            }
            float mu = model.Mu, lambda = model.Lambda;
            for (int e = start; e < end; e++)
            {
                TetElement element = model.Elements[e];
                int4 n = element.Nodes;
                float3x3 du = FemElasticity.DeformationGradient(u[n.x], u[n.y], u[n.z], u[n.w], element.InverseRestShape);
                var r = new float3x3(rotations[e]);
                FemElasticity.NodalForces(FemElasticity.WarpedStressDifferential(r, du, mu, lambda), element, slots.Slice(4 * e, 4));
            }
        }

        /// <summary>
        /// Elastic forces and tangents of the stable Neo-Hookean model at x + h v (the linearisation point of the implicit
        /// step; F = F(x) + h F(v)) for elements [<paramref name="start"/>, <paramref name="end"/>): P(F) = μF + λ(J − α) cof F
        /// into the slots (no damping: the implicit step puts it in its system), the element's rotation R re-extracted
        /// from F (warm-started at <paramref name="rotations"/>[e], which it updates) and the projected Hessian of
        /// <see cref="NeoHookeanTangent"/> stored at <paramref name="tangents"/>[<see cref="NeoHookeanTangent.Float3Count"/> e ..].
        /// An empty <paramref name="v"/> means v = 0. Returns the number of elements of the range with det F(x) ≤ 0.
        /// </summary>
        public static int NeoHookeanTangents(in FemModel model, ReadOnlySpan<float3> x, ReadOnlySpan<float3> v, float h,
            Span<quaternion> rotations, int rotationIterations, Span<float3> tangents, Span<float3> slots, int start, int end)
        {
            if (model.IsQuadratic)
                return QuadraticNeoHookeanTangents(model, x, v, h, rotations, rotationIterations, tangents, slots, start, end);
            float mu = model.Mu;
            float lambdaSnh = FemElasticity.NeoHookeanLambda(mu, model.Lambda);
            bool moving = v.Length > 0;
            int inverted = 0;
            for (int e = start; e < end; e++)
            {
                TetElement element = model.Elements[e];
                int4 n = element.Nodes;
                float3x3 f = FemElasticity.DeformationGradient(x[n.x], x[n.y], x[n.z], x[n.w], element.InverseRestShape);
                if (!(math.determinant(f) > 0f))
                    inverted++;
                if (moving)
                    f += h * FemElasticity.DeformationGradient(v[n.x], v[n.y], v[n.z], v[n.w], element.InverseRestShape);
                quaternion q = rotations[e];
                RotationExtraction.Extract(f, ref q, rotationIterations);
                rotations[e] = q;
                NeoHookeanTangent.Compute(f, new float3x3(q), mu, lambdaSnh, true)
                    .Store(tangents.Slice(NeoHookeanTangent.Float3Count * e, NeoHookeanTangent.Float3Count));
                FemElasticity.NodalForces(FemElasticity.NeoHookeanStress(f, mu, lambdaSnh), element, slots.Slice(4 * e, 4));
            }
            return inverted;
        }

        /// <summary>
        /// V (Ψ(F + D) − Ψ(F)) (J) of elements [<paramref name="start"/>, <paramref name="end"/>) into the element's first slot's x (the other
        /// corners untouched): the stable Neo-Hookean energy change when the positions x + h v move by
        /// <paramref name="step"/> h <paramref name="dv"/> (F = F(x) + h F(v), D = step h F(dv); see
        /// <see cref="FemElasticity.NeoHookeanEnergyChange"/>). The line search of the implicit step sums them in element order.
        /// </summary>
        public static void NeoHookeanEnergyChange(in FemModel model, ReadOnlySpan<float3> x, ReadOnlySpan<float3> v,
            ReadOnlySpan<float3> dv, float h, float step, Span<float3> slots, int start, int end)
        {
            if (model.IsQuadratic)
            {
                QuadraticNeoHookeanEnergyChange(model, x, v, dv, h, step, slots, start, end);
                return;
            }
            float mu = model.Mu;
            float lambdaSnh = FemElasticity.NeoHookeanLambda(mu, model.Lambda);
            for (int e = start; e < end; e++)
            {
                TetElement element = model.Elements[e];
                int4 n = element.Nodes;
                float3x3 f = FemElasticity.DeformationGradient(x[n.x], x[n.y], x[n.z], x[n.w], element.InverseRestShape)
                             + h * FemElasticity.DeformationGradient(v[n.x], v[n.y], v[n.z], v[n.w], element.InverseRestShape);
                float3x3 d = (step * h) * FemElasticity.DeformationGradient(dv[n.x], dv[n.y], dv[n.z], dv[n.w], element.InverseRestShape);
                slots[4 * e] = new float3(element.RestVolume * FemElasticity.NeoHookeanEnergyChange(f, d, mu, lambdaSnh), 0f, 0f);
            }
        }

        /// <summary>
        /// −K u of elements [<paramref name="start"/>, <paramref name="end"/>) into their slots, K the stable Neo-Hookean
        /// tangent stiffness stored by <see cref="NeoHookeanTangents"/> (with the same <paramref name="rotations"/>):
        /// δF of the displacement <paramref name="u"/>, δP of the tangent, nodal forces −V δP Dm⁻ᵀ. Symmetric positive
        /// semi-definite (the projected Hessian).
        /// </summary>
        public static void NeoHookeanStiffness(in FemModel model, ReadOnlySpan<quaternion> rotations, ReadOnlySpan<float3> tangents,
            ReadOnlySpan<float3> u, Span<float3> slots, int start, int end)
        {
            if (model.IsQuadratic)
            {
                QuadraticNeoHookeanStiffness(model, rotations, tangents, u, slots, start, end);
                return;
            }
            for (int e = start; e < end; e++)
            {
                TetElement element = model.Elements[e];
                int4 n = element.Nodes;
                float3x3 du = FemElasticity.DeformationGradient(u[n.x], u[n.y], u[n.z], u[n.w], element.InverseRestShape);
                NeoHookeanTangent tangent = NeoHookeanTangent.Load(tangents.Slice(NeoHookeanTangent.Float3Count * e, NeoHookeanTangent.Float3Count));
                FemElasticity.NodalForces(tangent.StressDifferential(new float3x3(rotations[e]), du), element, slots.Slice(4 * e, 4));
            }
        }

        /// <summary>resultᵢ = Σ of node i's slots for nodes [<paramref name="start"/>, <paramref name="end"/>) (overwrites).</summary>
        public static void Gather(in FemModel model, ReadOnlySpan<float3> slots, Span<float3> result, int start, int end)
        {
            result.Slice(start, end - start).Clear();
            ElementIncidence.Gather(model.IncidenceOffsets, model.IncidenceSlots, slots, start, end, result);
        }
    }
}
