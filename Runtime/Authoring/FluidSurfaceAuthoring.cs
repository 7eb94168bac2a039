using SoftBodyDynamics.Solvers;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>The look presets of <see cref="FluidLook"/>, or a custom look.</summary>
    public enum FluidLookPreset
    {
        Water, Honey, Slime, Oil, Lava, FlatColour, ThicknessTint, Toon, Custom,
    }

    /// <summary>
    /// Draws the fluid on this GameObject with the screen-space fluid renderer (add the Fluid Renderer Feature to the URP
    /// renderer). Each particle is a sphere; the renderer smooths their depth into a surface and shades it with the look.
    /// </summary>
    [DisallowMultipleComponent]
    [RequireComponent(typeof(FluidAuthoring))]
    [AddComponentMenu("Soft Body Dynamics/Fluid Surface")]
    public sealed class FluidSurfaceAuthoring : MonoBehaviour
    {
        [Tooltip("The look: lit water, honey, slime, oil or lava (glows by the particle attribute, its temperature in K), or unlit flat, thickness-tinted or toon; Custom uses the values below.")]
        public FluidLookPreset look = FluidLookPreset.Water;

        [Tooltip("Custom look (linear colours; absorption in 1/m; attributes in K). Used when the look is Custom.")]
        public FluidLook customLook = FluidLook.Water;

        [Tooltip("Radius of the sphere drawn per particle, in particle spacings (0.5–2; 0.7 closes the gaps of a resting fluid without blurring it).")]
        [Min(0f)]
        public float radiusInSpacings = 0.7f;

        /// <summary>The look this component asks for, before sanitizing.</summary>
        public FluidLook Look => look switch
        {
            FluidLookPreset.Water => FluidLook.Water,
            FluidLookPreset.Honey => FluidLook.Honey,
            FluidLookPreset.Slime => FluidLook.Slime,
            FluidLookPreset.Oil => FluidLook.Oil,
            FluidLookPreset.Lava => FluidLook.Lava,
            FluidLookPreset.FlatColour => FluidLook.FlatColour,
            FluidLookPreset.ThicknessTint => FluidLook.ThicknessTint,
            FluidLookPreset.Toon => FluidLook.Toon,
            _ => customLook,
        };
    }
}
