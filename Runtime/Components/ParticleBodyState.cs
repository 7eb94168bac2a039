using SoftBodyDynamics.Solvers;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Runtime bookkeeping of every particle body, whatever its method (tier 3): placement, sleep, NaN-guard count and the
    /// last step's report. A method's own report is beside it (<see cref="ShapeMatchingDiagnostics"/>,
    /// <see cref="FemDiagnostics"/>).
    /// </summary>
    public struct ParticleBodyState : IComponentData
    {
        /// <summary>Centre of mass (m, world) and best-fit rotation after the last good step; sleep state; reset count.</summary>
        public ParticleBodyStatus Status;
        /// <summary>What the last step did (stepped, slept, reset by the NaN guard and at which particle, contacts, substeps).</summary>
        public ParticleStepReport LastReport;

        /// <summary>A body not stepped yet.</summary>
        public static ParticleBodyState Unstepped => new ParticleBodyState { LastReport = new ParticleStepReport { BadParticle = -1 } };
    }
}
