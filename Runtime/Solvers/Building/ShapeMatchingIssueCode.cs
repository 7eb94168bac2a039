namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Problems of shape-matching parameters (<see cref="ShapeMatchingParameterValidation"/>).
    /// The numbers are unique across domains and stable (they may be stored); new codes take new numbers. An
    /// <see cref="IssueCode"/> carries any domain's code.
    /// </summary>
    public enum ShapeMatchingIssueCode
    {
        /// <summary>The shape-matching mode is not one of the defined values.</summary>
        ModeInvalid = 61,
        /// <summary>Frequency below 0 Hz or above <see cref="ShapeMatchingParameters.MaxFrequency"/>.</summary>
        FrequencyOutOfRange = 62,
        /// <summary>Warning: frequency 0 Hz, so the body will not hold its shape.</summary>
        FrequencyZero = 63,
        /// <summary>β outside [0, 1].</summary>
        BetaOutOfRange = 64,
        /// <summary>Damping ratio below 0 or above <see cref="ShapeMatchingParameters.MaxDampingRatio"/>.</summary>
        DampingRatioOutOfRange = 65,
        /// <summary>Substeps outside 1..64.</summary>
        SubstepsOutOfRange = 66,
        /// <summary>A plasticity field (yield, creep, maximum deformation) below 0.</summary>
        PlasticityNegative = 70,
        /// <summary>Warning: β above <see cref="ShapeMatchingParameters.MaxBeta"/> acts as <see cref="ShapeMatchingParameters.MaxBeta"/>.</summary>
        BetaLimited = 75,
        /// <summary>Maximum substep phase not positive.</summary>
        MaxSubstepPhaseNotPositive = 76,
        /// <summary>Warning: plasticity is set but the mode is Rigid, whose goals cannot hold a deformed rest shape: it has no effect.</summary>
        PlasticityIgnoredInRigidMode = 78,
    }
}
