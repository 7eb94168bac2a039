using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One linearly implicit backward-Euler substep of the co-rotational model (Baraff &amp; Witkin 1998, eq. 6, with the
    /// warped stiffness of Müller &amp; Gross 2004): with f the elastic forces at x, K_R = R K₀ Rᵀ per element and the
    /// Rayleigh damping C = β K_R,
    /// <code>
    ///   (M + h C + h² K_R) Δv = h (f − (β + h) K_R v),   v ← v + Δv
    /// </code>
    /// solved matrix-free by conjugate gradients with a Jacobi preconditioner (mᵢ + (hβ + h²) kᵢ, kᵢ the rotation-invariant
    /// diagonal of <see cref="FemModel.StiffnessDiagonal"/>), pinned nodes filtered out of every vector. The matrix is
    /// symmetric positive definite for any h, so the substep is stable at any step length. The velocities on entry
    /// already hold the substep's gravity (the shared step adds it first), which is the same system with f + Mg.
    /// </summary>
    public static class FemImplicitEuler
    {
        /// <summary>Solves one substep and adds Δv to <paramref name="v"/>. Returns the CG iterations taken.</summary>
        /// <param name="forces">Scratch, one per node.</param>
        /// <param name="work">Scratch, <see cref="FemState.WorkVectors"/> per node.</param>
        /// <param name="converged">True when ‖r‖ ≤ <paramref name="tolerance"/> ‖b‖ was reached.</param>
        /// <param name="inverted">Elements with det F ≤ 0 at x.</param>
        public static int Solve(in FemModel model, ReadOnlySpan<float3> x, Span<float3> v, Span<quaternion> rotations,
            int rotationIterations, Span<float3> slots, Span<float3> forces, Span<float3> work, float h, float beta,
            int maxIterations, float tolerance, out bool converged, out int inverted)
        {
            int n = x.Length, elements = model.ElementCount;
            Span<float3> dv = work.Slice(0, n), r = work.Slice(n, n), z = work.Slice(2 * n, n), p = work.Slice(3 * n, n),
                q = work.Slice(4 * n, n);
            ReadOnlySpan<float> w = model.InverseMasses, m = model.Masses, k = model.StiffnessDiagonal;

            // f at x (rotations re-extracted), then −K_R v.
            inverted = FemForces.Elastic(model, FemMaterialModel.CoRotational, x, default, 0f, rotations, rotationIterations, slots, 0, elements);
            FemForces.Gather(model, slots, forces, 0, n);
            FemForces.WarpedStiffness(model, rotations, v, slots, 0, elements);
            FemForces.Gather(model, slots, q, 0, n);
            float c = h * beta + h * h;
            float bb = 0f;
            for (int i = 0; i < n; i++)
            {
                r[i] = w[i] > 0f ? h * (forces[i] + (beta + h) * q[i]) : float3.zero;
                dv[i] = float3.zero;
                bb += math.lengthsq(r[i]);
            }
            converged = true;
            int iterations = 0;
            if (bb > 0f && math.isfinite(bb))
            {
                float threshold = tolerance * tolerance * bb;
                float rz = Precondition(r, z, m, k, w, c);
                z.CopyTo(p);
                converged = false;
                while (iterations < maxIterations)
                {
                    iterations++;
                    // q = A p = M p + c K_R p (the gathered slots hold −K_R p).
                    FemForces.WarpedStiffness(model, rotations, p, slots, 0, elements);
                    FemForces.Gather(model, slots, q, 0, n);
                    float pq = 0f;
                    for (int i = 0; i < n; i++)
                    {
                        q[i] = w[i] > 0f ? m[i] * p[i] - c * q[i] : float3.zero;
                        pq += math.dot(p[i], q[i]);
                    }
                    if (!(pq > 0f))
                        break;
                    float a = rz / pq;
                    float rr = 0f;
                    for (int i = 0; i < n; i++)
                    {
                        dv[i] += a * p[i];
                        r[i] -= a * q[i];
                        rr += math.lengthsq(r[i]);
                    }
                    if (rr <= threshold)
                    {
                        converged = true;
                        break;
                    }
                    float rzNew = Precondition(r, z, m, k, w, c);
                    float b = rzNew / rz;
                    rz = rzNew;
                    for (int i = 0; i < n; i++)
                        p[i] = z[i] + b * p[i];
                }
            }
            for (int i = 0; i < n; i++)
                v[i] += dv[i];
            return iterations;
        }

        /// <summary>z = D⁻¹ r with D = mᵢ + c kᵢ (0 at pinned nodes); returns r · z.</summary>
        static float Precondition(ReadOnlySpan<float3> r, Span<float3> z, ReadOnlySpan<float> m, ReadOnlySpan<float> k,
            ReadOnlySpan<float> w, float c)
        {
            float rz = 0f;
            for (int i = 0; i < r.Length; i++)
            {
                z[i] = w[i] > 0f ? r[i] / (m[i] + c * k[i]) : float3.zero;
                rz += math.dot(r[i], z[i]);
            }
            return rz;
        }
    }
}
