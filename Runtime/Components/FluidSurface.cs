using SoftBodyDynamics.Solvers;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// The fluid is drawn by the screen-space fluid renderer (URP's Fluid Renderer Feature): baked from
    /// <c>FluidSurfaceAuthoring</c> next to a fluid. Without it the fluid is simulated but not drawn, and nothing is
    /// uploaded for the renderer.
    /// </summary>
    public struct FluidSurface : IComponentData
    {
        /// <summary>How the surface is shaded (sanitized at bake time).</summary>
        public FluidLook Look;
        /// <summary>Radius of the sphere drawn for each particle (m).</summary>
        public float ParticleRadius;
    }
}
