using System;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>A drain (kill volume): every particle whose centre is inside <see cref="Shape"/> is removed at the next step.</summary>
    public struct FluidDrain
    {
        /// <summary>The volume in world space (any collider shape: a plane drains the half-space behind it).</summary>
        public ColliderShape Shape;

        /// <summary>
        /// Marks (lifetime −1) every live particle inside any of <paramref name="drains"/>; the next step's sort removes
        /// them and counts them in <see cref="FluidStatus.Killed"/>. Returns how many it marked.
        /// </summary>
        public static int Apply(ReadOnlySpan<FluidDrain> drains, FluidParticles p, int count)
        {
            int marked = 0;
            for (int i = 0; i < count; i++)
            {
                if (p.Lifetimes[i] < 0f)
                    continue;
                for (int d = 0; d < drains.Length; d++)
                {
                    // Radius 0: "penetrates" means the centre is inside the solid.
                    if (ParticleCollision.Penetration(drains[d].Shape, p.Positions[i], 0f, out _, out _))
                    {
                        p.Lifetimes[i] = -1f;
                        marked++;
                        break;
                    }
                }
            }
            return marked;
        }
    }
}
