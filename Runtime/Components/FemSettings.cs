using SoftBodyDynamics.Solvers;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Per-instance tunables of a finite-element body (tier 2): constitutive model, integrator, substeps, gravity,
    /// contacts, sleep and the NaN-guard limit. Units are documented on <see cref="FemParameters"/>. The material
    /// constants (μ, λ, ζ) are in the blob. Change it at run time like any component.
    /// </summary>
    public struct FemSettings : IComponentData
    {
        /// <summary>The solver parameters of this body.</summary>
        public FemParameters Value;
    }
}
