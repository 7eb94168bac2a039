using SoftBodyDynamics.Solvers;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// The shape-matching specifics of a body's last step (tier 3): cluster fallbacks, rotation iterations, plastic
    /// updates. The shared part of the report is in <see cref="ParticleBodyState.LastReport"/>.
    /// </summary>
    public struct ShapeMatchingDiagnostics : IComponentData
    {
        /// <summary>The full report of the last <see cref="ShapeMatchingSolver.Step"/>.</summary>
        public ShapeMatchingStepReport LastReport;

        /// <summary>A body not stepped yet.</summary>
        public static ShapeMatchingDiagnostics Unstepped => new ShapeMatchingDiagnostics { LastReport = new ShapeMatchingStepReport { BadParticle = -1 } };
    }
}
