using SoftBodyDynamics.Solvers;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// The finite-element specifics of a body's last step (tier 3): the integrator that ran, whether it fell back from an
    /// unsupported model/integrator pair, the conjugate-gradient iterations and convergence, and the inverted elements.
    /// The shared part of the report is in <see cref="ParticleBodyState.LastReport"/>.
    /// </summary>
    public struct FemDiagnostics : IComponentData
    {
        /// <summary>The full report of the last <see cref="FemSolver.Step"/>.</summary>
        public FemStepReport LastReport;
    }
}
