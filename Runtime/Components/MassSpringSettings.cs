using SoftBodyDynamics.Solvers;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Per-instance tunables of a mass-spring body (tier 2): integrator, substeps, gravity, contacts, sleep and the
    /// NaN-guard limit. Units are documented on <see cref="MassSpringParameters"/>. The spring stiffness and damping
    /// are in the blob (they follow from the material at bake time). Change it at run time like any component.
    /// </summary>
    public struct MassSpringSettings : IComponentData
    {
        /// <summary>The solver parameters of this body.</summary>
        public MassSpringParameters Value;
    }
}
