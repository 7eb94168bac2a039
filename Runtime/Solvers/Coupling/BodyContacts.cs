using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Tunables of <see cref="BodyContacts"/>.</summary>
    public struct BodyContactSettings
    {
        /// <summary>Gauss–Seidel sweeps over the contacting pairs (1 … <see cref="MaxIterations"/>); more settle deep piles.</summary>
        public int Iterations;
        /// <summary>Coulomb friction coefficient between bodies (0 … 1): the tangential impulse is at most μ × the normal impulse.</summary>
        public float Friction;

        /// <summary>Most sweeps a resolve runs.</summary>
        public const int MaxIterations = 64;

        /// <summary>4 sweeps, μ = 0.5.</summary>
        public static BodyContactSettings Default => new BodyContactSettings { Iterations = 4, Friction = 0.5f };

        /// <summary>Iterations clamped to 1 … <see cref="MaxIterations"/>, friction to [0, 1]; NaN gives the default.</summary>
        public BodyContactSettings Sanitized()
        {
            BodyContactSettings d = Default;
            return new BodyContactSettings
            {
                Iterations = Iterations < 1 ? d.Iterations : math.min(Iterations, MaxIterations),
                Friction = math.isnan(Friction) ? d.Friction : math.saturate(Friction),
            };
        }
    }

    /// <summary>The particles of several bodies gathered in world space, each with the body it belongs to. Views only.</summary>
    public readonly ref struct BodyContactParticles
    {
        /// <summary>World positions (m), moved apart in place.</summary>
        public readonly Span<float3> Positions;
        /// <summary>Velocities (m/s), changed in place by the contact impulses.</summary>
        public readonly Span<float3> Velocities;
        /// <summary>Inverse masses (1/kg); 0 for a pinned particle, which the contacts do not move.</summary>
        public readonly ReadOnlySpan<float> InverseMasses;
        /// <summary>Contact radius of each particle (m, ≥ 0).</summary>
        public readonly ReadOnlySpan<float> Radii;
        /// <summary>The body each particle belongs to; particles of one body do not collide with each other.</summary>
        public readonly ReadOnlySpan<int> Bodies;

        public BodyContactParticles(Span<float3> positions, Span<float3> velocities, ReadOnlySpan<float> inverseMasses,
            ReadOnlySpan<float> radii, ReadOnlySpan<int> bodies)
        {
            Positions = positions;
            Velocities = velocities;
            InverseMasses = inverseMasses;
            Radii = radii;
            Bodies = bodies;
        }

        public int Count => Positions.Length;
    }

    /// <summary>What one <see cref="BodyContacts.Resolve"/> found.</summary>
    public struct BodyContactReport
    {
        /// <summary>Pairs of particles of different bodies closer than their radii' sum in the first sweep.</summary>
        public int Pairs;
        /// <summary>Deepest overlap (m) before the first sweep and after the last.</summary>
        public float MaxOverlapBefore, MaxOverlapAfter;
        /// <summary>The scratch was too short (or its bucket count not a power of two): nothing was resolved.</summary>
        public bool ScratchTooSmall;
    }

    /// <summary>
    /// Particles of different bodies kept apart: each pair closer than rᵢ + rⱼ is pushed apart along its line,
    /// Δxᵢ = wᵢ/(wᵢ + wⱼ)·(rᵢ + rⱼ − d)·n̂ and Δxⱼ the opposite share (Müller et al. 2007, position-based dynamics, eq. 9–10), the
    /// push given to the velocities too (Δv = Δx/h, as a substep's positions give its velocities), any approach left removed,
    /// J = −(vᵢ − vⱼ)·n̂/(wᵢ + wⱼ), and the sliding reduced by at most μ × the pair's normal impulse (Coulomb). Each push and
    /// impulse is a pair, so the bodies' joint centre of mass and momentum keep their values to round-off. Run it after every
    /// substep of the bodies (as a collider's contacts are), so that a body's solver spreads a push over the body before the
    /// next; pairs are found on a hashed grid of cell 2·max r and swept in slot order: the same input gives the same bits.
    /// </summary>
    public static class BodyContacts
    {
        /// <summary>Hash buckets for <paramref name="count"/> particles: the power of two ≥ 2·count (≥ 16).</summary>
        public static int TableSize(int count)
        {
            int size = 16;
            while (size < 2 * count && size < 1 << 30)
                size <<= 1;
            return size;
        }

        /// <summary>
        /// Resolves the contacts between bodies after a substep of <paramref name="h"/> (s; see the class comment). A particle with a non-finite position or radius takes
        /// no part. Scratch: <paramref name="bucketStarts"/> of <see cref="TableSize"/>(count) + 1 (any power of two + 1),
        /// <paramref name="sorted"/> and <paramref name="buckets"/> of count each; shorter scratch resolves nothing and says so
        /// (<see cref="BodyContactReport.ScratchTooSmall"/>).
        /// </summary>
        public static BodyContactReport Resolve(BodyContactParticles p, in BodyContactSettings settings, float h,
            Span<int> bucketStarts, Span<int> sorted, Span<int> buckets)
        {
            var report = new BodyContactReport();
            int n = p.Count;
            if (n < 2)
                return report;
            BodyContactSettings s = settings.Sanitized();
            int table = bucketStarts.Length - 1;
            if (table < 1 || (table & (table - 1)) != 0 || sorted.Length < n || buckets.Length < n)
            {
                report.ScratchTooSmall = true;
                return report;
            }
            float rMax = 0f;
            for (int i = 0; i < n; i++)
                if (Usable(p, i))
                    rMax = math.max(rMax, p.Radii[i]);
            if (!(rMax > 0f))
                return report;
            float inverseCell = 0.5f / rMax;
            float inverseH = h > 0f && math.isfinite(h) ? 1f / h : 0f;
            // Counting sort of the particles by bucket, stable in slot order: counts, inclusive sums, then filled backwards.
            bucketStarts.Clear();
            for (int i = 0; i < n; i++)
            {
                buckets[i] = Usable(p, i) ? Bucket(Cell(p.Positions[i], inverseCell), table) : -1;
                if (buckets[i] >= 0)
                    bucketStarts[buckets[i]]++;
            }
            for (int b = 1; b <= table; b++)
                bucketStarts[b] += bucketStarts[b - 1];
            for (int i = n - 1; i >= 0; i--)
                if (buckets[i] >= 0)
                    sorted[--bucketStarts[buckets[i]]] = i;
            Span<int> seen = stackalloc int[27];
            for (int sweep = 0; sweep <= s.Iterations; sweep++)
            {
                // The last pass only measures what the sweeps left.
                bool measure = sweep == s.Iterations;
                float deepest = 0f;
                int pairs = 0;
                for (int i = 0; i < n; i++)
                {
                    if (buckets[i] < 0)
                        continue;
                    // The grid holds the positions it was built from: a sweep moves particles by a small part of a cell.
                    int3 cell = Cell(p.Positions[i], inverseCell);
                    int distinct = 0;
                    for (int dz = -1; dz <= 1; dz++)
                    for (int dy = -1; dy <= 1; dy++)
                    for (int dx = -1; dx <= 1; dx++)
                    {
                        int b = Bucket(cell + new int3(dx, dy, dz), table);
                        if (Contains(seen.Slice(0, distinct), b))
                            continue;
                        seen[distinct++] = b;
                        for (int k = bucketStarts[b]; k < bucketStarts[b + 1]; k++)
                        {
                            int j = sorted[k];
                            if (j <= i || p.Bodies[j] == p.Bodies[i])
                                continue;
                            float overlap = measure
                                ? p.Radii[i] + p.Radii[j] - math.distance(p.Positions[i], p.Positions[j])
                                : Pair(p, i, j, s.Friction, inverseH);
                            if (overlap > 0f)
                            {
                                pairs++;
                                deepest = math.max(deepest, overlap);
                            }
                        }
                    }
                }
                if (sweep == 0)
                {
                    report.Pairs = pairs;
                    report.MaxOverlapBefore = deepest;
                }
                if (measure)
                    report.MaxOverlapAfter = deepest;
            }
            return report;
        }

        static bool Usable(BodyContactParticles p, int i) =>
            math.all(math.isfinite(p.Positions[i])) && math.isfinite(p.Radii[i]) && p.Radii[i] >= 0f;

        /// <summary>
        /// One pair: pushed apart, the push given to the velocities as Δx/h (so that a resting contact holds still, as a
        /// collider's does), any approach left removed and the sliding reduced; returns the overlap found (m, ≤ 0 if none).
        /// </summary>
        static float Pair(BodyContactParticles p, int i, int j, float friction, float inverseH)
        {
            float3 d = p.Positions[i] - p.Positions[j];
            float reach = p.Radii[i] + p.Radii[j];
            float d2 = math.lengthsq(d);
            if (!(d2 < reach * reach))
                return 0f;
            float wi = p.InverseMasses[i], wj = p.InverseMasses[j], w = wi + wj;
            if (!(w > 0f))
                return 0f;
            float distance = math.sqrt(d2);
            // Coincident particles part along the body order (any fixed direction keeps the bits).
            float3 n = distance > 1e-9f * reach ? d / distance : new float3(0f, p.Bodies[i] < p.Bodies[j] ? 1f : -1f, 0f);
            float overlap = reach - distance;
            // Normal impulse per unit of w: the push's, over h, then what still approaches.
            float jn = overlap / w * inverseH;
            p.Positions[i] += (wi * overlap / w) * n;
            p.Positions[j] -= (wj * overlap / w) * n;
            float3 relative = p.Velocities[i] - p.Velocities[j] + jn * w * n;
            float approach = math.dot(relative, n);
            if (approach < 0f)
                jn -= approach / w;
            float3 sliding = relative - math.dot(relative, n) * n;
            float slide = math.length(sliding);
            float3 impulse = jn * n;
            if (slide > 0f)
                impulse -= (math.min(slide / w, friction * jn) / slide) * sliding;
            p.Velocities[i] += wi * impulse;
            p.Velocities[j] -= wj * impulse;
            return overlap;
        }

        static bool Contains(ReadOnlySpan<int> values, int v)
        {
            for (int k = 0; k < values.Length; k++)
                if (values[k] == v)
                    return true;
            return false;
        }

        static int3 Cell(float3 x, float inverseCell)
        {
            float3 c = math.floor(x * inverseCell);
            return new int3((int)c.x, (int)c.y, (int)c.z);
        }

        /// <summary>Teschner et al. 2003's spatial hash of a cell into [0, table) (table a power of two).</summary>
        static int Bucket(int3 cell, int table) =>
            (int)(((uint)cell.x * 73856093u ^ (uint)cell.y * 19349663u ^ (uint)cell.z * 83492791u) & (uint)(table - 1));
    }
}
