using System;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Tracks particles through a frame when they come from somewhere else (one entity each) and the frame sorts,
    /// removes and adds particles. Before the frame, slot k (in gather order) gets the temporary id k and the status's
    /// next id becomes n, so particles the taps add get ids n, n + 1, …; after the frame, a slot's id below n names the
    /// gathered particle it holds (its entity), an id of n or more marks a new particle, and every slot gets its real id
    /// back. O(particles), no search.
    /// </summary>
    public static class FluidGatherIds
    {
        /// <summary>
        /// Call after packing <paramref name="gathered"/> particles (their real ids in <see cref="FluidParticles.Ids"/>):
        /// moves the real ids to <paramref name="realIds"/>, writes the temporary ids, and returns the real next id.
        /// The status count becomes <paramref name="gathered"/>; particles that disappeared since the last frame (destroyed
        /// by gameplay) are added to <see cref="FluidStatus.Killed"/> so the accounting identity still holds.
        /// </summary>
        public static int Begin(FluidParticles p, Span<int> realIds, int gathered, ref FluidStatus status)
        {
            for (int k = 0; k < gathered; k++)
            {
                realIds[k] = p.Ids[k];
                p.Ids[k] = k;
            }
            if (status.Count > gathered)
                status.Killed += status.Count - gathered;
            status.Count = gathered;
            int realNext = status.NextId;
            status.NextId = gathered;
            return realNext;
        }

        /// <summary>
        /// Call after the frame: for every live slot, <paramref name="gatherOfSlot"/> gets the gather index it holds (−1
        /// for a new particle) and <paramref name="survived"/>[gather index] = 1; real ids are restored (new particles get
        /// <paramref name="realNext"/> + their temporary offset) and the status's next id moves past them. Returns the
        /// number of new particles.
        /// </summary>
        public static int End(FluidParticles p, ReadOnlySpan<int> realIds, int gathered, int realNext, Span<int> gatherOfSlot,
            Span<byte> survived, ref FluidStatus status)
        {
            survived.Slice(0, gathered).Clear();
            int created = 0;
            for (int s = 0; s < status.Count; s++)
            {
                int g = p.Ids[s];
                if (g < gathered)
                {
                    gatherOfSlot[s] = g;
                    survived[g] = 1;
                    p.Ids[s] = realIds[g];
                }
                else
                {
                    gatherOfSlot[s] = -1;
                    p.Ids[s] = realNext + (g - gathered);
                    created++;
                }
            }
            status.NextId = realNext + (status.NextId - gathered);
            return created;
        }
    }
}
