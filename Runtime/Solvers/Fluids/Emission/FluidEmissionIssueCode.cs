namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Problems of fluid taps and drains (<see cref="FluidValidation"/>, the tap and drain bakers).
    /// The numbers are unique across domains and stable (they may be stored); new codes take new numbers. An
    /// <see cref="IssueCode"/> carries any domain's code.
    /// </summary>
    public enum FluidEmissionIssueCode
    {
        /// <summary>The tap's shape is not one of point, disc, sphere or box.</summary>
        TapShapeInvalid = 220,
        /// <summary>The tap's radius or half extents are negative or not finite (m).</summary>
        TapSizeInvalid = 221,
        /// <summary>The tap's rotation is not a finite non-zero quaternion (no flow direction).</summary>
        TapDirectionInvalid = 222,
        /// <summary>The cone angle is outside [0°, 180°).</summary>
        TapConeInvalid = 223,
        /// <summary>The speed or its random range is negative or not finite (m/s), or the range exceeds the speed.</summary>
        TapSpeedInvalid = 224,
        /// <summary>The rate (particles/s) or volume flow (L/s) is negative or not finite.</summary>
        TapRateInvalid = 225,
        /// <summary>The pulse period is negative or the duty cycle is outside (0, 1].</summary>
        TapPulseInvalid = 226,
        /// <summary>Duration, start delay or prewarm is negative or not finite (s).</summary>
        TapTimingInvalid = 227,
        /// <summary>A burst has a negative time or count, fewer than one cycle, or several cycles with no positive interval.</summary>
        TapBurstInvalid = 228,
        /// <summary>The lifetime or its random range is negative or not finite (s), or the range exceeds the lifetime.</summary>
        TapLifetimeInvalid = 229,
        /// <summary>The steady-state alive count (rate × lifetime, with bursts) exceeds the fluid's particle budget: the tap would stall at the budget.</summary>
        TapOverBudget = 230,
        /// <summary>Warning: the tap emits nothing (zero rate and no bursts).</summary>
        TapSilent = 231,
        /// <summary>The drain's shape is invalid (non-positive or non-finite size).</summary>
        DrainInvalid = 232,
    }
}
