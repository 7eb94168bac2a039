using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Named fluid materials.</summary>
    public enum FluidPresetKind : byte
    {
        Water = 0,
        Honey = 1,
        Oil = 2,
        Slime = 3,
        Lava = 4,
    }

    /// <summary>A fluid material: solver settings with physical values, plus the look's base colour and the particle attribute it starts with.</summary>
    public struct FluidPreset
    {
        /// <summary>Fluid settings (spacing and domain are the defaults; the authoring component sets its own).</summary>
        public FluidParameters Parameters;
        /// <summary>Base colour of the look, linear RGBA (absorption tint for clear liquids, albedo for opaque ones).</summary>
        public float4 Color;
        /// <summary>Initial particle attribute: temperature in K (lava cools from it; others start at room temperature).</summary>
        public float Attribute;
    }

    /// <summary>
    /// Presets with physical meaning: density ρ₀ and kinematic viscosity ν = μ/ρ₀ at room temperature (lava at
    /// eruption temperature), from handbook values (water μ = 1.0 mPa·s; olive oil ≈ 80 mPa·s, ρ ≈ 910; honey
    /// ≈ 10 Pa·s, ρ ≈ 1420; basaltic lava ≈ 100–1000 Pa·s, ρ ≈ 2700). Slime is non-Newtonian; it gets a high
    /// constant viscosity and strong cohesion. Viscosity is implicit, so the real values are usable at game time
    /// steps (more Jacobi iterations make a thick fluid closer to its converged viscosity).
    /// </summary>
    public static class FluidPresets
    {
        /// <summary>The preset of <paramref name="kind"/> (water for an unknown value).</summary>
        public static FluidPreset Get(FluidPresetKind kind)
        {
            FluidParameters p = FluidParameters.Default;
            switch (kind)
            {
                case FluidPresetKind.Honey:
                    p.RestDensity = 1420f;
                    p.Viscosity = 7e-3f;
                    p.ViscosityIterations = 8;
                    p.Cohesion = FluidCohesionModel.Flocking;
                    p.CohesionWeight = 20f;
                    return new FluidPreset { Parameters = p, Color = new float4(0.85f, 0.5f, 0.08f, 1f), Attribute = 293f };
                case FluidPresetKind.Oil:
                    p.RestDensity = 910f;
                    p.Viscosity = 8.8e-5f;
                    return new FluidPreset { Parameters = p, Color = new float4(0.75f, 0.65f, 0.2f, 1f), Attribute = 293f };
                case FluidPresetKind.Slime:
                    p.RestDensity = 1100f;
                    p.Viscosity = 2e-2f;
                    p.ViscosityIterations = 8;
                    p.Cohesion = FluidCohesionModel.Flocking;
                    p.CohesionWeight = 60f;
                    p.SeparationWeight = 200f;
                    p.AlignmentRate = 5f;
                    return new FluidPreset { Parameters = p, Color = new float4(0.3f, 0.85f, 0.2f, 1f), Attribute = 293f };
                case FluidPresetKind.Lava:
                    p.RestDensity = 2700f;
                    p.Viscosity = 0.1f;
                    p.ViscosityIterations = 12;
                    return new FluidPreset { Parameters = p, Color = new float4(1f, 0.3f, 0.05f, 1f), Attribute = 1400f };
                default:
                    p.ViscosityIterations = 1;
                    return new FluidPreset { Parameters = p, Color = new float4(0.6f, 0.8f, 0.95f, 1f), Attribute = 293f };
            }
        }
    }
}
