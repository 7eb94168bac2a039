namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>A method body whose substeps solve a linear system iteratively: what the solves cost and how far they got, summed over every run of the body (not reset by <see cref="IMethodBody.Place"/>).</summary>
    public interface IIterativeMethodBody
    {
        /// <summary>Conjugate-gradient iterations of all implicit substeps so far.</summary>
        long CgIterations { get; }
        /// <summary>Implicit substeps so far.</summary>
        long ImplicitSubsteps { get; }
        /// <summary>The largest relative residual ‖b − A x‖/‖b‖ a solve ended at.</summary>
        double MaxCgResidual { get; }
    }
}
