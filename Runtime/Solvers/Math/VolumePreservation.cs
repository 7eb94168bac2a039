using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Volume of the linear shape-matching transform. The solver's linear mode uses
    /// <see cref="ConservativeLinearGoalTransform"/>: the optimal fit A blended with R plus the gradient of a volume
    /// energy, so its goals derive from an energy. Müller et al. 2005 (§4.3) instead normalise A ← A / ∛det(A)
    /// (<see cref="TryNormalize"/>, <see cref="LinearGoalTransform"/>), which keeps det A = 1 but is not a gradient and feeds
    /// energy into an undamped spinning body. Flat, collapsed or inverted clusters (det ≤ floor) fall back to the rigid rotation R.
    /// </summary>
    public static class VolumePreservation
    {
        /// <summary>
        /// Smallest accepted det(A) relative to the cube of A's largest entry. Below it the linear
        /// transform is treated as degenerate. 1e-6 means a cluster squashed to one hundredth of
        /// its size along one axis still uses the linear mode.
        /// </summary>
        public const float DefaultRelativeDeterminantFloor = 1e-6f;

        /// <summary>
        /// Largest strain a goal transform may ask for (1 = 100 % strain): ‖Ã − R‖_F for the paper's goals
        /// (<see cref="LimitStrain"/>), and the same norm in the fit's metric for the conservative ones (<see cref="StrainLimit"/>).
        /// A cluster squashed flat has a tiny det A, and A / ∛det A then stretches it enormously in the other directions (a
        /// cluster flattened to 1e-5 would be told to grow 46-fold in-plane): goals that far away inject energy.
        /// </summary>
        public const float MaxGoalStrain = 1f;

        /// <summary>
        /// Relative determinant (det of A over its largest entry cubed) from which a goal follows the full β. Below
        /// it the β part fades linearly to zero at <see cref="DefaultRelativeDeterminantFloor"/>, so the fallback to
        /// rigid goals of a flat, collapsed or inverted cluster is continuous. Shared by the linear and quadratic modes.
        /// </summary>
        public const float FadeEnd = 10f * DefaultRelativeDeterminantFloor;

        /// <summary>Weight (0 to 1) of the β part for relative determinant <paramref name="relativeDeterminant"/>.</summary>
        public static float BetaFade(float relativeDeterminant) =>
            math.saturate((relativeDeterminant - DefaultRelativeDeterminantFloor) / (FadeEnd - DefaultRelativeDeterminantFloor));

        /// <summary>
        /// Returns A / ∛det(A) when det(A) is finite and above the floor; otherwise returns false and
        /// leaves <paramref name="normalized"/> at identity.
        /// </summary>
        public static bool TryNormalize(in float3x3 a, out float3x3 normalized,
            float relativeDeterminantFloor = DefaultRelativeDeterminantFloor) =>
            TryNormalize(a, out normalized, out _, relativeDeterminantFloor);

        /// <summary>As above; also returns det(A / max|Aᵢⱼ|), the determinant relative to A's scale.</summary>
        public static bool TryNormalize(in float3x3 a, out float3x3 normalized, out float relativeDeterminant,
            float relativeDeterminantFloor = DefaultRelativeDeterminantFloor)
        {
            normalized = float3x3.identity;
            relativeDeterminant = RelativeDeterminant(a, out float3x3 an);
            if (!(relativeDeterminant > relativeDeterminantFloor)) // also rejects NaN
                return false;
            normalized = an * (1f / math.pow(relativeDeterminant, 1f / 3f));
            return true;
        }

        /// <summary>det(A / max|Aᵢⱼ|), the determinant relative to A's scale; 0 for a zero or non-finite A.</summary>
        public static float RelativeDeterminant(in float3x3 a) => RelativeDeterminant(a, out _);

        static float RelativeDeterminant(in float3x3 a, out float3x3 scaled)
        {
            scaled = float3x3.identity;
            if (!Finite.All(a))
                return 0f;
            float scale = Matrix3.MaxAbs(a);
            if (!(scale > 0f))
                return 0f;
            // Normalise first so det cannot under- or overflow in float32.
            scaled = a * (1f / scale);
            return math.determinant(scaled);
        }

        /// <summary>
        /// Goal transform of the linear mode: R + β·(Ã − R), i.e. β·Ã + (1 − β)·R with Ã the
        /// volume-normalised linear transform (Müller et al. 2005, eq. 8 and §4.3), made safe for
        /// squashed clusters in two ways: the strain Ã − R is limited to <see cref="MaxGoalStrain"/>,
        /// and it fades out linearly as the relative det falls from <see cref="FadeEnd"/> to the floor, so the fallback to
        /// R is continuous (no jump in the goals, hence no kick, when a cluster flattens).
        /// </summary>
        /// <param name="aLinear">A = A_pq · A_qq⁻¹.</param>
        /// <param name="rotation">The rotational part of A_pq.</param>
        /// <param name="beta">Blend toward the linear transform, 0 (rigid) to 1 (fully linear).</param>
        /// <param name="rigidFallback">True when the linear part was degenerate and R was used.</param>
        public static float3x3 LinearGoalTransform(in float3x3 aLinear, in float3x3 rotation, float beta,
            out bool rigidFallback)
        {
            const float floor = DefaultRelativeDeterminantFloor;
            if (!TryNormalize(aLinear, out float3x3 normalized, out float det, floor))
            {
                rigidFallback = true;
                return rotation;
            }
            rigidFallback = false;
            return rotation + (math.saturate(beta) * BetaFade(det)) * LimitStrain(normalized - rotation);
        }

        /// <summary>
        /// Conservative goal transform of the linear mode: R + β·fade·limit·(A − R) + V, with A = A_pq A_qq⁻¹ the optimal linear fit
        /// (not volume-normalised), the strain A − R limited to <see cref="MaxGoalStrain"/> in the fit's metric
        /// (<see cref="StrainLimit"/>) and faded as in <see cref="LinearGoalTransform(in float3x3, in float3x3, float, out bool)"/>, and V the gradient of the volume energy
        /// E = ½ ω² κ M L² (det A − 1)², V = −κ (J − 1) M L² cof(A) A_qq⁻¹ with κ = β·fade/9 (a uniform dilation is then
        /// resisted at the full ω², as by Müller et al.'s A/∛det A). Away from the limiter both parts are gradients of
        /// energies (β E_A + (1 − β) E_R by the envelope theorem, and E; the limiter keeps that, see <see cref="StrainLimit"/>), so an
        /// undamped free body gains no energy, which the
        /// normalisation A/∛det A does not give: a spinning body with overlapping clusters at β = 0.99 gains 20× its kinetic energy with it.
        /// </summary>
        /// <param name="aLinear">A = A_pq · A_qq⁻¹.</param>
        /// <param name="rotation">The rotational part of A_pq.</param>
        /// <param name="beta">Blend toward the linear transform, 0 (rigid) to 1.</param>
        /// <param name="totalMass">The cluster's mass M (kg).</param>
        /// <param name="lengthScale">The cluster's length L (m): M L² A_qq⁻¹ is dimensionless (3·I for an isotropic cluster).</param>
        /// <param name="aqqInverse">A_qq⁻¹ of the cluster (1/(kg m²)).</param>
        /// <param name="rigidFallback">True when A was degenerate (flat, collapsed or inverted) and R was used.</param>
        public static float3x3 ConservativeLinearGoalTransform(in float3x3 aLinear, in float3x3 rotation, float beta, float totalMass,
            float lengthScale, in float3x3 aqqInverse, out bool rigidFallback)
        {
            float det = RelativeDeterminant(aLinear);
            if (!(det > DefaultRelativeDeterminantFloor))
            {
                rigidFallback = true;
                return rotation;
            }
            rigidFallback = false;
            float3x3 strain = aLinear - rotation;
            float massLengthSquared = totalMass * lengthScale * lengthScale;
            float fitGap = Matrix3.Dot(math.mul(strain, math.inverse(aqqInverse)), strain);
            float weight = math.saturate(beta) * BetaFade(det) * StrainLimit(fitGap, massLengthSquared);
            float3x3 t = rotation + weight * strain;
            float j = math.determinant(aLinear);
            float3x3 cofactor = j * math.transpose(math.inverse(aLinear));
            float3x3 volume = (-math.saturate(beta) * BetaFade(det) / 9f * (j - 1f) * massLengthSquared) * math.mul(cofactor, aqqInverse);
            return Finite.All(volume) ? t + volume : t;
        }

        /// <summary>
        /// Factor (0 to 1] on β that limits a goal's strain D = Ã − R to <see cref="MaxGoalStrain"/>, measured in the fit's own
        /// metric: ε² = 3 tr(D A_qq Dᵀ) / M (the Frobenius norm of D for an isotropic cluster, A_qq = M L²/3 · I). Since Ã
        /// minimises the fit energy E(T) = ½ Σ wᵢ |T qᵢ − pᵢ|², ½ tr(D A_qq Dᵀ) = E_R − E_A exactly, so the limited pull
        /// c(δ) = β min(1, ε_max/ε) is the gradient of Φ = E_R − h(E_R − E_A) with h′ = c: conservative at every strain,
        /// where scaling by the plain Frobenius norm is not (an undamped quadratic body at β = 0.99 gained 2× its energy).
        /// </summary>
        /// <param name="fitGap">tr(D A_qq Dᵀ) (kg m²; in kg when the offsets are divided by L).</param>
        /// <param name="massLengthSquared">M L² in the same units (M alone when the offsets are divided by L).</param>
        public static float StrainLimit(float fitGap, float massLengthSquared)
        {
            float strainSquared = 3f * fitGap / massLengthSquared;
            const float max = MaxGoalStrain * MaxGoalStrain;
            return strainSquared > max ? MaxGoalStrain / math.sqrt(strainSquared) : 1f; // NaN → 1: the fade and guard handle it
        }

        /// <summary>The strain scaled down to a Frobenius norm of at most <see cref="MaxGoalStrain"/>.</summary>
        public static float3x3 LimitStrain(in float3x3 strain)
        {
            float norm = math.sqrt(math.lengthsq(strain.c0) + math.lengthsq(strain.c1) + math.lengthsq(strain.c2));
            return norm > MaxGoalStrain ? strain * (MaxGoalStrain / norm) : strain;
        }
    }
}
