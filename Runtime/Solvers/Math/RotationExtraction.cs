using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Rotational part of a 3×3 matrix: the proper rotation R (det R = +1) that maximises tr(Rᵀ A),
    /// i.e. the rotation closest to A in the Frobenius norm. This is the polar factor of A when
    /// det A &gt; 0, and the sign-corrected factor U·diag(1, 1, det UVᵀ)·Vᵀ of the SVD otherwise, so an
    /// inverted (mirrored) cluster yields a rotation, never a reflection.
    ///
    /// Method: the quaternion iteration of Müller, Bender, Chentanez &amp; Macklin 2016,
    /// "A Robust Method to Extract the Rotational Part of Deformations" (MIG '16), eq. (7):
    /// ω = Σᵢ rᵢ × aᵢ / (|Σᵢ rᵢ · aᵢ| + ε), q ← exp(ω) q, where rᵢ, aᵢ are the columns of R and A,
    /// upgraded to a Newton step near the optimum (see <c>Iterate</c>) so that ill-conditioned and
    /// inverted clusters converge in a few iterations instead of dozens.
    /// Two additions make it safe for every input:
    /// <list type="bullet">
    /// <item>A is divided by its largest entry first, so ε and the stopping test do not depend on
    /// the scale of the cluster (1e-4 m and 1e4 m behave alike).</item>
    /// <item>Saddles are left by a half turn: with S = A Rᵀ and λ₁ ≥ λ₂ ≥ λ₃ the eigenvalues of
    /// sym(S), a stationary R is the maximiser iff λ₂ + λ₃ ≥ 0; otherwise a half turn about the
    /// eigenvector of λ₁ raises tr(Rᵀ A) by −2(λ₂ + λ₃) &gt; 0. It is taken during the iteration
    /// wherever the curvature is negative, and once more after it stops, for the exact stationary
    /// points where ω = 0 (e.g. a cold start on a symmetric inverted A).</item>
    /// </list>
    /// The result is always a unit quaternion, hence a proper rotation. A rank-0 or non-finite A
    /// leaves the warm start unchanged (or resets a non-finite warm start to identity).
    /// </summary>
    public static class RotationExtraction
    {
        /// <summary>Default cap on iterations when warm-started from the previous step's rotation.</summary>
        public const int DefaultMaxIterations = 20;

        /// <summary>Default stopping threshold on Müller's |ω| = |Σ rᵢ × aᵢ| / |tr(RᵀA)| (radians).</summary>
        public const float DefaultTolerance = 1e-6f;

        /// <summary>Denominator guard of eq. (7), relative to the normalised A.</summary>
        const float k_DenominatorEpsilon = 1e-9f;

        /// <summary>Smallest accepted det H relative to tr(S)³ for a plain Newton step (H's condition ≲ 1e6).</summary>
        const float k_NewtonMargin = 1e-6f;

        /// <summary>λmin(H) below −margin·|tr S| is taken as negative curvature (beyond float32 noise).</summary>
        const float k_HalfTurnMargin = 1e-4f;

        /// <summary>δ: smallest eigenvalue of the shifted Hessian, relative to |tr S|.</summary>
        const float k_ShiftFraction = 0.1f;

        /// <summary>Relative drop of tr(RᵀA) that triggers backtracking (≈ 80 ε of float32).</summary>
        const float k_TraceDropTolerance = 1e-5f;

        /// <summary>Longest Newton/LM/Müller step per iteration, in radians (half turns excepted).</summary>
        const float k_MaxStepAngle = 1f;

        /// <summary>
        /// Updates <paramref name="q"/> (the warm start, usually the previous step's rotation) to the
        /// rotational part of <paramref name="a"/>. Returns the number of iterations taken.
        /// </summary>
        /// <param name="a">Any 3×3 matrix, e.g. A_pq = Σ mᵢ pᵢ qᵢᵀ of shape matching.</param>
        /// <param name="q">In: warm start. Out: unit quaternion of the extracted rotation.</param>
        /// <param name="maxIterations">Iteration cap (≥ 0).</param>
        /// <param name="tolerance">Stop when |ω| = |Σ rᵢ × aᵢ| / |tr(RᵀA)| falls below this, in radians.</param>
        public static int Extract(in float3x3 a, ref quaternion q, int maxIterations = DefaultMaxIterations,
            float tolerance = DefaultTolerance)
        {
            if (!Finite.All(q.value) || math.lengthsq(q.value) < 1e-12f)
                q = quaternion.identity;
            else
                q = math.normalize(q);

            if (!Finite.All(a))
                return 0; // non-finite input: keep the (finite) warm start; callers detect and report bad state.
            float scale = Matrix3.MaxAbs(a);
            if (!(scale > 0f))
                return 0; // rank 0 (all particles coincide): no information, keep the warm start.

            float3x3 an = a * (1f / scale);
            int iterations = Iterate(an, ref q, maxIterations, tolerance);

            // Final check for an exact saddle, where the iteration stopped because g = 0.
            float3x3 s = math.mul(an, math.transpose(new float3x3(q)));
            if (TryHalfTurnAxis(s, s.c0.x + s.c1.y + s.c2.z, out float3 axis))
            {
                q = math.normalize(math.mul(new quaternion(new float4(axis, 0f)), q)); // half turn: (axis, 0)
                iterations += Iterate(an, ref q, maxIterations - iterations, tolerance);
            }
            return iterations;
        }

        /// <summary>
        /// Iterates q ← exp(θ) q on a normalised A until Müller's |ω| = |g| / |tr S| &lt; tolerance. The gradient of
        /// f(θ) = tr((exp([θ]) R)ᵀ A) is g = Σᵢ rᵢ × aᵢ (the numerator of Müller et al. 2016, eq. 7)
        /// and its Hessian is −H with H = tr(S)·I − sym(S), S = A Rᵀ (second-order expansion of
        /// exp([θ])). Where H is positive definite — always near a unique maximum — the Newton step
        /// θ = H⁻¹ g converges quadratically. Elsewhere (far from the optimum, or between a maximum and
        /// a saddle on inverted clusters) H is shifted to H + μI with μ making its smallest eigenvalue
        /// δ·|tr S| (Levenberg–Marquardt), which still ascends and leaves flat regions quickly, and where
        /// H has clearly negative curvature the step is the half turn of <see cref="TryHalfTurnAxis"/>.
        /// Müller's eq. (7), θ = g / (|tr S| + ε), is the limit of a large shift and the last resort.
        /// </summary>
        static int Iterate(in float3x3 a, ref quaternion q, int maxIterations, float tolerance)
        {
            // Backtracking: a step that lowered tr(RᵀA) (a Newton step past a ridge) is halved and
            // retried from the previous rotation, so the objective never decreases and no cycle forms.
            quaternion qPrev = q;
            float3 thetaPrev = float3.zero;
            float tracePrev = float.NegativeInfinity;
            for (int i = 0; i < maxIterations; i++)
            {
                float3x3 r = new float3x3(q);
                float3x3 s = math.mul(a, math.transpose(r));
                float trace = s.c0.x + s.c1.y + s.c2.z;
                // Only a drop well above float32 round-off of the trace counts: near the optimum a
                // Newton step gains ~θ²·σ, far below what float32 resolves.
                if (trace < tracePrev - k_TraceDropTolerance * math.abs(tracePrev))
                {
                    thetaPrev *= 0.5f;
                    float half = math.length(thetaPrev);
                    if (!(half >= tolerance))
                    {
                        q = qPrev;
                        return i;
                    }
                    q = math.normalize(math.mul(quaternion.AxisAngle(thetaPrev * (1f / half), half), qPrev));
                    continue;
                }

                float3 g = math.cross(r.c0, a.c0) + math.cross(r.c1, a.c1) + math.cross(r.c2, a.c2);
                // Stop on Müller's |ω| = |g| / |tr S|: it measures the residual itself, whereas the
                // Newton step amplifies float32 noise in g by 1/λmin(H) on nearly flat axes.
                if (!(math.length(g) >= tolerance * (math.abs(trace) + k_DenominatorEpsilon))) // also stops on NaN
                    return i;
                float3 theta = Step(s, g, trace);
                float w = math.length(theta);
                if (!(w > 0f))
                    return i;
                qPrev = q;
                thetaPrev = theta;
                tracePrev = trace;
                q = math.normalize(math.mul(quaternion.AxisAngle(theta * (1f / w), w), q));
            }
            return maxIterations;
        }

        /// <summary>
        /// The ascent step θ for S = A Rᵀ, gradient g and trace tr S (see <c>Iterate</c>): a half turn
        /// (|θ| = π) or a Newton/LM/Müller step capped at <see cref="k_MaxStepAngle"/>.
        /// </summary>
        static float3 Step(in float3x3 s, float3 g, float trace)
        {
            float t = math.abs(trace) + k_DenominatorEpsilon;
            // H = tr(S)·I − sym(S)
            float h00 = trace - s.c0.x, h11 = trace - s.c1.y, h22 = trace - s.c2.z;
            float h01 = -0.5f * (s.c1.x + s.c0.y);
            float h02 = -0.5f * (s.c2.x + s.c0.z);
            float h12 = -0.5f * (s.c2.y + s.c1.z);
            if (TrySolveSpd(h00, h11, h22, h01, h02, h12, g, k_NewtonMargin * t * t * t, out float3 theta))
                return CapStep(theta);

            if (TryHalfTurnAxis(s, trace, out float3 axis, out float lambdaMinH))
                return axis * math.PI;
            // Levenberg–Marquardt shift so that λmin(H + μI) = δ·|tr S|.
            float mu = math.max(0f, k_ShiftFraction * t - lambdaMinH);
            if (TrySolveSpd(h00 + mu, h11 + mu, h22 + mu, h01, h02, h12, g, 0f, out theta))
                return CapStep(theta);
            return CapStep(g * (1f / t)); // Müller et al. 2016, eq. (7)
        }

        /// <summary>Shortens a step longer than <see cref="k_MaxStepAngle"/> (beyond it the quadratic model is not trusted).</summary>
        static float3 CapStep(float3 theta)
        {
            float w = math.length(theta);
            return w > k_MaxStepAngle ? theta * (k_MaxStepAngle / w) : theta;
        }

        static bool TryHalfTurnAxis(in float3x3 s, float trace, out float3 axis) =>
            TryHalfTurnAxis(s, trace, out axis, out _);

        /// <summary>
        /// Where tr(RᵀA) has negative curvature — λmin(H) = tr S − λ₁ &lt; −margin·|tr S|, with
        /// eig(H) = tr S − eig(sym S) and λ₁ = λmax(sym S) — R sits on the wrong sheet and would
        /// converge to a saddle. A half turn about the unit eigenvector v of λ₁ changes tr(RᵀA) to
        /// tr(S (2vvᵀ − I)) = 2λ₁ − tr S, a gain of −2 λmin(H) &gt; 0, exactly. Returns that axis.
        /// </summary>
        static bool TryHalfTurnAxis(in float3x3 s, float trace, out float3 axis, out float lambdaMinH)
        {
            float3x3 sym = 0.5f * (s + math.transpose(s));
            float lambda1 = LargestEigenvalue(sym);
            lambdaMinH = trace - lambda1;
            axis = float3.zero;
            if (!(lambdaMinH < -k_HalfTurnMargin * (math.abs(trace) + k_DenominatorEpsilon)))
                return false;
            axis = EigenvectorOf(sym, lambda1);
            return math.lengthsq(axis) > 0f;
        }

        /// <summary>Solves H θ = g for symmetric H when H is positive definite with det H &gt; minDet.</summary>
        static bool TrySolveSpd(float h00, float h11, float h22, float h01, float h02, float h12, float3 g,
            float minDet, out float3 theta)
        {
            float m2 = h00 * h11 - h01 * h01;
            float c0 = h11 * h22 - h12 * h12, c1 = h02 * h12 - h01 * h22, c2 = h01 * h12 - h02 * h11;
            float det = h00 * c0 + h01 * c1 + h02 * c2;
            // Sylvester's criterion.
            if (!(h00 > 0f) || !(m2 > 0f) || !(det > minDet) || !(det > 0f))
            {
                theta = default;
                return false;
            }
            float i11 = h00 * h22 - h02 * h02, i12 = h01 * h02 - h00 * h12;
            theta = new float3(c0 * g.x + c1 * g.y + c2 * g.z,
                               c1 * g.x + i11 * g.y + i12 * g.z,
                               c2 * g.x + i12 * g.y + m2 * g.z) * (1f / det);
            return true;
        }

        /// <summary>Largest eigenvalue of a symmetric 3×3 matrix (trigonometric closed form).</summary>
        static float LargestEigenvalue(in float3x3 m)
        {
            float p1 = m.c1.x * m.c1.x + m.c2.x * m.c2.x + m.c2.y * m.c2.y;
            float tr = m.c0.x + m.c1.y + m.c2.z;
            float mean = tr / 3f;
            float d0 = m.c0.x - mean, d1 = m.c1.y - mean, d2 = m.c2.z - mean;
            float p2 = d0 * d0 + d1 * d1 + d2 * d2 + 2f * p1;
            if (p2 <= 1e-30f)
                return mean; // a multiple of identity
            float p = math.sqrt(p2 / 6f);
            float3x3 b = (m - mean * float3x3.identity) * (1f / p);
            float r = math.clamp(0.5f * math.determinant(b), -1f, 1f);
            float phi = math.acos(r) / 3f;
            return mean + 2f * p * math.cos(phi);
        }

        /// <summary>Unit eigenvector of the symmetric matrix m for eigenvalue lambda (largest-norm row cross product).</summary>
        static float3 EigenvectorOf(in float3x3 m, float lambda)
        {
            float3x3 d = m - lambda * float3x3.identity; // symmetric, so columns = rows
            float3 v0 = math.cross(d.c0, d.c1), v1 = math.cross(d.c0, d.c2), v2 = math.cross(d.c1, d.c2);
            float l0 = math.lengthsq(v0), l1 = math.lengthsq(v1), l2 = math.lengthsq(v2);
            float3 best = v0; float bestLen = l0;
            if (l1 > bestLen) { best = v1; bestLen = l1; }
            if (l2 > bestLen) { best = v2; bestLen = l2; }
            return bestLen > 0f ? best * math.rsqrt(bestLen) : float3.zero;
        }
    }
}
