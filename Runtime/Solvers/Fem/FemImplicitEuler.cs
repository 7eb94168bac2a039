using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One backward-Euler substep of a finite-element body, linearised as in Baraff &amp; Witkin 1998, eq. 6: with f the
    /// elastic forces at x, K the element stiffness and the Rayleigh damping C = β K,
    /// <code>
    ///   (M + h C + h² K) Δv = h (f − (β + h) K v),   v ← v + Δv
    /// </code>
    /// Co-rotational: K = K_R = R K₀ Rᵀ, the warped stiffness of Müller &amp; Gross 2004. Stable Neo-Hookean: K = the
    /// energy Hessian projected to positive semi-definite per element (<see cref="NeoHookeanTangent"/>, Smith, de Goes
    /// &amp; Kim 2018, §4), and the step is the first of <c>newtonIterations</c> Newton iterations on the nonlinear
    /// backward-Euler equations M(v⁺ − v) = h (f(x + h v⁺) − C v⁺): iteration k ≥ 1 linearises at x_k = x + h v_k,
    /// <code>
    ///   (M + h C_k + h² K_k) δ = h (f(x_k) − β K_k v_k) − M (v_k − v),   v_{k+1} = v_k + δ
    /// </code>
    /// Each system is solved matrix-free by conjugate gradients (K·p per element into its slots, gathered per node
    /// through <see cref="ElementIncidence"/>) with a Jacobi preconditioner (mᵢ + (hβ + h²) kᵢ, kᵢ the rotation-invariant
    /// rest diagonal of <see cref="FemModel.StiffnessDiagonal"/>), pinned nodes filtered out of every vector. The matrix is
    /// symmetric positive definite for any h, so the substep is stable at any step length. The velocities on entry
    /// already hold the substep's gravity (the shared step adds it first), which is the same system with f + Mg.
    /// </summary>
    public static class FemImplicitEuler
    {
        /// <summary>Most Newton iterations per substep of the Neo-Hookean model.</summary>
        public const int MaxNewtonIterations = 16;

        /// <summary>One co-rotational substep (see the class comment); adds Δv to <paramref name="v"/>. Returns the CG iterations taken.</summary>
        /// <param name="forces">Scratch, one per node.</param>
        /// <param name="work">Scratch, <see cref="FemState.WorkVectors"/> per node.</param>
        /// <param name="converged">True when ‖r‖ ≤ <paramref name="tolerance"/> ‖b‖ was reached.</param>
        /// <param name="inverted">Elements with det F ≤ 0 at x.</param>
        public static int Solve(in FemModel model, ReadOnlySpan<float3> x, Span<float3> v, Span<quaternion> rotations,
            int rotationIterations, Span<float3> slots, Span<float3> forces, Span<float3> work, float h, float beta,
            int maxIterations, float tolerance, out bool converged, out int inverted) =>
            Solve(model, FemMaterialModel.CoRotational, x, v, rotations, default, rotationIterations, slots, forces, work, h, beta, 1,
                maxIterations, tolerance, out converged, out inverted);

        /// <summary>One substep of <paramref name="materialModel"/> (see the class comment); updates <paramref name="v"/>. Returns the CG iterations taken, summed over the Newton iterations.</summary>
        /// <param name="rotations">Per element: the rotation R, the warm start of its extraction (updated).</param>
        /// <param name="tangents">Neo-Hookean: scratch, <see cref="NeoHookeanTangent.Float3Count"/> per element (unused by the co-rotational model).</param>
        /// <param name="scratch">Scratch, one per node.</param>
        /// <param name="work">Scratch, <see cref="FemState.WorkVectors"/> per node.</param>
        /// <param name="newtonIterations">Neo-Hookean: Newton iterations (1 = linearly implicit; clamped to 1 … <see cref="MaxNewtonIterations"/>). The co-rotational model takes one.</param>
        /// <param name="converged">True when every CG solve reached ‖r‖ ≤ <paramref name="tolerance"/> ‖b‖.</param>
        /// <param name="inverted">Elements with det F ≤ 0 at x.</param>
        public static int Solve(in FemModel model, FemMaterialModel materialModel, ReadOnlySpan<float3> x, Span<float3> v,
            Span<quaternion> rotations, Span<float3> tangents, int rotationIterations, Span<float3> slots, Span<float3> scratch,
            Span<float3> work, float h, float beta, int newtonIterations, int maxIterations, float tolerance, out bool converged,
            out int inverted)
        {
            int n = x.Length, elements = model.ElementCount;
            bool neoHookean = materialModel == FemMaterialModel.NeoHookean;
            int newton = neoHookean ? math.clamp(newtonIterations, 1, MaxNewtonIterations) : 1;
            Span<float3> dv = work.Slice(0, n), r = work.Slice(n, n), z = work.Slice(2 * n, n), p = work.Slice(3 * n, n),
                q = work.Slice(4 * n, n);
            // The velocity change of the earlier Newton iterations, v_k − v.
            Span<float3> accumulated = scratch.Slice(0, n);
            ReadOnlySpan<float> w = model.InverseMasses, m = model.Masses;
            float c = h * beta + h * h;
            converged = true;
            inverted = 0;
            int iterations = 0;
            for (int newtonIteration = 0; newtonIteration < newton; newtonIteration++)
            {
                // The linearisation point: x, then x_k = x + h v_k (in p, free until the CG starts).
                ReadOnlySpan<float3> xk = x;
                if (newtonIteration > 0)
                {
                    for (int i = 0; i < n; i++)
                        p[i] = x[i] + h * v[i];
                    xk = p;
                }
                // f at x_k (rotations re-extracted; Neo-Hookean tangents stored) into r, then −K v_k into q.
                int invertedHere = neoHookean
                    ? FemForces.NeoHookeanTangents(model, xk, rotations, rotationIterations, tangents, slots, 0, elements)
                    : FemForces.Elastic(model, FemMaterialModel.CoRotational, xk, default, 0f, rotations, rotationIterations, slots, 0, elements);
                if (newtonIteration == 0)
                    inverted = invertedHere;
                FemForces.Gather(model, slots, r, 0, n);
                Stiffness(model, neoHookean, rotations, tangents, v, slots, q);
                float bb = 0f;
                if (newtonIteration == 0)
                {
                    for (int i = 0; i < n; i++)
                    {
                        r[i] = w[i] > 0f ? h * (r[i] + (beta + h) * q[i]) : float3.zero;
                        dv[i] = float3.zero;
                        accumulated[i] = float3.zero;
                        bb += math.lengthsq(r[i]);
                    }
                }
                else
                {
                    for (int i = 0; i < n; i++)
                    {
                        r[i] = w[i] > 0f ? h * (r[i] + beta * q[i]) - m[i] * accumulated[i] : float3.zero;
                        dv[i] = float3.zero;
                        bb += math.lengthsq(r[i]);
                    }
                }
                iterations += ConjugateGradient(model, neoHookean, rotations, tangents, slots, dv, r, z, p, q, c, bb, maxIterations,
                    tolerance, out bool solved);
                converged &= solved;
                RemoveMomentumError(dv, m, w);
                for (int i = 0; i < n; i++)
                {
                    v[i] += dv[i];
                    accumulated[i] += dv[i];
                }
            }
            return iterations;
        }

        /// <summary>q = −K u gathered per node (K of the model: warped, or the stored Neo-Hookean tangents).</summary>
        static void Stiffness(in FemModel model, bool neoHookean, ReadOnlySpan<quaternion> rotations, ReadOnlySpan<float3> tangents,
            ReadOnlySpan<float3> u, Span<float3> slots, Span<float3> q)
        {
            if (neoHookean)
                FemForces.NeoHookeanStiffness(model, rotations, tangents, u, slots, 0, model.ElementCount);
            else
                FemForces.WarpedStiffness(model, rotations, u, slots, 0, model.ElementCount);
            FemForces.Gather(model, slots, q, 0, model.ParticleCount);
        }

        /// <summary>
        /// Preconditioned conjugate gradients on (M + c K) dv = r from dv = 0, r the right-hand side with ‖r‖² =
        /// <paramref name="bb"/>; stops at ‖r‖ ≤ tolerance ‖b‖ (<paramref name="converged"/>), after
        /// <paramref name="maxIterations"/>, or when pᵀAp ≤ 0. Returns the iterations taken.
        /// </summary>
        static int ConjugateGradient(in FemModel model, bool neoHookean, ReadOnlySpan<quaternion> rotations, ReadOnlySpan<float3> tangents,
            Span<float3> slots, Span<float3> dv, Span<float3> r, Span<float3> z, Span<float3> p, Span<float3> q, float c, float bb,
            int maxIterations, float tolerance, out bool converged)
        {
            int n = model.ParticleCount;
            ReadOnlySpan<float> w = model.InverseMasses, m = model.Masses, k = model.StiffnessDiagonal;
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
                    // q = A p = M p + c K p (the gathered slots hold −K p).
                    Stiffness(model, neoHookean, rotations, tangents, p, slots, q);
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
            return iterations;
        }

        /// <summary>
        /// Internal forces change no momentum: 1ᵀK = 0 and Σ bᵢ = h Σ fᵢ = 0, so the exact Δv has Σ mᵢ Δvᵢ = 0, but a CG
        /// iterate stopped at the tolerance has Σ mᵢ Δvᵢ = −Σ rᵢ. For a body with no pinned node the mass-weighted mean of
        /// Δv is removed (a projection toward the exact solution); a pinned body exchanges momentum with its pins anyway.
        /// </summary>
        static void RemoveMomentumError(Span<float3> dv, ReadOnlySpan<float> m, ReadOnlySpan<float> w)
        {
            // Summed in double: the float sum's own round-off (~ε Σ mᵢ|Δvᵢ| √n) would be the error it removes.
            double px = 0.0, py = 0.0, pz = 0.0, mass = 0.0;
            for (int i = 0; i < dv.Length; i++)
            {
                if (!(w[i] > 0f))
                    return;
                px += (double)m[i] * dv[i].x;
                py += (double)m[i] * dv[i].y;
                pz += (double)m[i] * dv[i].z;
                mass += m[i];
            }
            var mean = new float3((float)(px / mass), (float)(py / mass), (float)(pz / mass));
            for (int i = 0; i < dv.Length; i++)
                dv[i] -= mean;
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
