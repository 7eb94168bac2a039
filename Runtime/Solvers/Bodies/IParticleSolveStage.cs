using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// What holds a particle body together: the "solve" of each substep of <see cref="ParticleBodyStep"/>. Shape
    /// matching (<see cref="ShapeMatchingSolveStage"/>) is one; mass-spring and finite-element stages plug in the same
    /// way. A struct, so the generic step is specialised for it (no virtual call in a Burst job); it holds pointers to
    /// its own data, because a struct that is not a ref struct cannot hold spans.
    /// </summary>
    public interface IParticleSolveStage
    {
        /// <summary>
        /// Adds the internal forces of one substep to the velocities, given the positions xᵢ at the substep's start:
        /// vᵢ += Δvᵢ. Internal forces change neither momentum nor angular momentum. <paramref name="lastSubstep"/>
        /// marks the substep where once-per-step work (plastic flow) happens. <paramref name="frame"/> is the rigid frame of
        /// the positions (mass, centre, inverse inertia), shared with the damping. May use <see cref="ParticleBody.Scratch"/>.
        /// </summary>
        void Solve(in ParticleBody body, in ParticleStepConstants constants, in RigidFrame frame, bool lastSubstep);

        /// <summary>The guard reset the particles to the rest shape at <paramref name="rotation"/>: reset what of the stage's state no longer fits.</summary>
        void OnReset(quaternion rotation);
    }
}
