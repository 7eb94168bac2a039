namespace SoftBodyDynamics.Solvers
{
    /// <summary>What one fluid step did and what it found out of bounds (reported, never silent).</summary>
    public struct FluidStepReport
    {
        /// <summary>Substeps the step ran.</summary>
        public int Substeps;
        /// <summary>Substeps the CFL limit asked for; above <see cref="Substeps"/> when the cap <see cref="FluidParameters.MaxSubsteps"/> held it back.</summary>
        public int SubstepsWanted;
        /// <summary>Time simulated (s): the step's dt, or Substeps / SubstepsWanted of it when the cap held it back (slow motion).</summary>
        public float SimulatedTime;
        /// <summary>Particle-substeps in which a speed above <see cref="FluidParameters.MaxSpeed"/> was slowed to it.</summary>
        public int SpeedClamped;
        /// <summary>Particle-substeps with ρ/ρ₀ above <see cref="FluidParameters.MaxDensityRatio"/>.</summary>
        public int OverCompressed;
        /// <summary>Particle-substeps that had more than <see cref="FluidScratch.MaxNeighbours"/> neighbours (the extra ones were ignored).</summary>
        public int NeighbourOverflow;
        /// <summary>Largest ρ/ρ₀ seen in the step.</summary>
        public float MaxDensityRatio;
        /// <summary>Particles removed this step because a drain or gameplay code marked them.</summary>
        public int Killed;
        /// <summary>Particles removed this step at the end of their lifetime.</summary>
        public int Expired;
        /// <summary>Particles removed this step because their position or velocity was not finite (NaN guard).</summary>
        public int Invalid;
        /// <summary>Particle–collider contacts in the last substep.</summary>
        public int Contacts;
        /// <summary>Live particles after the step.</summary>
        public int Count;
    }
}
