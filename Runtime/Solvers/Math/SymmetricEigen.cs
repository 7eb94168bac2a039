using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Eigen-decomposition of a symmetric 3×3 matrix by the cyclic Jacobi method (Golub &amp; Van Loan, "Matrix
    /// Computations", §8.5): plane rotations J(p, q, θ) chosen to zero the entry a_pq, swept over (0,1), (0,2), (1,2)
    /// until the off-diagonal part is at float32 round-off. Each rotation has det +1, so the eigenvector matrix is a
    /// proper rotation. Burst-compatible: no allocation, a fixed bound on the work.
    /// </summary>
    public static class SymmetricEigen
    {
        /// <summary>Most sweeps (3 rotations each); Jacobi converges quadratically, 3×3 needs 3–4 at float32.</summary>
        public const int MaxSweeps = 8;

        /// <summary>
        /// An entry |a_pq| ≤ this × (|a_pp| + |a_qq|) is taken as zero: far below float32 round-off of the diagonal
        /// (its rotation would move the eigenvalues by ~ a_pq²/|a_pp − a_qq|), and it keeps tan 2θ finite.
        /// </summary>
        const float k_NegligibleRatio = 1e-10f;

        /// <summary>
        /// <paramref name="s"/> = V diag(<paramref name="eigenvalues"/>) Vᵀ with V (<paramref name="vectors"/>, columns the
        /// unit eigenvectors) a proper rotation. Of a non-symmetric <paramref name="s"/> the symmetric part ½(s + sᵀ) is decomposed. Eigenvalues
        /// are unsorted. Returns the sweeps taken.
        /// </summary>
        public static int Decompose(in float3x3 s, out float3x3 vectors, out float3 eigenvalues)
        {
            float a00 = s.c0.x, a11 = s.c1.y, a22 = s.c2.z;
            float a01 = 0.5f * (s.c1.x + s.c0.y), a02 = 0.5f * (s.c2.x + s.c0.z), a12 = 0.5f * (s.c2.y + s.c1.z);
            float3 v0 = new float3(1f, 0f, 0f), v1 = new float3(0f, 1f, 0f), v2 = new float3(0f, 0f, 1f);
            int sweep = 0;
            while (sweep < MaxSweeps && !(Negligible(a01, a00, a11) && Negligible(a02, a00, a22) && Negligible(a12, a11, a22)))
            {
                sweep++;
                Rotate(ref a00, ref a11, ref a01, ref a02, ref a12, ref v0, ref v1);
                // (0,2): the third index is 1; a01 and a12 are its couplings to 0 and 2.
                Rotate(ref a00, ref a22, ref a02, ref a01, ref a12, ref v0, ref v2);
                // (1,2): the third index is 0; a01 and a02 are its couplings to 1 and 2.
                Rotate(ref a11, ref a22, ref a12, ref a01, ref a02, ref v1, ref v2);
            }
            vectors = new float3x3(v0, v1, v2);
            eigenvalues = new float3(a00, a11, a22);
            return sweep;
        }

        static bool Negligible(float apq, float app, float aqq) =>
            !(math.abs(apq) > k_NegligibleRatio * (math.abs(app) + math.abs(aqq)));

        /// <summary>
        /// One Jacobi rotation of the pair (p, q) with r the third index: A ← JᵀAJ, V ← VJ, J = [[c, s], [−s, c]] on (p, q).
        /// With θ = (a_qq − a_pp)/(2a_pq) and t = tan φ = sgn θ / (|θ| + √(θ² + 1)) (the smaller root of t² + 2θt − 1 = 0),
        /// a_pp −= t a_pq, a_qq += t a_pq, a_pq = 0, a_rp ← c a_rp − s a_rq, a_rq ← s a_rp + c a_rq (Golub &amp; Van Loan §8.5.2).
        /// </summary>
        static void Rotate(ref float app, ref float aqq, ref float apq, ref float arp, ref float arq, ref float3 vp, ref float3 vq)
        {
            if (Negligible(apq, app, aqq))
                return;
            float theta = (aqq - app) / (2f * apq);
            float t = (theta >= 0f ? 1f : -1f) / (math.abs(theta) + math.sqrt(theta * theta + 1f));
            float c = math.rsqrt(t * t + 1f), s = t * c;
            app -= t * apq;
            aqq += t * apq;
            apq = 0f;
            float rp = arp, rq = arq;
            arp = c * rp - s * rq;
            arq = s * rp + c * rq;
            float3 p = vp, q = vq;
            vp = c * p - s * q;
            vq = s * p + c * q;
        }
    }
}
