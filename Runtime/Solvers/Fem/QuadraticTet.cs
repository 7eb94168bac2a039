using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The 10-node quadratic tetrahedron (straight-sided, edge nodes at the midpoints): shape functions in barycentric
    /// coordinates L₀..L₃, N_a = L_a(2L_a − 1) at corner a and N_ab = 4 L_a L_b at edge (a, b) (Zienkiewicz, Taylor &amp;
    /// Zhu, <i>The Finite Element Method</i>, §6.5), the 4-point quadrature that integrates their products exactly for
    /// linear elasticity (degree 2), and the row-sum-free lumped masses. Node order: the four corners, then the edges
    /// (0,1), (0,2), (0,3), (1,2), (1,3), (2,3). Its strain varies linearly inside the element, so pure bending is exact
    /// and the element does not lock in bending as the linear tetrahedron does.
    /// </summary>
    public static class QuadraticTet
    {
        /// <summary>Nodes per element.</summary>
        public const int NodeCount = 10;
        /// <summary>Edge nodes per element.</summary>
        public const int EdgeCount = 6;
        /// <summary>Quadrature points per element.</summary>
        public const int PointCount = 4;

        /// <summary>Barycentric coordinate of a quadrature point at its own corner: (5 + 3√5)/20 (the other three are (5 − √5)/20).</summary>
        public const double PointNear = 0.58541019662496845;
        /// <summary>The other three barycentric coordinates of a quadrature point.</summary>
        public const double PointFar = 0.13819660112501052;

        /// <summary>
        /// Lumped mass fraction of a corner node: the consistent mass matrix's diagonal (ρV/70 at a corner, 8ρV/105 at an
        /// edge) scaled to the element's mass (Hinton, Rock &amp; Zienkiewicz 1976): 1/36, every mass positive (row sums give corners −ρV/20).
        /// </summary>
        public const float CornerMassFraction = 1f / 36f;
        /// <summary>Lumped mass fraction of an edge node: 4/27 (4 × 1/36 + 6 × 4/27 = 1).</summary>
        public const float EdgeMassFraction = 4f / 27f;

        /// <summary>The corners (a, b) of edge node 4 + k.</summary>
        public static int2 EdgeCorners(int k) => k switch
        {
            0 => new int2(0, 1),
            1 => new int2(0, 2),
            2 => new int2(0, 3),
            3 => new int2(1, 2),
            4 => new int2(1, 3),
            _ => new int2(2, 3),
        };

        /// <summary>Barycentric coordinate <paramref name="a"/> (L_a) of quadrature point <paramref name="q"/> (weight V/4 each).</summary>
        public static float Barycentric(int q, int a) => (float)(a == q ? PointNear : PointFar);

        /// <summary>The 10 shape functions at quadrature point <paramref name="q"/> (they sum to 1).</summary>
        public static void ShapeFunctions(int q, Span<float> n) =>
            ShapeFunctions(Barycentric(q, 0), Barycentric(q, 1), Barycentric(q, 2), Barycentric(q, 3), n);

        /// <summary>The 10 shape functions at barycentric coordinates (L₀, L₁, L₂, L₃) (they sum to 1).</summary>
        public static void ShapeFunctions(float l0, float l1, float l2, float l3, Span<float> n)
        {
            Span<float> l = stackalloc float[4];
            l[0] = l0;
            l[1] = l1;
            l[2] = l2;
            l[3] = l3;
            for (int a = 0; a < 4; a++)
                n[a] = l[a] * (2f * l[a] - 1f);
            for (int k = 0; k < 6; k++)
            {
                int2 e = EdgeCorners(k);
                n[4 + k] = 4f * l[e.x] * l[e.y];
            }
        }

        /// <summary>
        /// Gradients (1/m) of the 10 shape functions at quadrature point <paramref name="q"/> from the corner gradients ∇L_a
        /// (the linear tetrahedron's): ∇N_a = (4L_a − 1)∇L_a, ∇N_ab = 4(L_a ∇L_b + L_b ∇L_a). They sum to zero.
        /// </summary>
        public static void Gradients(int q, ReadOnlySpan<float3> cornerGradients, Span<float3> g)
        {
            for (int a = 0; a < 4; a++)
                g[a] = (4f * Barycentric(q, a) - 1f) * cornerGradients[a];
            for (int k = 0; k < 6; k++)
            {
                int2 e = EdgeCorners(k);
                g[4 + k] = 4f * (Barycentric(q, e.x) * cornerGradients[e.y] + Barycentric(q, e.y) * cornerGradients[e.x]);
            }
        }

        /// <summary>F = Σ_a x_a ⊗ ∇N_a over an element's nodes (dimensionless; <paramref name="gradients"/> the point's 10 gradients).</summary>
        public static float3x3 DeformationGradient(ReadOnlySpan<float3> x, ReadOnlySpan<int> nodes, ReadOnlySpan<float3> gradients)
        {
            float3x3 f = float3x3.zero;
            for (int a = 0; a < NodeCount; a++)
            {
                float3 xa = x[nodes[a]], g = gradients[a];
                f.c0 += xa * g.x;
                f.c1 += xa * g.y;
                f.c2 += xa * g.z;
            }
            return f;
        }

        /// <summary>Adds the nodal forces −V_q P ∇N_a of a point's stress P (Pa) to the element's 10 slots.</summary>
        public static void AddNodalForces(in float3x3 p, float volume, ReadOnlySpan<float3> gradients, Span<float3> slots)
        {
            float3x3 vp = -volume * p;
            for (int a = 0; a < NodeCount; a++)
                slots[a] += math.mul(vp, gradients[a]);
        }
    }
}
