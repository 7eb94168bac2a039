using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Put on the particle prefab of a fluid with Entities storage: every particle becomes an instance of this prefab
    /// (a sphere MeshRenderer on it is drawn by Entities Graphics until the fluid renderer exists). The particle's mass
    /// follows from the fluid (ρ₀ over the kernel sum of a rest lattice at the spacing, about ρ₀·Δx³); its lifetime and
    /// attribute come from the tap that spawns it.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("Soft Body Dynamics/Metaball Particle")]
    public sealed class MetaballParticleAuthoring : MonoBehaviour
    {
        [Tooltip("Radius of the metaball (m) for drawing; about half the fluid's particle spacing. The prefab's scale sets the size of a sphere mesh on it.")]
        [Min(0f)]
        public float radius = 0.01f;
    }
}
