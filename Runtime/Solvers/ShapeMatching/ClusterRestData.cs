using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Per-cluster data computed from the rest shape (Müller et al. 2005, eq. 7 and §4.4). The masses
    /// are the cluster weights wᵢ = mᵢ / nᵢ (nᵢ = clusters containing particle i), as in lattice shape
    /// matching (Rivers &amp; James 2007), so that overlapping clusters conserve momentum.
    /// </summary>
    public struct ClusterRestData
    {
        /// <summary>Weighted centre of the rest positions x⁰_cm (m).</summary>
        public float3 RestCenter;
        /// <summary>Σ wᵢ (kg).</summary>
        public float TotalMass;
        /// <summary>A_qq⁻¹ = (Σ wᵢ qᵢ qᵢᵀ)⁻¹ with qᵢ = x⁰ᵢ − x⁰_cm (1/(kg·m²)); identity when <see cref="LinearValid"/> is false.</summary>
        public float3x3 AqqInverse;
        /// <summary>False for planar, collinear or single-point rest shapes, where A_qq is singular: linear mode then falls back to rigid.</summary>
        public bool LinearValid;
        /// <summary>
        /// True when the scaled 9×9 Ã_qq of the quadratic mode is invertible (not planar, condition below
        /// <see cref="QuadraticShapeMatching.MaxCondition"/>); otherwise the quadratic mode falls back to linear.
        /// </summary>
        public bool QuadraticValid;
        /// <summary>Weighted mean of the squared part (qᵢ/L)∘(qᵢ/L) of q̃, subtracted so the quadratic basis is centred.</summary>
        public float3 QuadraticMeanSquare;
        /// <summary>Weighted mean of the cross part (qᵢ/L)∘(qᵢ/L).yzx of q̃, subtracted so the quadratic basis is centred.</summary>
        public float3 QuadraticMeanCross;
        /// <summary>L = √(Σ wᵢ|qᵢ|² / Σ wᵢ), the RMS radius (m); the quadratic mode works in q/L so Ã_qq is scale-free.</summary>
        public float LengthScale;
    }
}
