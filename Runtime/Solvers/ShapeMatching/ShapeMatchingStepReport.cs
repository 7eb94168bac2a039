namespace SoftBodyDynamics.Solvers
{
    /// <summary>What one call of <see cref="ShapeMatchingSolver.Step"/> did.</summary>
    public struct ShapeMatchingStepReport
    {
        /// <summary>False when the body slept through the step.</summary>
        public bool Stepped;
        /// <summary>The body woke at the start of this step (force change, velocity, or a collider overlapping it).</summary>
        public bool WokeUp;
        /// <summary>The body fell asleep at the end of this step.</summary>
        public bool FellAsleep;
        /// <summary>The NaN guard found a non-finite or absurd state and reset the body to its rest shape.</summary>
        public bool Reset;
        /// <summary>Index of the first bad particle when <see cref="Reset"/> is true, else −1.</summary>
        public int BadParticle;
        /// <summary>Cluster solves of the last substep that used a fallback (rigid for linear, linear for quadratic).</summary>
        public int Fallbacks;
        /// <summary>Most rotation-extraction iterations any cluster needed during the step.</summary>
        public int MaxRotationIterations;
        /// <summary>Particle–collider contacts in the last substep.</summary>
        public int Contacts;
        /// <summary>Clusters whose rest shape flowed plastically during the step.</summary>
        public int PlasticUpdates;
        /// <summary>Substeps the step took (at least the requested count; more where the frequency needed them).</summary>
        public int Substeps;
        /// <summary>
        /// Plasticity was asked for in quadratic mode, but the state has no per-instance quadratic inverses to
        /// rewrite, so the rest shape did not flow (allocate <see cref="ShapeMatchingState.QuadraticInverse"/>).
        /// </summary>
        public bool PlasticityUnavailable;
        /// <summary>See <see cref="ParticleStepReport.ParametersReplaced"/>.</summary>
        public bool ParametersReplaced;

        /// <summary>The part every particle-body method reports (<see cref="ParticleStepReport"/>).</summary>
        public ParticleStepReport Step => new ParticleStepReport
        {
            Stepped = Stepped, WokeUp = WokeUp, FellAsleep = FellAsleep, Reset = Reset, BadParticle = BadParticle,
            Contacts = Contacts, Substeps = Substeps, ParametersReplaced = ParametersReplaced,
        };
    }
}
