using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Contacts of one substep, position-based (Müller et al. 2007; friction after Macklin et al. 2014,
    /// eq. 24): predicted positions are pushed out of every collider, the tangential part of the
    /// substep's motion is cancelled up to μ times the penetration depth, and the normal velocity of
    /// an approaching particle is set to −e times its pre-contact value.
    /// </summary>
    public static class ContactProjection
    {
        /// <summary>Distance off the surface, as a fraction of the particle radius, from which a particle counts as arriving.</summary>
        const float k_ArrivalFraction = 0.1f;

        /// <summary>
        /// The closest-point normal contradicts the swept face when their cosine is below −this: normals at right angles
        /// (a particle sliding over a box edge) are not a contradiction, whatever the sign round-off gives their dot product.
        /// </summary>
        public const float OppositeNormals = 1e-4f;

        /// <summary>What a substep's contacts need besides the particles and colliders.</summary>
        public struct Settings
        {
            /// <summary>Particle radius (m).</summary>
            public float Radius;
            /// <summary>Coulomb friction coefficient μ.</summary>
            public float Friction;
            /// <summary>Restitution e ∈ [0, 1].</summary>
            public float Restitution;
            /// <summary>Approach speed (m/s) below which an arriving particle does not bounce.</summary>
            public float BounceThreshold;
            /// <summary>
            /// Most of a particle's overlap at the start of the substep removed in one substep (m): a body that
            /// starts inside a collider leaves at MaxDepenetration / h. Overlap the substep's own motion created is
            /// always removed. Infinity = no cap.
            /// </summary>
            public float MaxDepenetration;
            /// <summary>World position of the particles' origin (m): colliders are in world space, particles relative to it.</summary>
            public float3 Origin;
            /// <summary>
            /// The particles are one body: while some particle starts a substep deeper than <see cref="MaxDepenetration"/> in a
            /// collider, the whole body leaves that collider along one direction (see <see cref="Project"/>) instead of each
            /// particle by its nearest face, which would tear the body around the collider. Off for fluids.
            /// </summary>
            public bool WholeBody;
            /// <summary>
            /// The contact normals passed in are the previous substep's (the step's first from <see cref="StartContacts"/>):
            /// a particle in contact then stays in contact (its normal kept, nothing pushed) while it is within
            /// <see cref="TouchingDistance"/> outside a collider whose normal there is within 60° of the old one, and the
            /// normals written are surface contacts only (none while the body leaves a collider it started in). A solver that
            /// holds contact particles on the surface (<see cref="FemImplicitEuler"/>) would otherwise see every other contact vanish.
            /// </summary>
            public bool KeepTouching;
        }

        /// <summary>
        /// Gap (m) within which a particle in contact stays in contact under <see cref="Settings.KeepTouching"/>: above the
        /// float32 resolution of positions 64 m from the origin (4 µm), below one substep's motion at 1 mm/s.
        /// </summary>
        public const float TouchingDistance = 1e-5f;

        /// <summary>Colliders that can have a shared leaving direction in one call; further ones push each particle on its own.</summary>
        public const int MaxSharedColliders = 32;

        /// <summary>
        /// Projects <paramref name="predicted"/> out of the colliders and adds each push to the velocity
        /// (Δv = Δx/h); a particle that arrives at a surface (from more than a tenth of its radius away) at
        /// v⁻ₙ = v·n &lt; −BounceThreshold leaves it at −e·v⁻ₙ. Of the overlap a particle already had at the
        /// start of the substep, at most <see cref="Settings.MaxDepenetration"/> is removed per substep, so a
        /// body spawned inside a collider is not shot out of it. With <see cref="Settings.WholeBody"/>, a collider in
        /// which some particle starts deeper than that gets one leaving direction d for the body — the collider's outward
        /// direction at the particles' centroid (<see cref="ParticleCollision.Outward"/>; planes excepted: they push every
        /// particle the same way) — and, this substep, every particle moves at least MaxDepenetration along d (the body
        /// leaves as a whole, undeformed, at the capped speed); a particle that is not deep is then pushed out as usual,
        /// but never against d (it passes on through, as the body does). Writes each particle's contact normal (zero when
        /// free) to <paramref name="contactNormals"/>. Returns the number of particles in contact.
        /// </summary>
        /// <param name="previous">Positions at the start of the substep (for the swept test, friction and the depenetration cap).</param>
        /// <param name="h">Substep (s).</param>
        public static int Project(ReadOnlySpan<float3> previous, Span<float3> predicted, Span<float3> velocities,
            Span<float3> contactNormals, ReadOnlySpan<ColliderShape> colliders, in Settings settings, float h)
        {
            int contacts = 0;
            float invH = 1f / h;
            float radius = settings.Radius;
            Span<float3> leaving = stackalloc float3[MaxSharedColliders];
            leaving = leaving.Slice(0, SharedColliders(colliders, settings));
            bool bodyLeaving = BodyLeaves(previous, colliders, settings, leaving);
            for (int i = 0; i < predicted.Length; i++)
            {
                float3 start = predicted[i];
                float3 x = start;
                float3 contactNormal = float3.zero;
                float3 previousNormal = settings.KeepTouching ? contactNormals[i] : float3.zero;
                bool surface = false; // pushed out of a surface (not only carried by the whole body's leave)
                for (int c = 0; c < colliders.Length; c++)
                {
                    ColliderShape collider = Local(colliders[c], settings);
                    float3 away = c < leaving.Length ? leaving[c] : float3.zero;
                    bool bodyLeaves = math.lengthsq(away) > 0f;
                    // Overlap at the start of the substep: known up front while the body leaves this collider, else found on a hit.
                    float startDepth = bodyLeaves ? StartDepth(collider, previous[i], radius) : -1f;
                    if (bodyLeaves)
                    {
                        // The whole body leaves along one direction: every particle moves at least MaxDepenetration along it.
                        x += math.max(0f, settings.MaxDepenetration - math.dot(x - previous[i], away)) * away;
                        contactNormal = away;
                        if (startDepth > settings.MaxDepenetration)
                            continue;
                    }
                    float3 n;
                    float depth;
                    // Pushed along the normal of the closest surface point, except when the swept test shows
                    // the particle came through a box face that the closest point contradicts: its centre
                    // ended inside the box (the nearest face may be the far one) or beyond a thin box
                    // (the closest point is on the far side). Then it leaves through the face it entered.
                    bool hit = ParticleCollision.Penetration(collider, x, radius, out n, out depth, out bool deep);
                    if (collider.Type == ColliderShapeType.Box
                        && ParticleCollision.Sweep(collider, previous[i], x, radius, out float3 entry, out float3 face)
                        && (!hit || deep || math.dot(n, face) < -OppositeNormals))
                    {
                        n = face;
                        depth = math.dot(entry - x, face);
                    }
                    else if (!hit)
                        continue;
                    // While the body leaves this collider, nothing pushes a particle back the way the body came.
                    if (bodyLeaves && math.dot(n, away) < 0f)
                        continue;
                    // Overlap carried over from the start of the substep leaves at a bounded speed.
                    if (startDepth < 0f)
                        startDepth = StartDepth(collider, previous[i], radius);
                    if (startDepth > settings.MaxDepenetration)
                        depth = math.min(depth, math.max(0f, depth - (startDepth - settings.MaxDepenetration)));
                    if (!(depth > 0f))
                        continue;
                    x += depth * n;
                    surface = true;
                    // Friction: cancel tangential motion of this substep, at most μ·depth.
                    float3 motion = x - previous[i];
                    float3 tangential = motion - math.dot(motion, n) * n;
                    float slide = math.length(tangential);
                    float limit = settings.Friction * depth;
                    if (slide > 0f)
                        x -= tangential * math.min(1f, limit / slide);
                    contactNormal = n;
                }
                if (math.lengthsq(contactNormal) == 0f && math.lengthsq(previousNormal) > 0f)
                {
                    contactNormal = Touching(colliders, settings, x, previousNormal);
                    contactNormals[i] = contactNormal;
                    if (math.lengthsq(contactNormal) > 0f)
                        contacts++;
                    continue;
                }
                // Under KeepTouching the buffer holds resting surface contacts only: none while the body leaves a collider it started in.
                contactNormals[i] = !settings.KeepTouching || (surface && !bodyLeaving) ? contactNormal : float3.zero;
                if (math.lengthsq(contactNormal) == 0f)
                    continue;
                contacts++;
                float approach = math.dot(velocities[i], contactNormal);
                float3 v = velocities[i] + (x - start) * invH;
                // Bounce only a particle that arrives: one that started the substep more than a tenth of its
                // radius off the surface. A resting particle the goal pull presses into the floor would
                // otherwise bounce every substep and never settle.
                bool arriving = math.dot(previous[i] - x, contactNormal) > k_ArrivalFraction * radius;
                if (arriving && approach < -settings.BounceThreshold)
                    v += (-settings.Restitution * approach - math.dot(v, contactNormal)) * contactNormal;
                velocities[i] = v;
                predicted[i] = x;
            }
            return contacts;
        }

        /// <summary>
        /// The contacts a step starts with under <see cref="Settings.KeepTouching"/> (so that they need not be kept between
        /// steps): each particle's normal of the first collider it overlaps or is within <see cref="TouchingDistance"/> of,
        /// zero for the others; all zero while a particle is deeper than <see cref="Settings.MaxDepenetration"/> in a collider
        /// (the body then leaves it as a whole, <see cref="Project"/>).
        /// </summary>
        public static void StartContacts(ReadOnlySpan<float3> positions, Span<float3> contactNormals, ReadOnlySpan<ColliderShape> colliders,
            in Settings settings)
        {
            Span<float3> leaving = stackalloc float3[MaxSharedColliders];
            if (BodyLeaves(positions, colliders, settings, leaving.Slice(0, SharedColliders(colliders, settings))))
            {
                contactNormals.Clear();
                return;
            }
            for (int i = 0; i < positions.Length; i++)
                contactNormals[i] = Touching(colliders, settings, positions[i], float3.zero);
        }

        /// <summary>Colliders with a shared leaving direction: at most <see cref="MaxSharedColliders"/>, none without <see cref="Settings.WholeBody"/>.</summary>
        static int SharedColliders(ReadOnlySpan<ColliderShape> colliders, in Settings settings) =>
            settings.WholeBody ? math.min(colliders.Length, MaxSharedColliders) : 0;

        /// <summary>
        /// The whole-body leaving directions of <see cref="LeavingDirections"/> into <paramref name="leaving"/> (one per shared
        /// collider, <see cref="SharedColliders"/>), and whether the body leaves any collider.
        /// </summary>
        static bool BodyLeaves(ReadOnlySpan<float3> previous, ReadOnlySpan<ColliderShape> colliders, in Settings settings, Span<float3> leaving)
        {
            if (leaving.Length == 0)
                return false;
            LeavingDirections(previous, colliders, settings, leaving);
            for (int c = 0; c < leaving.Length; c++)
                if (math.lengthsq(leaving[c]) > 0f)
                    return true;
            return false;
        }

        /// <summary>The collider in the particles' frame (relative to <see cref="Settings.Origin"/>).</summary>
        static ColliderShape Local(in ColliderShape collider, in Settings settings) =>
            math.any(settings.Origin != float3.zero) ? collider.Translated(-settings.Origin) : collider;

        /// <summary>
        /// The normal of the first collider that a particle at <paramref name="x"/> overlaps or is within <see cref="TouchingDistance"/>
        /// of, and whose normal there is within 60° of <paramref name="previousNormal"/> (any, when that is zero); zero when none.
        /// </summary>
        static float3 Touching(ReadOnlySpan<ColliderShape> colliders, in Settings settings, float3 x, float3 previousNormal)
        {
            bool anyDirection = math.lengthsq(previousNormal) == 0f;
            for (int c = 0; c < colliders.Length; c++)
            {
                if (ParticleCollision.Penetration(Local(colliders[c], settings), x, settings.Radius + TouchingDistance, out float3 n, out _)
                    && (anyDirection || math.dot(n, previousNormal) > 0.5f))
                    return n;
            }
            return float3.zero;
        }

        /// <summary>How deep (m) a particle at <paramref name="x"/> overlaps the collider; 0 when it does not.</summary>
        static float StartDepth(in ColliderShape collider, float3 x, float radius) =>
            ParticleCollision.Penetration(collider, x, radius, out _, out float depth) ? depth : 0f;

        /// <summary>
        /// For each collider (up to <paramref name="leaving"/>.Length): zero, or, when some particle starts deeper in it than
        /// the depenetration cap, the collider's outward direction at the particles' centroid.
        /// </summary>
        static void LeavingDirections(ReadOnlySpan<float3> previous, ReadOnlySpan<ColliderShape> colliders, in Settings settings, Span<float3> leaving)
        {
            leaving.Clear();
            if (!(settings.MaxDepenetration < float.PositiveInfinity) || previous.Length == 0)
                return;
            float3 centroid = float3.zero;
            bool centroidKnown = false;
            for (int c = 0; c < leaving.Length; c++)
            {
                ColliderShape collider = Local(colliders[c], settings);
                // A plane pushes every particle the same way: it cannot tear a body.
                if (collider.Type == ColliderShapeType.Plane)
                    continue;
                bool deep = false;
                for (int i = 0; i < previous.Length && !deep; i++)
                    deep = StartDepth(collider, previous[i], settings.Radius) > settings.MaxDepenetration;
                if (!deep)
                    continue;
                if (!centroidKnown)
                {
                    centroid = Centroid(previous);
                    centroidKnown = true;
                }
                leaving[c] = ParticleCollision.Outward(collider, centroid);
            }
        }

        /// <summary>Mean of the positions, summed in double.</summary>
        static float3 Centroid(ReadOnlySpan<float3> x)
        {
            double cx = 0.0, cy = 0.0, cz = 0.0;
            for (int i = 0; i < x.Length; i++)
            {
                cx += x[i].x;
                cy += x[i].y;
                cz += x[i].z;
            }
            return new float3((float)(cx / x.Length), (float)(cy / x.Length), (float)(cz / x.Length));
        }
    }
}
