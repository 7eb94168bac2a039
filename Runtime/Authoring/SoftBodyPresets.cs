using System;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// The values behind each <see cref="SoftBodyPreset"/> (<see cref="ShapeMatchingMaterial"/>, where the
    /// numbers are explained), and the rule that keeps an authoring component's preset field honest.
    /// </summary>
    public static class SoftBodyPresets
    {
        /// <summary>Tolerance when comparing authored values with a preset's (absolute, on values of order 1).</summary>
        public const float MatchTolerance = 1e-5f;

        public static readonly ShapeMatchingMaterial Jelly = ShapeMatchingMaterial.Jelly;
        public static readonly ShapeMatchingMaterial Rubber = ShapeMatchingMaterial.Rubber;
        public static readonly ShapeMatchingMaterial Clay = ShapeMatchingMaterial.Clay;

        /// <summary>The values of <paramref name="preset"/>; <see cref="SoftBodyPreset.Custom"/> has none.</summary>
        public static ShapeMatchingMaterial Get(SoftBodyPreset preset)
        {
            switch (preset)
            {
                case SoftBodyPreset.Jelly: return Jelly;
                case SoftBodyPreset.Rubber: return Rubber;
                case SoftBodyPreset.Clay: return Clay;
                default: throw new ArgumentOutOfRangeException(nameof(preset), preset, "Custom has no preset values.");
            }
        }

        /// <summary>Writes <paramref name="preset"/>'s values into <paramref name="authoring"/> and selects it.</summary>
        public static void Apply(SoftBodyAuthoring authoring, SoftBodyPreset preset)
        {
            if (preset != SoftBodyPreset.Custom)
            {
                ShapeMatchingMaterial v = Get(preset);
                authoring.mode = v.Mode;
                authoring.stiffness = v.Stiffness;
                authoring.beta = v.Beta;
                authoring.damping = v.Damping;
                authoring.plasticYield = v.Plasticity.Yield;
                authoring.plasticCreep = v.Plasticity.Creep;
                authoring.plasticMaxDeformation = v.Plasticity.MaxDeformation;
                authoring.friction = v.Friction;
                authoring.restitution = v.Restitution;
            }
            authoring.preset = preset;
            authoring.appliedPreset = preset;
        }

        /// <summary>True when <paramref name="authoring"/>'s material values are <paramref name="preset"/>'s.</summary>
        public static bool Matches(SoftBodyAuthoring authoring, SoftBodyPreset preset)
        {
            if (preset == SoftBodyPreset.Custom)
                return true;
            ShapeMatchingMaterial v = Get(preset);
            return authoring.mode == v.Mode
                   && Near(authoring.stiffness, v.Stiffness) && Near(authoring.beta, v.Beta) && Near(authoring.damping, v.Damping)
                   && Near(authoring.plasticYield, v.Plasticity.Yield) && Near(authoring.plasticCreep, v.Plasticity.Creep)
                   && Near(authoring.plasticMaxDeformation, v.Plasticity.MaxDeformation)
                   && Near(authoring.friction, v.Friction) && Near(authoring.restitution, v.Restitution);
        }

        /// <summary>
        /// Keeps the preset field honest after an edit: a newly picked preset writes its values; a hand edit of
        /// a value the preset sets turns the preset to Custom. Called from <c>OnValidate</c>.
        /// </summary>
        public static void Synchronize(SoftBodyAuthoring authoring)
        {
            if (authoring.preset != authoring.appliedPreset)
                Apply(authoring, authoring.preset);
            else if (!Matches(authoring, authoring.preset))
                Apply(authoring, SoftBodyPreset.Custom);
        }

        static bool Near(float a, float b) => Math.Abs(a - b) <= MatchTolerance;
    }
}
