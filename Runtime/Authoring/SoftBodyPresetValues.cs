using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>The material values a <see cref="SoftBodyPreset"/> sets.</summary>
    public struct SoftBodyPresetValues
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
    }
}
