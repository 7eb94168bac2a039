namespace SoftBodyDynamics.Solvers
{
    /// <summary>What one <see cref="FemSolver.Step"/> did: the shared step's report and the finite-element specifics.</summary>
    public struct FemStepReport
    {
        /// <summary>The shared particle step's report (stepped, woke, slept, reset, contacts, substeps).</summary>
        public ParticleStepReport Step;
        /// <summary>The integrator that ran (differs from the parameters' when the pair was unsupported).</summary>
        public FemIntegrator Integrator;
        /// <summary>The parameters asked for an unsupported model/integrator pair; <see cref="Integrator"/> ran instead.</summary>
        public bool IntegratorFallback;
        /// <summary>Most conjugate-gradient iterations any implicit substep took (summed over its Newton iterations).</summary>
        public int MaxCgIterations;
        /// <summary>Conjugate-gradient iterations of all implicit substeps of the step, summed.</summary>
        public int TotalCgIterations;
        /// <summary>Every implicit substep reached the CG tolerance (true when none ran).</summary>
        public bool CgConverged;
        /// <summary>The largest relative residual ‖b − A Δv‖/‖b‖ any implicit substep's CG solve ended at (0 when none ran).</summary>
        public float MaxCgResidual;
        /// <summary>Elements with det F ≤ 0 in the last substep (explicit and implicit only; counted before the update).</summary>
        public int InvertedElements;
    }
}
