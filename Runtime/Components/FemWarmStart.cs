using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Velocity change of one node in the last implicit substep of a finite-element body (tier 3, runtime state), one element
    /// per node: the first guess of the next conjugate-gradient solve when the shape has a rest factor
    /// (<see cref="SoftBodyDynamics.Solvers.FemState.WarmStart"/>). Sized and cleared by <see cref="FemSimulationSystem"/>.
    /// </summary>
    [InternalBufferCapacity(0)]
    public struct FemWarmStart : IBufferElementData
    {
        /// <summary>Δv of the node (m/s).</summary>
        public float3 Value;
    }
}
