using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One backward-Euler substep of a finite-element body: M(v⁺ − v) = h (f(x + h v⁺) − C v⁺), x⁺ = x + h v⁺, with the
    /// Rayleigh damping C = β K. Each linear system is solved matrix-free by conjugate gradients (K·p per element into
    /// its slots, gathered per node through <see cref="ElementIncidence"/>), preconditioned by the model's
    /// <see cref="FemRestFactor"/> when it has one (a Cholesky factor of the rest system warped by node rotations), else by
    /// <see cref="FemBlockJacobi"/> (node i's 3×3 diagonal block of M + (hβ + h²) K_R at the current rotations), pinned
    /// nodes filtered out of every vector, warm-started from the previous substep's Δv when the caller keeps it
    /// (<see cref="FemState.WarmStart"/>) and the rest factor preconditions, and stopped at the relative residual ‖b − A Δv‖ ≤ tolerance ‖b‖. Its matrix
    /// M + (hβ + h²) K is symmetric positive definite for any h, so the substep is stable at any step length (first order
    /// in h). The velocities on entry already hold the substep's gravity (the shared step adds it first), which is the
    /// same system with f + Mg.
    /// <para>
    /// Frictionless contacts enter the solve (the caller passes them only when μ = 0): a node in contact at the end of the
    /// previous substep (normal n in the contact buffer) ends the substep with no normal velocity, n·(v + Δv) = 0, the
    /// collider carrying the normal component of its equation (CG filtered by Sᵢ = I − n nᵀ from Δv₀ = −(n·v) n,
    /// Baraff &amp; Witkin 1998, §5.3); its tangential motion and the body's other nodes are solved with it held. A node whose
    /// collider would have to pull (n·(A Δv − b)ᵢ &gt; 0) is released and the solve continues. Without this, the elastic push
    /// of a pressed body moves its interior freely while only the contact nodes are pushed back after the solve: a jelly cube
    /// squashed to half its height between frictionless plates settles 12 % fuller than its equilibrium (Neo-Hookean, one
    /// 1/60 s substep). With friction the contact nodes are pushed out after the solve, as in the other integrators:
    /// Coulomb friction on held nodes needs a stick/slide split, and the post-solve one at the solve's impulses locks
    /// bodies that a collider squeezes.
    /// </para>
    /// <para>
    /// Co-rotational: one linearly implicit step (Baraff &amp; Witkin 1998, eq. 6) on the warped stiffness
    /// K_R = R K₀ Rᵀ (Müller &amp; Gross 2004), forces and K_R at x:
    /// <c>(M + h C + h² K_R) Δv = h (f − (β + h) K_R v)</c>.
    /// </para>
    /// <para>
    /// Stable Neo-Hookean: the same first step with K the energy Hessian projected to positive semi-definite per element
    /// (<see cref="NeoHookeanTangent"/>, Smith, de Goes &amp; Kim 2018, §4); it is Newton's first iteration on the
    /// backward-Euler equations from the guess x⁺ = x. Further iterations (<see cref="FemParameters.NewtonIterations"/>)
    /// linearise at x_k = x + h v_k: <c>(M + h C_k + h² K_k) δ = h (f(x_k) − β K_k v_k) − M (v_k − v)</c>. The equations
    /// are the stationarity of the incremental potential Φ(v⁺) = ½‖v⁺ − v‖²_M + E(x + h v⁺) + h/2 v⁺ᵀ C v⁺ (C held), and
    /// each update v_{k+1} = v_k + s δ (v₀ = v, δ₀ = Δv) takes the first s = 1, ½, ¼, … that does not raise Φ
    /// (backtracking; ΔΦ evaluated without cancellation by <see cref="FemForces.NeoHookeanEnergyChange"/>). For k ≥ 1, δ is
    /// a descent direction of Φ (its matrix is Φ's projected Hessian); for k = 0 it is one to first order in h v. A
    /// linearisation far from rest (a strongly compressed stiff element, whose volume term is cubic in the positions)
    /// would otherwise overshoot; near equilibrium s = 1 and the step is Baraff &amp; Witkin's.
    /// </para>
    /// </summary>
    public static class FemImplicitEuler
    {
        /// <summary>Most Newton iterations per substep of the Neo-Hookean model.</summary>
        public const int MaxNewtonIterations = 16;

        /// <summary>Most halvings of the Newton step in the line search (the smallest step is 2⁻¹² of it).</summary>
        public const int MaxLineSearchHalvings = 12;

        /// <summary>
        /// A step is accepted when ΔΦ ≤ this × the sum of the magnitudes of ΔΦ's terms: float32 round-off of the per-element
        /// energy changes (~1e-6 of each) must not reject a step that is exact to first order.
        /// </summary>
        const double k_LineSearchSlack = 1e-5;

        /// <summary>One substep of <paramref name="materialModel"/> (see the class comment); updates <paramref name="v"/>. Returns the CG iterations taken, summed over the Newton iterations.</summary>
        /// <param name="rotations">Per integration point: the rotation R, the warm start of its extraction (updated).</param>
        /// <param name="tangents">Neo-Hookean: scratch, <see cref="NeoHookeanTangent.Float3Count"/> per integration point (unused by the co-rotational model).</param>
        /// <param name="scratch">Scratch, one per node.</param>
        /// <param name="work">Scratch, <see cref="FemState.WorkVectors"/> per node.</param>
        /// <param name="warmStart">Per node: the previous substep's Δv, the first guess of this one's (updated); empty = start from 0.</param>
        /// <param name="contacts">Per node: the contact normal of the previous substep (zero: free); a node the solve releases is set to zero. Empty = no contacts.</param>
        /// <param name="newtonIterations">Neo-Hookean: Newton iterations (clamped to 1 … <see cref="MaxNewtonIterations"/>). The co-rotational model takes one linear step.</param>
        /// <param name="converged">True when every CG solve reached ‖r‖ ≤ <paramref name="tolerance"/> ‖b‖.</param>
        /// <param name="residual">The largest relative residual ‖r‖/‖b‖ a CG solve of the substep ended at (0 when none ran).</param>
        /// <param name="inverted">Elements with det F ≤ 0 at x.</param>
        public static int Solve(in FemModel model, FemMaterialModel materialModel, ReadOnlySpan<float3> x, Span<float3> v,
            Span<quaternion> rotations, Span<float3> tangents, int rotationIterations, Span<float3> slots, Span<float3> scratch,
            Span<float3> work, Span<float3> warmStart, Span<float3> contacts, float h, float beta, int newtonIterations, int maxIterations,
            float tolerance, out bool converged, out float residual, out int inverted)
        {
            if (!AnyContact(contacts, model.InverseMasses))
                contacts = default;
            if (materialModel == FemMaterialModel.NeoHookean)
                return SolveNeoHookean(model, x, v, rotations, tangents, rotationIterations, slots, scratch, work, warmStart, contacts, h,
                    beta, math.clamp(newtonIterations, 1, MaxNewtonIterations), maxIterations, tolerance, out converged, out residual,
                    out inverted);

            int n = x.Length, elements = model.ElementCount;
            Span<float3> dv = work.Slice(0, n), b = work.Slice(n, n);
            Span<float3> forces = scratch.Slice(0, n);
            ReadOnlySpan<float> w = model.InverseMasses, m = model.Masses;

            // f at x (rotations re-extracted), then −K_R v.
            inverted = FemForces.Elastic(model, FemMaterialModel.CoRotational, x, default, 0f, rotations, rotationIterations, slots, 0, elements);
            FemForces.Gather(model, slots, forces, 0, n);
            FemForces.WarpedStiffness(model, rotations, v, slots, 0, elements);
            FemForces.Gather(model, slots, b, 0, n);
            float c = h * beta + h * h;
            for (int i = 0; i < n; i++)
                b[i] = w[i] > 0f ? h * (forces[i] + (beta + h) * b[i]) : float3.zero;
            PreparePreconditioner(model, rotations, slots, work, c);
            int iterations = ConjugateGradient(model, false, rotations, default, slots, work, warmStart, contacts, v, c, maxIterations,
                tolerance, out converged, out residual);
            if (contacts.IsEmpty)
                RemoveMomentumError(dv, m, w);
            for (int i = 0; i < n; i++)
                v[i] += dv[i];
            if (warmStart.Length == n)
                dv.CopyTo(warmStart);
            return iterations;
        }

        /// <summary>The Newton iterations of the Neo-Hookean model (see the class comment).</summary>
        static int SolveNeoHookean(in FemModel model, ReadOnlySpan<float3> x, Span<float3> v, Span<quaternion> rotations,
            Span<float3> tangents, int rotationIterations, Span<float3> slots, Span<float3> scratch, Span<float3> work,
            Span<float3> warmStart, Span<float3> contacts, float h, float beta, int newtonIterations, int maxIterations, float tolerance,
            out bool converged, out float residual, out int inverted)
        {
            int n = x.Length, elements = model.ElementCount;
            Span<float3> dv = work.Slice(0, n), r = work.Slice(n, n), q = work.Slice(4 * n, n);
            // v_k − v: the velocity change of the earlier iterations.
            Span<float3> accumulated = scratch.Slice(0, n);
            accumulated.Clear();
            ReadOnlySpan<float> w = model.InverseMasses, m = model.Masses;
            float c = h * beta + h * h;
            converged = true;
            residual = 0f;
            inverted = 0;
            int iterations = 0;
            for (int k = 0; k < newtonIterations; k++)
            {
                // f and the tangents at the linearisation point (x, then x_k = x + h v_k) into r, then −K_k v_k into q.
                int invertedAtX = FemForces.NeoHookeanTangents(model, x, k == 0 ? default : v, h, rotations, rotationIterations, tangents,
                    slots, 0, elements);
                if (k == 0)
                    inverted = invertedAtX;
                FemForces.Gather(model, slots, r, 0, n);
                Stiffness(model, true, rotations, tangents, v, slots, q);
                // k = 0: h (f − (β + h) K v) (x⁺ = x + h(v + Δv) linearised at x); k ≥ 1: h (f − β K v_k) − M (v_k − v).
                float damping = k == 0 ? beta + h : beta;
                float bb = 0f;
                for (int i = 0; i < n; i++)
                {
                    r[i] = w[i] > 0f ? h * (r[i] + damping * q[i]) - m[i] * accumulated[i] : float3.zero;
                    bb += math.lengthsq(r[i]);
                }
                if (!(bb > 0f))
                    break; // at the solution (or a non-finite state the guard will catch)
                PreparePreconditioner(model, rotations, slots, work, c);
                iterations += ConjugateGradient(model, true, rotations, tangents, slots, work, k == 0 ? warmStart : default, contacts, v, c,
                    maxIterations, tolerance, out bool solved, out float reached);
                converged &= solved;
                residual = math.max(residual, reached);
                if (contacts.IsEmpty)
                    RemoveMomentumError(dv, m, w);
                float step = LineSearch(model, x, v, dv, accumulated, rotations, tangents, slots, q, h, beta, HeldWork(contacts, r, dv));
                for (int i = 0; i < n; i++)
                {
                    float3 change = step * dv[i];
                    v[i] += change;
                    accumulated[i] += change;
                }
            }
            if (warmStart.Length == n)
                accumulated.CopyTo(warmStart);
            return iterations;
        }

        /// <summary>
        /// The first s = 1, ½, ¼, … (at most <see cref="MaxLineSearchHalvings"/> halvings) with Φ(v_k + s δ) ≤ Φ(v_k):
        /// ΔΦ(s) = s δᵀM(v_k − v) + s²/2 δᵀMδ + h β (s v_kᵀKδ + s²/2 δᵀKδ) + Σ_e V ΔΨ_e(s) (− s fᵀδ with held contacts,
        /// <see cref="HeldWork"/>), the quadratic terms from one
        /// product K δ (into <paramref name="q"/>), the elastic one per element. Sums in double, in node and element order.
        /// </summary>
        static float LineSearch(in FemModel model, ReadOnlySpan<float3> x, ReadOnlySpan<float3> v, ReadOnlySpan<float3> dv,
            ReadOnlySpan<float3> accumulated, ReadOnlySpan<quaternion> rotations, ReadOnlySpan<float3> tangents, Span<float3> slots,
            Span<float3> q, float h, float beta, double heldWork)
        {
            int n = model.ParticleCount, elements = model.ElementCount;
            ReadOnlySpan<float> w = model.InverseMasses, m = model.Masses;
            Stiffness(model, true, rotations, tangents, dv, slots, q);
            double dMd = 0.0, dMa = 0.0, dKd = 0.0, vKd = 0.0;
            for (int i = 0; i < n; i++)
            {
                if (!(w[i] > 0f))
                    continue;
                dMd += m[i] * math.lengthsq(dv[i]);
                dMa += m[i] * math.dot(dv[i], accumulated[i]);
                dKd -= math.dot(dv[i], q[i]);
                vKd -= math.dot(v[i], q[i]);
            }
            double linear = dMa + h * beta * vKd + heldWork, quadratic = 0.5 * (dMd + h * beta * dKd);
            float step = 1f;
            for (int halving = 0; halving < MaxLineSearchHalvings; halving++)
            {
                FemForces.NeoHookeanEnergyChange(model, x, v, dv, h, step, slots, 0, elements);
                double elastic = 0.0, magnitude = 0.0;
                int stride = model.NodesPerElement;
                for (int e = 0; e < elements; e++)
                {
                    double de = slots[stride * e].x;
                    elastic += de;
                    magnitude += math.abs(de);
                }
                double inertiaAndDamping = step * linear + step * step * quadratic;
                magnitude += math.abs(step * linear) + math.abs(step * step * quadratic);
                if (inertiaAndDamping + elastic <= k_LineSearchSlack * magnitude)
                    break;
                step *= 0.5f;
            }
            return step;
        }

        /// <summary>
        /// Σ rᵢ·δᵢ over the held nodes: −fᵀδ, the work of the colliders' impulses f = −r along the step. With it the line search's
        /// ΔΦ(s) − s fᵀδ is a merit function of the constrained step (its slope at 0 is −δᵀAδ &lt; 0); without it the held
        /// targets, which raise Φ, would shorten every step.
        /// </summary>
        static double HeldWork(ReadOnlySpan<float3> contacts, ReadOnlySpan<float3> r, ReadOnlySpan<float3> dv)
        {
            double work = 0.0;
            for (int i = 0; i < contacts.Length; i++)
                if (math.lengthsq(contacts[i]) > 0f)
                    work += math.dot(r[i], dv[i]);
            return work;
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
        /// Preconditioned conjugate gradients on A Δv = b, A = M + c K, b in <paramref name="work"/>'s second vector (it becomes
        /// the residual), Δv (its first) from <paramref name="warmStart"/> when it has one value per node, the model has a
        /// rest factor and the guess's residual is smaller than ‖b‖, else from 0; z, p, q
        /// in its third to fifth, the preconditioner's blocks in its last two (<see cref="FemBlockJacobi"/>). Stops at
        /// ‖r‖ ≤ tolerance ‖b‖ (<paramref name="converged"/>), after <paramref name="maxIterations"/>, or when pᵀAp ≤ 0.
        /// With <paramref name="contacts"/>: the filtered iteration of the class comment from the held nodes' target (no warm
        /// start; r and b measured through S, the normal parts of r left unfiltered so that they hold the colliders'
        /// impulses −n·rᵢ; <paramref name="velocities"/> the velocities the targets cancel), then up to
        /// <see cref="MaxContactPasses"/> − 1 restarts after releasing the nodes a collider would pull.
        /// Returns the iterations taken; <paramref name="residual"/> = ‖r‖/‖b‖ at the end.
        /// </summary>
        static int ConjugateGradient(in FemModel model, bool neoHookean, ReadOnlySpan<quaternion> rotations, ReadOnlySpan<float3> tangents,
            Span<float3> slots, Span<float3> work, ReadOnlySpan<float3> warmStart, Span<float3> contacts, ReadOnlySpan<float3> velocities,
            float c, int maxIterations, float tolerance, out bool converged, out float residual)
        {
            int n = model.ParticleCount;
            Span<float3> dv = work.Slice(0, n), r = work.Slice(n, n), z = work.Slice(2 * n, n), p = work.Slice(3 * n, n),
                q = work.Slice(4 * n, n);
            ReadOnlySpan<float> w = model.InverseMasses, m = model.Masses;
            converged = true;
            residual = 0f;
            int iterations = 0;
            float bb, rr;
            if (!contacts.IsEmpty)
            {
                // Held nodes start at their target, no normal velocity: Δv₀ = −(v·n) n there, 0 elsewhere; r₀ = b − A Δv₀.
                for (int i = 0; i < n; i++)
                    dv[i] = w[i] > 0f ? HeldVelocityChange(velocities[i], contacts[i]) : float3.zero;
                Apply(model, neoHookean, rotations, tangents, dv, slots, q, c, m, w);
                for (int i = 0; i < n; i++)
                    r[i] -= q[i];
                bb = rr = FilteredNorm(r, contacts);
                if (!math.isfinite(bb))
                {
                    dv.Clear();
                    return 0;
                }
            }
            else
            {
                bb = FilteredNorm(r, contacts);
                if (!(bb > 0f && math.isfinite(bb)))
                {
                    dv.Clear();
                    return 0;
                }
                rr = bb;
                dv.Clear();
                // Warm start with the rest factor only: its P ≈ A makes ‖r‖ ≤ tol ‖b‖ bound the error of the soft (bending) modes
                // too; under block-Jacobi a warm-started solve stops with those modes loose (measured: a 1 s quasi-static
                // beam step lands 30 % off), while a cold one resolves the smooth load first.
                if (warmStart.Length == n && model.HasRestFactor)
                {
                    // r₀ = b − A Δv₀ (into z first), kept only when smaller than b: a guess far from the solution (after a jolt)
                    // would leave float32 round-off of ‖A Δv₀‖ in the residual, above the tolerance of a small ‖b‖.
                    for (int i = 0; i < n; i++)
                        p[i] = w[i] > 0f && math.all(math.isfinite(warmStart[i])) ? warmStart[i] : float3.zero;
                    Apply(model, neoHookean, rotations, tangents, p, slots, q, c, m, w);
                    float guessed = 0f;
                    for (int i = 0; i < n; i++)
                    {
                        z[i] = r[i] - q[i];
                        guessed += math.lengthsq(z[i]);
                    }
                    if (guessed < bb)
                    {
                        p.CopyTo(dv);
                        z.CopyTo(r);
                        rr = guessed;
                    }
                }
            }
            float threshold = tolerance * tolerance * bb;
            for (int pass = 1; ; pass++)
            {
                if (rr > threshold)
                {
                    float rz = Precondition(model, work, r, z, contacts);
                    z.CopyTo(p);
                    converged = false;
                    while (iterations < maxIterations)
                    {
                        iterations++;
                        float pq = Apply(model, neoHookean, rotations, tangents, p, slots, q, c, m, w);
                        if (!(pq > 0f))
                            break;
                        float a = rz / pq;
                        rr = 0f;
                        for (int i = 0; i < n; i++)
                        {
                            dv[i] += a * p[i];
                            r[i] -= a * q[i];
                            rr += math.lengthsq(Filter(r[i], contacts, i));
                        }
                        if (rr <= threshold)
                        {
                            converged = true;
                            break;
                        }
                        float rzNew = Precondition(model, work, r, z, contacts);
                        float beta = rzNew / rz;
                        rz = rzNew;
                        for (int i = 0; i < n; i++)
                            p[i] = z[i] + beta * p[i];
                    }
                }
                if (contacts.IsEmpty || pass >= MaxContactPasses || !ReleasePulled(contacts, r))
                    break;
                rr = FilteredNorm(r, contacts);
            }
            // With contacts ‖S r₀‖ may be 0 (the held targets solve the system): nothing is left.
            residual = bb > 0f ? math.sqrt(rr / bb) : 0f;
            return iterations;
        }

        /// <summary>Most conjugate-gradient passes of a solve with contacts: the first, and restarts after releasing nodes a collider would pull.</summary>
        public const int MaxContactPasses = 16;

        /// <summary>True when a free node (inverse mass &gt; 0) has a contact normal.</summary>
        static bool AnyContact(ReadOnlySpan<float3> contacts, ReadOnlySpan<float> w)
        {
            if (contacts.Length != w.Length)
                return false;
            for (int i = 0; i < contacts.Length; i++)
                if (w[i] > 0f && math.lengthsq(contacts[i]) > 0f)
                    return true;
            return false;
        }

        /// <summary>Sᵢ u: u − (n·u) n for a held node (contact normal n), u for a free node or without contacts.</summary>
        static float3 Filter(float3 u, ReadOnlySpan<float3> contacts, int i)
        {
            if (contacts.IsEmpty)
                return u;
            float3 normal = contacts[i];
            return u - math.dot(u, normal) * normal;
        }

        /// <summary>The change that cancels a held node's normal velocity, −(v·n) n (0 for a free node).</summary>
        static float3 HeldVelocityChange(float3 v, float3 normal) => -math.dot(v, normal) * normal;

        /// <summary>Σ |Sᵢ uᵢ|².</summary>
        static float FilteredNorm(ReadOnlySpan<float3> u, ReadOnlySpan<float3> contacts)
        {
            float sum = 0f;
            for (int i = 0; i < u.Length; i++)
                sum += math.lengthsq(Filter(u[i], contacts, i));
            return sum;
        }

        /// <summary>
        /// Releases every held node whose collider would pull: impulse fₙ = −n·rᵢ &lt; 0 (r = b − A Δv, unfiltered along n).
        /// Returns whether any was released.
        /// </summary>
        static bool ReleasePulled(Span<float3> contacts, ReadOnlySpan<float3> r)
        {
            bool released = false;
            for (int i = 0; i < contacts.Length; i++)
            {
                if (math.dot(contacts[i], r[i]) > 0f)
                {
                    contacts[i] = float3.zero;
                    released = true;
                }
            }
            return released;
        }

        /// <summary>
        /// The preconditioner of this substep's solves into <paramref name="work"/>[5n, 7n): the node rotations of the
        /// <see cref="FemRestFactor"/> when the model has one, else the <see cref="FemBlockJacobi"/> blocks.
        /// </summary>
        static void PreparePreconditioner(in FemModel model, ReadOnlySpan<quaternion> rotations, Span<float3> slots, Span<float3> work, float c)
        {
            int n = model.ParticleCount;
            if (model.HasRestFactor)
                FemRestFactor.NodeRotations(model, rotations, work.Slice(5 * n, n));
            else
                FemBlockJacobi.Build(model, rotations, slots, work, c);
        }

        /// <summary>z = P⁻¹ r with the preconditioner of <see cref="PreparePreconditioner"/>; returns r · z.</summary>
        static unsafe float Precondition(in FemModel model, Span<float3> work, ReadOnlySpan<float3> r, Span<float3> z)
        {
            int n = model.ParticleCount;
            if (!model.HasRestFactor)
                return FemBlockJacobi.Apply(work.Slice(5 * n, n), work.Slice(6 * n, n), r, z);
            fixed (float3* temp = work.Slice(6 * n, n))
                return FemRestFactor.Apply(model, work.Slice(5 * n, n), r, z, new Span<float>(temp, 3 * n));
        }

        /// <summary>
        /// z = P⁻¹ r with the preconditioner of <see cref="PreparePreconditioner"/>; returns r · z. With contacts,
        /// z = S P⁻¹ S r (symmetric positive definite on the filtered subspace), r · z = (S r) · z.
        /// </summary>
        static float Precondition(in FemModel model, Span<float3> work, ReadOnlySpan<float3> r, Span<float3> z, ReadOnlySpan<float3> contacts)
        {
            if (contacts.IsEmpty)
                return Precondition(model, work, r, z);
            for (int i = 0; i < z.Length; i++)
                z[i] = Filter(r[i], contacts, i);
            // In place: both preconditioners read all of their input before writing a node of the output (their own r · z is then not used).
            Precondition(model, work, z, z);
            float rz = 0f;
            for (int i = 0; i < z.Length; i++)
            {
                z[i] = Filter(z[i], contacts, i);
                rz += math.dot(r[i], z[i]);
            }
            return rz;
        }

        /// <summary>q = A u = M u + c K u at the free nodes (0 at pinned ones); returns uᵀA u.</summary>
        static float Apply(in FemModel model, bool neoHookean, ReadOnlySpan<quaternion> rotations, ReadOnlySpan<float3> tangents,
            ReadOnlySpan<float3> u, Span<float3> slots, Span<float3> q, float c, ReadOnlySpan<float> m, ReadOnlySpan<float> w)
        {
            // The gathered slots hold −K u.
            Stiffness(model, neoHookean, rotations, tangents, u, slots, q);
            float uq = 0f;
            for (int i = 0; i < q.Length; i++)
            {
                q[i] = w[i] > 0f ? m[i] * u[i] - c * q[i] : float3.zero;
                uq += math.dot(u[i], q[i]);
            }
            return uq;
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
    }
}
