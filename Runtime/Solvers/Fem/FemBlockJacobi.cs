using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The block-Jacobi preconditioner of the implicit step: per node i the inverse of its 3×3 diagonal block of
    /// A = M + c K_R, B_i = mᵢ I + c Σ_points V_q (μ|g|² I + (μ + λ) (R g)(R g)ᵀ), g = ∇N_i at the point and R its rotation
    /// (the node's own block of the warped stiffness: δP = R(2μ sym(RᵀδF) + λ tr(RᵀδF) I) with δF = u gᵀ). Unlike a scalar
    /// diagonal it keeps the strong volumetric coupling (λ ≫ μ as ν → ½) of each node's three directions. The Neo-Hookean
    /// step uses the same blocks at its rotations (its tangent is this one at rest). Blocks are stored inverted, symmetric,
    /// as two float3 per node (diagonal xx, yy, zz; off-diagonal xy, xz, yz) in the last two vectors of the work span.
    /// </summary>
    public static class FemBlockJacobi
    {
        /// <summary>
        /// Builds the inverted blocks into <paramref name="work"/>[5n, 7n) for <paramref name="c"/> = hβ + h² (s²): two element
        /// passes into the slots (diagonal, then off-diagonal terms), each gathered per node in the incidence's fixed order.
        /// Pinned nodes get zero blocks.
        /// </summary>
        public static void Build(in FemModel model, ReadOnlySpan<quaternion> rotations, Span<float3> slots, Span<float3> work, float c)
        {
            int n = model.ParticleCount;
            Span<float3> diagonal = work.Slice(5 * n, n), offDiagonal = work.Slice(6 * n, n);
            ElementTerms(model, rotations, slots, false, 0, model.ElementCount);
            FemForces.Gather(model, slots, diagonal, 0, n);
            ElementTerms(model, rotations, slots, true, 0, model.ElementCount);
            FemForces.Gather(model, slots, offDiagonal, 0, n);
            ReadOnlySpan<float> m = model.Masses, w = model.InverseMasses;
            for (int i = 0; i < n; i++)
            {
                if (!(w[i] > 0f))
                {
                    diagonal[i] = float3.zero;
                    offDiagonal[i] = float3.zero;
                    continue;
                }
                float3 d = m[i] + c * diagonal[i], o = c * offDiagonal[i];
                var block = new float3x3(d.x, o.x, o.y, o.x, d.y, o.z, o.y, o.z, d.z);
                float3x3 inverse = math.inverse(block);
                if (!(math.all(math.isfinite(inverse.c0)) && math.all(math.isfinite(inverse.c1)) && math.all(math.isfinite(inverse.c2))))
                    inverse = new float3x3(1f / m[i], 0f, 0f, 0f, 1f / m[i], 0f, 0f, 0f, 1f / m[i]);
                diagonal[i] = new float3(inverse.c0.x, inverse.c1.y, inverse.c2.z);
                offDiagonal[i] = new float3(inverse.c1.x, inverse.c2.x, inverse.c2.y);
            }
        }

        /// <summary>z = B⁻¹ r per node (blocks from <see cref="Build"/>); returns r · z.</summary>
        public static float Apply(ReadOnlySpan<float3> diagonal, ReadOnlySpan<float3> offDiagonal, ReadOnlySpan<float3> r, Span<float3> z)
        {
            float rz = 0f;
            for (int i = 0; i < r.Length; i++)
            {
                float3 d = diagonal[i], o = offDiagonal[i], ri = r[i];
                z[i] = new float3(d.x * ri.x + o.x * ri.y + o.y * ri.z,
                    o.x * ri.x + d.y * ri.y + o.z * ri.z,
                    o.y * ri.x + o.z * ri.y + d.z * ri.z);
                rz += math.dot(ri, z[i]);
            }
            return rz;
        }

        /// <summary>
        /// Per slot of elements [<paramref name="start"/>, <paramref name="end"/>): the diagonal (xx, yy, zz) or the off-diagonal
        /// (xy, xz, yz) terms of Σ_points V (μ|g|² I + (μ + λ)(R g)(R g)ᵀ) for the slot's node (N/m).
        /// </summary>
        public static void ElementTerms(in FemModel model, ReadOnlySpan<quaternion> rotations, Span<float3> slots, bool offDiagonal,
            int start, int end)
        {
            float mu = model.Mu, volumetric = model.Mu + model.Lambda;
            int perElement = model.NodesPerElement, points = model.PointsPerElement;
            Span<float3> corner = stackalloc float3[4];
            for (int e = start; e < end; e++)
            {
                Span<float3> elementSlots = slots.Slice(perElement * e, perElement);
                elementSlots.Clear();
                if (!model.IsQuadratic)
                {
                    TetElement element = model.Elements[e];
                    TetElement.CornerGradients(element.InverseRestShape, corner);
                    AddTerms(corner, element.RestVolume, new float3x3(rotations[e]), mu, volumetric, offDiagonal, elementSlots);
                    continue;
                }
                for (int q = 0; q < points; q++)
                {
                    int point = points * e + q;
                    AddTerms(model.PointGradients.Slice(perElement * point, perElement), model.PointVolumes[point],
                        new float3x3(rotations[point]), mu, volumetric, offDiagonal, elementSlots);
                }
            }
        }

        static void AddTerms(ReadOnlySpan<float3> g, float volume, in float3x3 r, float mu, float volumetric, bool offDiagonal,
            Span<float3> slots)
        {
            for (int a = 0; a < g.Length; a++)
            {
                float3 rg = math.mul(r, g[a]);
                slots[a] += offDiagonal
                    ? volume * volumetric * new float3(rg.x * rg.y, rg.x * rg.z, rg.y * rg.z)
                    : volume * (mu * math.lengthsq(g[a]) + volumetric * rg * rg);
            }
        }
    }
}
