using System;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// The values behind each <see cref="SoftBodyPreset"/>: the physical material (<see cref="ElasticMaterial"/>, used by
    /// the mass-spring and FEM methods, the same numbers for both) and the shape-matching values
    /// (<see cref="ShapeMatchingMaterial"/>, where those numbers are explained), and the rule that keeps an authoring
    /// component's preset field honest.
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

        /// <summary>
        /// The physical material of <paramref name="preset"/> (<see cref="ElasticMaterial"/>'s presets of the same name), the
        /// same for the mass-spring and FEM methods; <see cref="SoftBodyPreset.Custom"/> has none.
        /// </summary>
        public static ElasticMaterial GetMaterial(SoftBodyPreset preset)
        {
            switch (preset)
            {
                case SoftBodyPreset.Jelly: return ElasticMaterial.Jelly;
                case SoftBodyPreset.Rubber: return ElasticMaterial.Rubber;
                case SoftBodyPreset.Clay: return ElasticMaterial.Clay;
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
                authoring.frequency = v.Frequency;
                authoring.dampingRatio = v.DampingRatio;
                authoring.beta = v.Beta;
                authoring.plasticYield = v.Plasticity.Yield;
                authoring.plasticCreep = v.Plasticity.Creep;
                authoring.plasticMaxDeformation = v.Plasticity.MaxDeformation;
                authoring.friction = v.Friction;
                authoring.restitution = v.Restitution;
                ElasticMaterial m = GetMaterial(preset);
                authoring.youngsModulus = m.YoungsModulus;
                authoring.poissonRatio = m.PoissonRatio;
                authoring.density = m.Density;
                authoring.materialDampingRatio = m.DampingRatio;
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
                   && Near(authoring.frequency, v.Frequency) && Near(authoring.dampingRatio, v.DampingRatio) && Near(authoring.beta, v.Beta)
                   && Near(authoring.plasticYield, v.Plasticity.Yield) && Near(authoring.plasticCreep, v.Plasticity.Creep)
                   && Near(authoring.plasticMaxDeformation, v.Plasticity.MaxDeformation)
                   && Near(authoring.friction, v.Friction) && Near(authoring.restitution, v.Restitution)
                   && SameMaterial(authoring, GetMaterial(preset));
        }

        /// <summary>True when the authored physical material is <paramref name="m"/> (relative tolerance on E and ρ, whose scale is large).</summary>
        static bool SameMaterial(SoftBodyAuthoring authoring, in ElasticMaterial m) =>
            NearRelative(authoring.youngsModulus, m.YoungsModulus) && Near(authoring.poissonRatio, m.PoissonRatio)
            && NearRelative(authoring.density, m.Density) && Near(authoring.materialDampingRatio, m.DampingRatio);

        /// <summary>
        /// A component saved before the physical material existed deserializes with the field defaults (Jelly's material)
        /// whatever its preset: it takes its preset's material instead, so the preset is not turned to Custom. A component
        /// whose material differs from Jelly's, or whose preset is Jelly or Custom, is left alone.
        /// </summary>
        public static void MigrateElasticMaterial(SoftBodyAuthoring authoring)
        {
            if (authoring.preset == SoftBodyPreset.Custom || authoring.preset == SoftBodyPreset.Jelly
                || authoring.appliedPreset != authoring.preset || !SameMaterial(authoring, ElasticMaterial.Jelly))
                return;
            ElasticMaterial m = GetMaterial(authoring.preset);
            authoring.youngsModulus = m.YoungsModulus;
            authoring.poissonRatio = m.PoissonRatio;
            authoring.density = m.Density;
            authoring.materialDampingRatio = m.DampingRatio;
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

        /// <summary>
        /// The 1/60 s fixed step 0.2 bodies were tuned at (the default of Entities' fixed-step group): their α is
        /// converted at this step.
        /// </summary>
        public const float LegacyTimeStep = 1f / 60f;

        /// <summary>
        /// Converts the per-frame stiffness α and damping rate a 0.2 component was saved with
        /// (<see cref="SoftBodyAuthoring.legacyStiffness"/>) into the frequency and damping ratio that behave the
        /// same at the 1/60 s step and the component's substeps (<see cref="LegacyStiffness.ToFrequency"/>). A
        /// component that still named a preset simply takes the preset's new values (they were derived the same way).
        /// Runs once: the legacy fields are cleared.
        /// </summary>
        public static void MigrateLegacyStiffness(SoftBodyAuthoring authoring)
        {
            if (authoring.legacyStiffness < 0f)
                return;
            if (authoring.preset != SoftBodyPreset.Custom)
            {
                ShapeMatchingMaterial v = Get(authoring.preset);
                authoring.frequency = v.Frequency;
                authoring.dampingRatio = v.DampingRatio;
            }
            else if (LegacyStiffness.ToFrequency(authoring.legacyStiffness, Math.Max(0f, authoring.legacyDamping),
                         authoring.substeps, LegacyTimeStep, out float f, out float zeta))
            {
                authoring.frequency = f;
                authoring.dampingRatio = zeta;
            }
            authoring.legacyStiffness = -1f;
            authoring.legacyDamping = -1f;
        }

        static bool Near(float a, float b) => Math.Abs(a - b) <= MatchTolerance;

        static bool NearRelative(float a, float b) => Math.Abs(a - b) <= MatchTolerance * Math.Max(Math.Abs(a), Math.Abs(b));
    }
}
