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

        /// <summary>The shape-function gradients at rest (1/m): ∇N₁..₃ = the rows of Dm⁻¹, ∇N₀ = −(∇N₁ + ∇N₂ + ∇N₃).</summary>
        public static void CornerGradients(in float3x3 inverseRestShape, System.Span<float3> g)
        {
            float3x3 rows = math.transpose(inverseRestShape);
            g[0] = -(rows.c0 + rows.c1 + rows.c2);
            g[1] = rows.c0;
            g[2] = rows.c1;
            g[3] = rows.c2;
        }
    }
}
