namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Problems of the settings every particle body shares (<see cref="ParticleBodySettings"/>: contact, guard, sleep), found by <c>ParameterChecks</c> for every method's validator.
    /// The numbers are unique across domains and stable (they may be stored); new codes take new numbers. An
    /// <see cref="IssueCode"/> carries any domain's code.
    /// </summary>
    public enum ParticleBodyIssueCode
    {
        /// <summary>A parameter is NaN or infinite.</summary>
        ParameterNotFinite = 60,
        /// <summary>Particle radius not positive, or implausibly large.</summary>
        ParticleRadiusInvalid = 67,
        /// <summary>Friction below 0.</summary>
        FrictionNegative = 68,
        /// <summary>Restitution outside [0, 1].</summary>
        RestitutionOutOfRange = 69,
        /// <summary>Sleep speed below 0.</summary>
        SleepSpeedNegative = 71,
        /// <summary>Sleep delay below 0.</summary>
        SleepDelayNegative = 72,
        /// <summary>Maximum speed not positive.</summary>
        MaxSpeedNotPositive = 73,
        /// <summary>Rotation iterations below 1.</summary>
        RotationIterationsInvalid = 74,
        /// <summary>Maximum depenetration speed not positive.</summary>
        MaxDepenetrationSpeedNotPositive = 77,
    }
}
