using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Immutable per-cluster data computed once from the rest shape (Müller et al. 2005, eq. 7).</summary>
    public struct ClusterRestData
    {
        /// <summary>Mass-weighted centre of the rest positions x⁰_cm (m).</summary>
        public float3 RestCenter;
        /// <summary>Σ mᵢ (kg).</summary>
        public float TotalMass;
        /// <summary>A_qq⁻¹ = (Σ mᵢ qᵢ qᵢᵀ)⁻¹ with qᵢ = x⁰ᵢ − x⁰_cm; identity when <see cref="LinearValid"/> is false.</summary>
        public float3x3 AqqInverse;
        /// <summary>False for planar, collinear or single-point rest shapes, where A_qq is singular: the linear mode then falls back to rigid.</summary>
        public bool LinearValid;
    }
}
