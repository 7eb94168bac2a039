using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The element passes of <see cref="FemForces"/> for quadratic elements (<see cref="QuadraticTet"/>): each element sums
    /// the forces of its 4 integration points, −V_q P(F_q) ∇N_a, into its 10 slots; rotations and tangents are per point.
    /// Elements count as inverted when any point has det F ≤ 0.
    /// </summary>
    public static partial class FemForces
    {
        const int k_Nodes = QuadraticTet.NodeCount, k_Points = QuadraticTet.PointCount;

        static int QuadraticElastic(in FemModel model, FemMaterialModel materialModel, ReadOnlySpan<float3> x, ReadOnlySpan<float3> v,
            float beta, Span<quaternion> rotations, int rotationIterations, Span<float3> slots, int start, int end)
        {
            bool damped = beta > 0f;
            int inverted = 0;
            for (int e = start; e < end; e++)
            {
                ReadOnlySpan<int> nodes = model.ElementNodes.Slice(k_Nodes * e, k_Nodes);
                Span<float3> elementSlots = slots.Slice(k_Nodes * e, k_Nodes);
                elementSlots.Clear();
                bool flat = false;
                for (int q = 0; q < k_Points; q++)
                {
                    int point = k_Points * e + q;
                    ReadOnlySpan<float3> g = model.PointGradients.Slice(k_Nodes * point, k_Nodes);
                    float3x3 f = QuadraticTet.DeformationGradient(x, nodes, g);
                    flat |= !(math.determinant(f) > 0f);
                    float3x3 fDot = damped ? QuadraticTet.DeformationGradient(v, nodes, g) : float3x3.zero;
                    float3x3 p = PointStress(model, materialModel, f, fDot, beta, ref rotations[point], rotationIterations);
                    QuadraticTet.AddNodalForces(p, model.PointVolumes[point], g, elementSlots);
                }
                if (flat)
                    inverted++;
            }
            return inverted;
        }

        static void QuadraticWarpedStiffness(in FemModel model, ReadOnlySpan<quaternion> rotations, ReadOnlySpan<float3> u,
            Span<float3> slots, int start, int end)
        {
            float mu = model.Mu, lambda = model.Lambda;
            for (int e = start; e < end; e++)
            {
                ReadOnlySpan<int> nodes = model.ElementNodes.Slice(k_Nodes * e, k_Nodes);
                Span<float3> elementSlots = slots.Slice(k_Nodes * e, k_Nodes);
                elementSlots.Clear();
                for (int q = 0; q < k_Points; q++)
                {
                    int point = k_Points * e + q;
                    ReadOnlySpan<float3> g = model.PointGradients.Slice(k_Nodes * point, k_Nodes);
                    float3x3 du = QuadraticTet.DeformationGradient(u, nodes, g);
                    float3x3 dp = FemElasticity.WarpedStressDifferential(new float3x3(rotations[point]), du, mu, lambda);
                    QuadraticTet.AddNodalForces(dp, model.PointVolumes[point], g, elementSlots);
                }
            }
        }

        static int QuadraticNeoHookeanTangents(in FemModel model, ReadOnlySpan<float3> x, ReadOnlySpan<float3> v, float h,
            Span<quaternion> rotations, int rotationIterations, Span<float3> tangents, Span<float3> slots, int start, int end)
        {
            float mu = model.Mu;
            float lambdaSnh = FemElasticity.NeoHookeanLambda(mu, model.Lambda);
            bool moving = v.Length > 0;
            int inverted = 0;
            for (int e = start; e < end; e++)
            {
                ReadOnlySpan<int> nodes = model.ElementNodes.Slice(k_Nodes * e, k_Nodes);
                Span<float3> elementSlots = slots.Slice(k_Nodes * e, k_Nodes);
                elementSlots.Clear();
                bool flat = false;
                for (int q = 0; q < k_Points; q++)
                {
                    int point = k_Points * e + q;
                    ReadOnlySpan<float3> g = model.PointGradients.Slice(k_Nodes * point, k_Nodes);
                    float3x3 f = QuadraticTet.DeformationGradient(x, nodes, g);
                    flat |= !(math.determinant(f) > 0f);
                    if (moving)
                        f += h * QuadraticTet.DeformationGradient(v, nodes, g);
                    RotationExtraction.Extract(f, ref rotations[point], rotationIterations);
                    NeoHookeanTangent.Compute(f, new float3x3(rotations[point]), mu, lambdaSnh, true)
                        .Store(tangents.Slice(NeoHookeanTangent.Float3Count * point, NeoHookeanTangent.Float3Count));
                    QuadraticTet.AddNodalForces(FemElasticity.NeoHookeanStress(f, mu, lambdaSnh), model.PointVolumes[point], g, elementSlots);
                }
                if (flat)
                    inverted++;
            }
            return inverted;
        }

        static void QuadraticNeoHookeanEnergyChange(in FemModel model, ReadOnlySpan<float3> x, ReadOnlySpan<float3> v,
            ReadOnlySpan<float3> dv, float h, float step, Span<float3> slots, int start, int end)
        {
            float mu = model.Mu;
            float lambdaSnh = FemElasticity.NeoHookeanLambda(mu, model.Lambda);
            for (int e = start; e < end; e++)
            {
                ReadOnlySpan<int> nodes = model.ElementNodes.Slice(k_Nodes * e, k_Nodes);
                float change = 0f;
                for (int q = 0; q < k_Points; q++)
                {
                    int point = k_Points * e + q;
                    ReadOnlySpan<float3> g = model.PointGradients.Slice(k_Nodes * point, k_Nodes);
                    float3x3 f = QuadraticTet.DeformationGradient(x, nodes, g) + h * QuadraticTet.DeformationGradient(v, nodes, g);
                    float3x3 d = (step * h) * QuadraticTet.DeformationGradient(dv, nodes, g);
                    change += model.PointVolumes[point] * FemElasticity.NeoHookeanEnergyChange(f, d, mu, lambdaSnh);
                }
                slots[k_Nodes * e] = new float3(change, 0f, 0f);
            }
        }

        static void QuadraticNeoHookeanStiffness(in FemModel model, ReadOnlySpan<quaternion> rotations, ReadOnlySpan<float3> tangents,
            ReadOnlySpan<float3> u, Span<float3> slots, int start, int end)
        {
            for (int e = start; e < end; e++)
            {
                ReadOnlySpan<int> nodes = model.ElementNodes.Slice(k_Nodes * e, k_Nodes);
                Span<float3> elementSlots = slots.Slice(k_Nodes * e, k_Nodes);
                elementSlots.Clear();
                for (int q = 0; q < k_Points; q++)
                {
                    int point = k_Points * e + q;
                    ReadOnlySpan<float3> g = model.PointGradients.Slice(k_Nodes * point, k_Nodes);
                    float3x3 du = QuadraticTet.DeformationGradient(u, nodes, g);
                    NeoHookeanTangent tangent = NeoHookeanTangent.Load(tangents.Slice(NeoHookeanTangent.Float3Count * point, NeoHookeanTangent.Float3Count));
                    QuadraticTet.AddNodalForces(tangent.StressDifferential(new float3x3(rotations[point]), du), model.PointVolumes[point], g, elementSlots);
                }
            }
        }
    }
}
