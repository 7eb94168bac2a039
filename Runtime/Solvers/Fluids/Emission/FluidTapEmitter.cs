using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Spawns a tap's particles into a fluid's arrays. Candidates are the points of a cubic lattice at the particle
    /// spacing inside the tap's shape (disc: one layer across the flow), jittered by at most
    /// <see cref="JitterFraction"/> spacings per axis, visited from a random start so no side is favoured. A
    /// candidate closer than <see cref="MinSpawnDistance"/> spacings to an existing particle (or outside the domain)
    /// is held back: an overlap would give SPH a huge pressure. Held-back particles wait for a later step, up to a
    /// second of flow; beyond that they are shed and counted. The lattice keeps particles of one call at least
    /// (1 − 2·jitter) spacings apart.
    /// </summary>
    public static class FluidTapEmitter
    {
        /// <summary>Closest a new particle may come to any particle, in spacings.</summary>
        public const float MinSpawnDistance = 0.9f;
        /// <summary>Largest jitter of a lattice point per axis, in spacings (keeps lattice neighbours ≥ 0.92 spacings apart).</summary>
        public const float JitterFraction = 0.04f;

        /// <summary>
        /// Advances the tap by <paramref name="dt"/> and places the particles now due (spawning convention: appended at
        /// slots [Count, Count + k), ages 0, ids from <see cref="FluidStatus.NextId"/>). Re-sorts the live particles first
        /// (so the overlap query sees the current positions); particles the sort removes are added to the status totals.
        /// <paramref name="budget"/> caps the fluid's particles (≤ capacity; 0 = capacity).
        /// </summary>
        public static FluidEmitReport Emit(in FluidTapSettings settings, ReadOnlySpan<FluidTapBurst> bursts, ref FluidTapState state,
            float dt, in FluidConstants c, int budget, FluidParticles p, FluidScratch s, ref FluidStatus status)
        {
            var report = new FluidEmitReport();
            if (!(dt >= 0f) || !math.isfinite(dt))
                return report;
            FluidTapSettings tap = settings.Sanitized();
            float dx = c.Parameters.ParticleSpacing;
            double t0 = state.Time, t1 = t0 + dt;
            state.Owed += FluidTapSchedule.SteadyDue(tap, dx, t1) - FluidTapSchedule.SteadyDue(tap, dx, t0);
            state.BurstOwed += FluidTapSchedule.BurstDue(tap, bursts, t1) - FluidTapSchedule.BurstDue(tap, bursts, t0);
            state.Time = t1;
            if (state.Random == 0)
                state.Random = tap.Seed != 0 ? tap.Seed : 0x9E3779B9u;
            long want = (long)Math.Floor(state.Owed) + state.BurstOwed;
            if (want <= 0)
                return report;

            int capacity = p.Capacity;
            int limit = budget > 0 ? Math.Min(budget, capacity) : capacity;
            if (tap.MaxAlive > 0)
                limit = Math.Min(limit, tap.MaxAlive);

            // Sort the live particles so the grid answers "is anyone near this point?" for their current positions.
            var counters = new FluidPassCounters();
            int live = FluidSolver.SortParticles(c, p, s, Math.Min(status.Count, capacity), false, ref counters);
            status.Count = live;
            status.Killed += counters.Killed;
            status.Expired += counters.Expired;
            status.Invalid += counters.Invalid;

            int3 extent = LatticeExtent(tap, dx);
            long candidates = (long)(2 * extent.x + 1) * (2 * extent.y + 1) * (2 * extent.z + 1);
            long startIndex = candidates > 1 ? Next(ref state.Random) % (uint)candidates : 0;
            float minDistance2 = MinSpawnDistance * dx * MinSpawnDistance * dx;
            float3 lo = c.Parameters.DomainMin + c.WallDistance, hi = c.Parameters.DomainMax - c.WallDistance;
            int placed = 0;
            for (long k = 0; k < candidates && placed < want; k++)
            {
                if (status.Count >= limit)
                {
                    report.OverBudget = budget > 0 && status.Count >= Math.Min(budget, capacity) || status.Count >= capacity;
                    break;
                }
                long index = (startIndex + k) % candidates;
                int3 cell = new int3(
                    (int)(index % (2 * extent.x + 1)) - extent.x,
                    (int)(index / (2 * extent.x + 1) % (2 * extent.y + 1)) - extent.y,
                    (int)(index / ((2 * extent.x + 1) * (2 * extent.y + 1))) - extent.z);
                float3 local = new float3(cell.x, cell.y, cell.z) * dx;
                if (!Inside(tap, local))
                    continue;
                float3 jitter = new float3(Signed(ref state.Random), Signed(ref state.Random), Signed(ref state.Random)) * (JitterFraction * dx);
                if (tap.Shape == FluidTapShape.Disc || tap.Shape == FluidTapShape.Point)
                    jitter.z = 0f;
                float3 x = tap.Position + math.rotate(tap.Rotation, local + jitter);
                if (math.any(x < lo) || math.any(x > hi) || Occupied(c, p, s, live, x, minDistance2))
                {
                    report.Blocked++;
                    continue;
                }
                int slot = status.Count;
                p.Positions[slot] = x;
                p.Velocities[slot] = math.rotate(tap.Rotation, Direction(tap, ref state.Random)) * (tap.Speed + tap.SpeedRandom * Signed(ref state.Random));
                p.Ages[slot] = 0f;
                p.Lifetimes[slot] = tap.Lifetime > 0f ? math.max(1e-3f, tap.Lifetime + tap.LifetimeRandom * Signed(ref state.Random)) : 0f;
                p.Attributes[slot] = tap.Attribute;
                p.Ids[slot] = status.NextId++;
                status.Count++;
                status.Spawned++;
                placed++;
            }
            // Bursts are paid first, then the steady flow.
            long fromBursts = Math.Min(placed, state.BurstOwed);
            state.BurstOwed -= fromBursts;
            state.Owed -= placed - fromBursts;
            state.Spawned += placed;
            // A blocked tap keeps at most one second of its flow (and one round of its bursts) waiting.
            double maxOwed = Math.Max(1.0, tap.ParticlesPerSecond(dx));
            long maxBurst = 0;
            for (int b = 0; b < bursts.Length; b++)
                maxBurst += Math.Max(0, bursts[b].Count);
            if (state.Owed > maxOwed)
            {
                report.Dropped += (int)Math.Floor(state.Owed - maxOwed);
                state.Owed -= Math.Floor(state.Owed - maxOwed);
            }
            if (state.BurstOwed > maxBurst)
            {
                report.Dropped += (int)(state.BurstOwed - maxBurst);
                state.BurstOwed = maxBurst;
            }
            state.Dropped += report.Dropped;
            report.Spawned = placed;
            report.HeldBack = (int)Math.Min(int.MaxValue, (long)Math.Floor(state.Owed) + state.BurstOwed);
            return report;
        }

        /// <summary>Lattice points (in spacings) the shape spans from its centre along each local axis.</summary>
        static int3 LatticeExtent(in FluidTapSettings tap, float dx)
        {
            switch (tap.Shape)
            {
                case FluidTapShape.Disc:
                {
                    int r = (int)math.floor(tap.Radius / dx);
                    return new int3(r, r, 0);
                }
                case FluidTapShape.Sphere:
                {
                    int r = (int)math.floor(tap.Radius / dx);
                    return new int3(r, r, r);
                }
                case FluidTapShape.Box:
                    return new int3((int)math.floor(tap.HalfExtents.x / dx), (int)math.floor(tap.HalfExtents.y / dx), (int)math.floor(tap.HalfExtents.z / dx));
                default:
                    return new int3(0, 0, 0);
            }
        }

        static bool Inside(in FluidTapSettings tap, float3 local)
        {
            switch (tap.Shape)
            {
                case FluidTapShape.Disc:
                case FluidTapShape.Sphere:
                    return math.lengthsq(local) <= tap.Radius * tap.Radius * (1f + 1e-5f);
                default:
                    return true;
            }
        }

        /// <summary>True when a live particle (sorted slots [0, live)) is closer than √<paramref name="minDistance2"/> to <paramref name="x"/>.</summary>
        static bool Occupied(in FluidConstants c, FluidParticles p, FluidScratch s, int live, float3 x, float minDistance2)
        {
            if (live == 0)
                return false;
            NeighbourRows rows = NeighbourRows.Find(c.Grid, s.CellStart, x);
            for (int r = 0; r < rows.Count; r++)
                for (int j = rows.Begin(r); j < rows.End(r); j++)
                {
                    float3 d = c.Offset(p.Positions[j], x);
                    if (math.lengthsq(d) < minDistance2)
                        return true;
                }
            return false;
        }

        /// <summary>A direction within the cone around +Z, uniform over the spherical cap.</summary>
        static float3 Direction(in FluidTapSettings tap, ref uint random)
        {
            if (tap.ConeAngle <= 0f)
                return new float3(0f, 0f, 1f);
            float cosMax = math.cos(tap.ConeAngle * (math.PI / 180f));
            float cosTheta = 1f - Unit(ref random) * (1f - cosMax);
            float sinTheta = math.sqrt(math.max(0f, 1f - cosTheta * cosTheta));
            float phi = 2f * math.PI * Unit(ref random);
            return new float3(sinTheta * math.cos(phi), sinTheta * math.sin(phi), cosTheta);
        }

        /// <summary>xorshift32 (Marsaglia 2003).</summary>
        static uint Next(ref uint x)
        {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            return x;
        }

        /// <summary>Uniform in [0, 1).</summary>
        static float Unit(ref uint x) => (Next(ref x) >> 8) * (1f / 16777216f);

        /// <summary>Uniform in [−1, 1).</summary>
        static float Signed(ref uint x) => 2f * Unit(ref x) - 1f;
    }
}
