using SoftBodyDynamics.Solvers;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Per-instance tunables of a soft body (tier 2): frequency, damping ratio, gravity, substeps, contacts,
    /// plasticity, sleep and the NaN-guard limit. Units are documented on <see cref="ShapeMatchingParameters"/>.
    /// Change it at run time like any component; the next step uses the new values.
    /// </summary>
    public struct ShapeMatchingSettings : IComponentData
    {
        /// <summary>The shape-matching parameters of this body.</summary>
        public ShapeMatchingParameters Value;
    }
}
