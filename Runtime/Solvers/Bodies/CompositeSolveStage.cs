using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Two solve stages on the same particles, one after the other in each substep (a hybrid body: shape matching plus
    /// springs). <see cref="First"/> adds its velocity change, then <see cref="Second"/> adds its own from the same
    /// positions; a reset reaches both. Each stage must keep what it needs across substeps in its own memory (both
    /// may use <see cref="ParticleBody.Scratch"/> within a call). A struct, so the step stays specialised (no virtual call).
    /// </summary>
    public struct CompositeSolveStage<TFirst, TSecond> : IParticleSolveStage
        where TFirst : struct, IParticleSolveStage
        where TSecond : struct, IParticleSolveStage
    {
        /// <summary>The stage that runs first.</summary>
        public TFirst First;
        /// <summary>The stage that runs second.</summary>
        public TSecond Second;

        public CompositeSolveStage(TFirst first, TSecond second)
        {
            First = first;
            Second = second;
        }

        /// <inheritdoc/>
        public void Solve(in ParticleBody body, in ParticleStepConstants constants, in RigidFrame frame, bool lastSubstep)
        {
            First.Solve(body, constants, frame, lastSubstep);
            Second.Solve(body, constants, frame, lastSubstep);
        }

        /// <inheritdoc/>
        public void OnReset(quaternion rotation)
        {
            First.OnReset(rotation);
            Second.OnReset(rotation);
        }
    }
}
