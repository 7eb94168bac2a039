namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The material-like subset of <see cref="ShapeMatchingParameters"/> a preset sets, and the three
    /// presets the authoring component offers. Why these numbers (α is the fraction of the way to the goal
    /// shape covered per step, substep-independent; β blends the linear transform into the rotation;
    /// damping decays only the non-rigid velocity):
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
    public struct ShapeMatchingMaterial
    {
        public ShapeMatchingMode Mode;
        /// <summary>Stiffness α ∈ [0, 1].</summary>
        public float Stiffness;
        /// <summary>β ∈ [0, 1].</summary>
        public float Beta;
        /// <summary>Damping (1/s).</summary>
        public float Damping;
        public PlasticityParameters Plasticity;
        /// <summary>Coulomb friction μ.</summary>
        public float Friction;
        /// <summary>Restitution e ∈ [0, 1].</summary>
        public float Restitution;

        public static ShapeMatchingMaterial Jelly => new ShapeMatchingMaterial
        {
            Mode = ShapeMatchingMode.Linear, Stiffness = 0.15f, Beta = 0.6f, Damping = 3f,
            Plasticity = PlasticityParameters.None, Friction = 0.4f, Restitution = 0.2f,
        };

        public static ShapeMatchingMaterial Rubber => new ShapeMatchingMaterial
        {
            Mode = ShapeMatchingMode.Linear, Stiffness = 0.6f, Beta = 0.3f, Damping = 4f,
            Plasticity = PlasticityParameters.None, Friction = 1f, Restitution = 0.7f,
        };

        public static ShapeMatchingMaterial Clay => new ShapeMatchingMaterial
        {
            Mode = ShapeMatchingMode.Linear, Stiffness = 0.4f, Beta = 0.8f, Damping = 8f,
            Plasticity = new PlasticityParameters { Yield = 0.05f, Creep = 10f, MaxDeformation = 0.6f },
            Friction = 0.9f, Restitution = 0f,
        };

        /// <summary><paramref name="parameters"/> with this material's values.</summary>
        public ShapeMatchingParameters ApplyTo(ShapeMatchingParameters parameters)
        {
            parameters.Mode = Mode;
            parameters.Stiffness = Stiffness;
            parameters.Beta = Beta;
            parameters.Damping = Damping;
            parameters.Plasticity = Plasticity;
            parameters.Friction = Friction;
            parameters.Restitution = Restitution;
            return parameters;
        }
    }
}
