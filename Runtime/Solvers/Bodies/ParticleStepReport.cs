namespace SoftBodyDynamics.Solvers
{
    /// <summary>What one call of <see cref="ParticleBodyStep.Step{TStage}"/> did, whatever the solve stage.</summary>
    public struct ParticleStepReport
    {
        /// <summary>False when the body slept through the step.</summary>
        public bool Stepped;
        /// <summary>The body woke at the start of this step (force change, velocity, or a collider overlapping it).</summary>
        public bool WokeUp;
        /// <summary>The body fell asleep at the end of this step.</summary>
        public bool FellAsleep;
        /// <summary>The guard found a non-finite or absurd state and reset the body to its rest shape.</summary>
        public bool Reset;
        /// <summary>Index of the first bad particle when <see cref="Reset"/> is true, else −1.</summary>
        public int BadParticle;
        /// <summary>Particle–collider contacts in the last substep.</summary>
        public int Contacts;
        /// <summary>Substeps the step took.</summary>
        public int Substeps;
        /// <summary>
        /// The parameters held an invalid or out-of-range value, which the step replaced (NaN, negative or otherwise invalid →
        /// the default; beyond a limit → the limit). Bake-time validation reports the same values as errors.
        /// </summary>
        public bool ParametersReplaced;
    }
}
