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
    /// Add it with <c>SoftBodyWorldAuthoring</c> in a SubScene, or from code.
    /// </summary>
    public struct SoftBodyWorldSettings : IComponentData
    {
        /// <summary>Acceleration of gravity for every particle body and fluid (m/s²).</summary>
        public float3 Gravity;
        /// <summary>Fewest substeps per fixed step for every body and fluid (1–64); a body's or fluid's own minimum applies if larger.</summary>
        public int MinSubsteps;

        /// <summary>Earth gravity, one substep minimum.</summary>
        public static SoftBodyWorldSettings Default => new SoftBodyWorldSettings { Gravity = new float3(0f, -9.81f, 0f), MinSubsteps = 1 };

        /// <summary><paramref name="body"/> as this world steps it: the world's gravity and at least its substeps.</summary>
        public SoftBodyDynamics.Solvers.ShapeMatchingParameters Apply(SoftBodyDynamics.Solvers.ShapeMatchingParameters body)
        {
            body.Body = body.Body.InWorld(Gravity, MinSubsteps);
            return body;
        }

        /// <summary>A mass-spring body as this world steps it: the world's gravity and at least its substeps.</summary>
        public SoftBodyDynamics.Solvers.MassSpringParameters Apply(SoftBodyDynamics.Solvers.MassSpringParameters body)
        {
            body.Body = body.Body.InWorld(Gravity, MinSubsteps);
            return body;
        }

        /// <summary>A finite-element body as this world steps it: the world's gravity and at least its substeps.</summary>
        public SoftBodyDynamics.Solvers.FemParameters Apply(SoftBodyDynamics.Solvers.FemParameters body)
        {
            body.Body = body.Body.InWorld(Gravity, MinSubsteps);
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
