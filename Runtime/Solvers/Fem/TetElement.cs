using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One linear tetrahedral element at rest: its nodes, the inverse of its rest shape matrix and its volume. The
    /// deformation gradient of the element is F = Ds Dm⁻¹ with Ds = [x₁ − x₀, x₂ − x₀, x₃ − x₀] of the current
    /// positions (Sifakis &amp; Barbič 2012, §4.1).
    /// </summary>
    public struct TetElement
    {
        /// <summary>Node indices (x₀, x₁, x₂, x₃), positively oriented at rest.</summary>
        public int4 Nodes;
        /// <summary>Dm⁻¹ (1/m), Dm = [X₁ − X₀, X₂ − X₀, X₃ − X₀] of the rest positions.</summary>
        public float3x3 InverseRestShape;
        /// <summary>Rest volume V = det(Dm) / 6 (m³), &gt; 0.</summary>
        public float RestVolume;
    }
}
