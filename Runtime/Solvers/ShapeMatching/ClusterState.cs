using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Runtime state of one cluster (an element of a dynamic buffer in ECS).</summary>
    public struct ClusterState
    {
        /// <summary>Rotation of the cluster from its rest pose; warm start of the next extraction.</summary>
        public quaternion Rotation;
        /// <summary>
        /// Plastic deformation Sₚ (Müller et al. 2005, §4.5): the rest offsets are Sₚ qᵢ. Symmetric,
        /// det = 1. Identity while the body has never yielded.
        /// </summary>
        public float3x3 PlasticDeformation;
        /// <summary>Rest data in use: the model's, with A_qq⁻¹ = Sₚ⁻ᵀ A_qq⁰⁻¹ Sₚ⁻¹ after plastic flow.</summary>
        public ClusterRestData Rest;
    }
}
