using SoftBodyDynamics.Solvers;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>Runtime bookkeeping of a soft body (tier 3): placement, sleep, NaN-guard count and the last step's report.</summary>
    public struct SoftBodyState : IComponentData
    {
        /// <summary>Centre of mass (m, world) and best-fit rotation after the last good step; sleep state; reset count.</summary>
        public SoftBodyStatus Status;
        /// <summary>What the last simulation step did (stepped, slept, reset by the NaN guard and at which particle, contacts…).</summary>
        public ShapeMatchingStepReport LastReport;
    }
}
