using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// World-level settings of every particle body and fluid (a singleton; optional). When it exists, every body and fluid
    /// falls with <see cref="Gravity"/> instead of its own (e.g.
    /// <see cref="SoftBodyDynamics.Solvers.ParticleBodySettings.Acceleration"/>,
    /// <see cref="SoftBodyDynamics.Solvers.FluidParameters.Gravity"/>), and every body and fluid takes at least
    /// <see cref="MinSubsteps"/> substeps per fixed step (a fluid more when its CFL limit asks). Without it each uses its own values.
    /// Add it with <c>ParticleWorldAuthoring</c> in a SubScene, or from code.
    /// </summary>
    public struct ParticleWorldSettings : IComponentData
    {
        /// <summary>Acceleration of gravity for every particle body and fluid (m/s²).</summary>
        public float3 Gravity;
        /// <summary>Fewest substeps per fixed step for every body and fluid (1–64); a body's or fluid's own minimum applies if larger.</summary>
        public int MinSubsteps;

        /// <summary>Earth gravity, one substep minimum.</summary>
        public static ParticleWorldSettings Default => new ParticleWorldSettings { Gravity = new float3(0f, -9.81f, 0f), MinSubsteps = 1 };

        /// <summary>A particle body's shared settings as this world steps it, whatever its method: the world's gravity and at least its substeps.</summary>
        public SoftBodyDynamics.Solvers.ParticleBodySettings Apply(SoftBodyDynamics.Solvers.ParticleBodySettings body)
        {
            body.Acceleration = Gravity;
            body.Substeps = math.max(body.Substeps, MinSubsteps);
            return body;
        }

        /// <summary>A fluid as this world steps it: the world's gravity and at least its substeps (more when the CFL limit asks).</summary>
        public SoftBodyDynamics.Solvers.FluidParameters Apply(SoftBodyDynamics.Solvers.FluidParameters fluid)
        {
            fluid.Gravity = Gravity;
            fluid.MinSubsteps = math.max(fluid.MinSubsteps, MinSubsteps);
            return fluid;
        }
    }
}
