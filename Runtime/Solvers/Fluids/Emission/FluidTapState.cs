namespace SoftBodyDynamics.Solvers
{
    /// <summary>The running state of one tap (a component in ECS).</summary>
    public struct FluidTapState
    {
        /// <summary>Time since the tap was created (s), start delay included.</summary>
        public double Time;
        /// <summary>Particles of the steady flow that are due but not yet placed (fractional).</summary>
        public double Owed;
        /// <summary>Burst particles that are due but not yet placed.</summary>
        public long BurstOwed;
        /// <summary>State of the tap's random numbers (xorshift32; 0 = not yet seeded).</summary>
        public uint Random;
        /// <summary>Particles this tap has spawned.</summary>
        public long Spawned;
        /// <summary>Particles this tap shed because they stayed blocked longer than a second of flow.</summary>
        public long Dropped;
    }

    /// <summary>What one <see cref="FluidTapEmitter.Emit"/> did.</summary>
    public struct FluidEmitReport
    {
        /// <summary>Particles placed.</summary>
        public int Spawned;
        /// <summary>Particles due but held back (overlap with existing particles, the domain, the budget or the tap's maximum alive); they wait for later steps.</summary>
        public int HeldBack;
        /// <summary>Candidate spawn points rejected because a particle was closer than <see cref="FluidTapEmitter.MinSpawnDistance"/> spacings.</summary>
        public int Blocked;
        /// <summary>True when the fluid's budget (or the capacity) stopped the tap this step.</summary>
        public bool OverBudget;
        /// <summary>Particles shed this step (held back for longer than a second of flow).</summary>
        public int Dropped;
    }
}
