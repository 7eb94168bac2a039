using System;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// The values behind each <see cref="SoftBodyPreset"/>, and the rule that keeps an authoring component's
    /// preset field honest. Why these numbers (α is the fraction of the way to the goal shape covered per
    /// frame, substep-independent; β blends the linear transform into the rotation; damping decays only the
    /// non-rigid velocity):
    /// <list type="bullet">
    /// <item>Jelly: linear, α 0.15, β 0.6, damping 3/s, elastic, μ 0.4, e 0.2. A low α lets the body sag and
    /// wobble visibly; a high β lets it shear and stretch; moderate damping lets wobbles die out within about two
    /// seconds; moderate friction and a little bounce.</item>
    /// <item>Rubber: linear, α 0.6, β 0.3, damping 4/s, elastic, μ 1.0, e 0.7. A high α recovers the shape within
    /// a few frames; a lower β keeps it firm; rubber grips (μ about 1 on most surfaces) and bounces.</item>
    /// <item>Clay: linear, α 0.4, β 0.8, damping 8/s, plasticity yield 0.05, creep 10/s, maximum 0.6, μ 0.9, e 0.
    /// A high β lets the linear transform carry the dent; beyond 5 % strain the rest shape creeps towards the
    /// deformed one within about 0.1 s, up to 60 % strain; heavy damping and no restitution make it land dead.</item>
    /// </list>
    /// </summary>
    public static class SoftBodyPresets
    {
        /// <summary>Tolerance when comparing authored values with a preset's (absolute, on values of order 1).</summary>
        public const float MatchTolerance = 1e-5f;

        public static readonly SoftBodyPresetValues Jelly = new SoftBodyPresetValues
        {
            Mode = ShapeMatchingMode.Linear,
            Stiffness = 0.15f,
            Beta = 0.6f,
            Damping = 3f,
            Plasticity = PlasticityParameters.None,
            Friction = 0.4f,
            Restitution = 0.2f,
        };

        public static readonly SoftBodyPresetValues Rubber = new SoftBodyPresetValues
        {
            Mode = ShapeMatchingMode.Linear,
            Stiffness = 0.6f,
            Beta = 0.3f,
            Damping = 4f,
            Plasticity = PlasticityParameters.None,
            Friction = 1f,
            Restitution = 0.7f,
        };

        public static readonly SoftBodyPresetValues Clay = new SoftBodyPresetValues
        {
            Mode = ShapeMatchingMode.Linear,
            Stiffness = 0.4f,
            Beta = 0.8f,
            Damping = 8f,
            Plasticity = new PlasticityParameters { Yield = 0.05f, Creep = 10f, MaxDeformation = 0.6f },
            Friction = 0.9f,
            Restitution = 0f,
        };

        /// <summary>The values of <paramref name="preset"/>; <see cref="SoftBodyPreset.Custom"/> has none.</summary>
        public static SoftBodyPresetValues Get(SoftBodyPreset preset)
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
                SoftBodyPresetValues v = Get(preset);
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
            SoftBodyPresetValues v = Get(preset);
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
