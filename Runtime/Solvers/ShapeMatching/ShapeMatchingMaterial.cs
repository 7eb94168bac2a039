namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The material-like subset of <see cref="ShapeMatchingParameters"/> a preset sets, and the three
    /// presets the authoring component offers. Frequency f and damping ratio ζ are times, so a preset is the
    /// same material at any frame rate and substep count. The values are those of the 0.2 presets (α per
    /// step) at the 1/60 s fixed step and 4 substeps they were tuned at (<see cref="LegacyStiffness"/>):
    /// <list type="bullet">
    /// <item>Jelly: linear, 7.7 Hz, ζ 0.13, β 0.6, elastic, μ 0.4, e 0.2. Soft enough to sag and wobble
    /// visibly (shear and stretch, carried by β, at 7.7·√0.4 ≈ 4.9 Hz); a wobble loses e^{−2π·0.13} ≈ 44 % of its
    /// amplitude per period and is gone within about a second; moderate friction and a little bounce.</item>
    /// <item>Rubber: linear, 18.5 Hz, ζ 0.25, β 0.3, elastic, μ 1.0, e 0.7. Recovers its shape within a few
    /// frames; firm; rubber grips (μ about 1 on most surfaces) and bounces.</item>
    /// <item>Clay: linear, 13.8 Hz, ζ 0.22, β 0.8, plasticity yield 0.05, creep 10/s, maximum 0.6, μ 0.9, e 0.
    /// A high β lets the linear transform carry the dent; beyond 5 % strain the rest shape creeps towards the
    /// deformed one within about 0.1 s, up to 60 % strain; no restitution makes it land dead.</item>
    /// </list>
    /// </summary>
    public struct ShapeMatchingMaterial
    {
        public ShapeMatchingMode Mode;
        /// <summary>Natural frequency f (Hz).</summary>
        public float Frequency;
        /// <summary>Damping ratio ζ.</summary>
        public float DampingRatio;
        /// <summary>β ∈ [0, 1].</summary>
        public float Beta;
        public PlasticityParameters Plasticity;
        /// <summary>Coulomb friction μ.</summary>
        public float Friction;
        /// <summary>Restitution e ∈ [0, 1].</summary>
        public float Restitution;

        public static ShapeMatchingMaterial Jelly => new ShapeMatchingMaterial
        {
            Mode = ShapeMatchingMode.Linear, Frequency = 7.7f, DampingRatio = 0.13f, Beta = 0.6f,
            Plasticity = PlasticityParameters.None, Friction = 0.4f, Restitution = 0.2f,
        };

        public static ShapeMatchingMaterial Rubber => new ShapeMatchingMaterial
        {
            Mode = ShapeMatchingMode.Linear, Frequency = 18.5f, DampingRatio = 0.25f, Beta = 0.3f,
            Plasticity = PlasticityParameters.None, Friction = 1f, Restitution = 0.7f,
        };

        public static ShapeMatchingMaterial Clay => new ShapeMatchingMaterial
        {
            Mode = ShapeMatchingMode.Linear, Frequency = 13.8f, DampingRatio = 0.22f, Beta = 0.8f,
            Plasticity = new PlasticityParameters { Yield = 0.05f, Creep = 10f, MaxDeformation = 0.6f },
            Friction = 0.9f, Restitution = 0f,
        };

        /// <summary><paramref name="parameters"/> with this material's values.</summary>
        public ShapeMatchingParameters ApplyTo(ShapeMatchingParameters parameters)
        {
            parameters.Mode = Mode;
            parameters.Frequency = Frequency;
            parameters.DampingRatio = DampingRatio;
            parameters.Beta = Beta;
            parameters.Plasticity = Plasticity;
            parameters.Body.Friction = Friction;
            parameters.Body.Restitution = Restitution;
            return parameters;
        }
    }
}
