using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Contacts of one substep, position-based (Müller et al. 2007; friction after Macklin et al. 2014,
    /// eq. 24): predicted positions are pushed out of every collider, the tangential part of the
    /// substep's motion is cancelled up to μ times the penetration depth, and the normal velocity of
    /// an approaching particle is set to −e times its pre-contact value when velocities are updated.
    /// </summary>
    public static class ContactProjection
    {
        /// <summary>
        /// Projects <paramref name="predicted"/> out of the colliders; writes each particle's contact
        /// normal (zero when free) to <paramref name="contactNormals"/>. Returns the number of contacts.
        /// </summary>
        public static int Project(ReadOnlySpan<float3> previous, Span<float3> predicted, Span<float3> contactNormals,
            ReadOnlySpan<ColliderShape> colliders, float radius, float friction)
        {
            int contacts = 0;
            for (int i = 0; i < predicted.Length; i++)
            {
                float3 x = predicted[i];
                float3 contactNormal = float3.zero;
                for (int c = 0; c < colliders.Length; c++)
                {
                    float3 n;
                    float depth;
                    if (!ParticleCollision.Penetration(colliders[c], x, radius, out n, out depth))
                    {
                        if (!ParticleCollision.Sweep(colliders[c], previous[i], x, radius, out float3 entry, out n))
                            continue;
                        // Tunnelled through a thin box: push the end point back to the entry face.
                        depth = math.dot(entry - x, n);
                    }
                    x += depth * n;
                    // Friction: cancel tangential motion of this substep, at most μ·depth.
                    float3 motion = x - previous[i];
                    float3 tangential = motion - math.dot(motion, n) * n;
                    float slide = math.length(tangential);
                    float limit = friction * depth;
                    if (slide > 0f)
                        x -= tangential * math.min(1f, limit / slide);
                    contactNormal = n;
                }
                predicted[i] = x;
                contactNormals[i] = contactNormal;
                if (math.lengthsq(contactNormal) > 0f)
                    contacts++;
            }
            return contacts;
        }

        /// <summary>
        /// Velocity update vᵢ = (x*ᵢ − xᵢ)/h, then restitution: a particle in contact that approached at
        /// v⁻ₙ = vᵢ⁻·n &lt; −<paramref name="bounceThreshold"/> leaves at −e·v⁻ₙ. Positions advance to x*.
        /// </summary>
        /// <param name="velocities">In: velocities before the substep's solve (after external forces). Out: new velocities.</param>
        public static void UpdateVelocities(Span<float3> positions, Span<float3> velocities, ReadOnlySpan<float3> predicted,
            ReadOnlySpan<float3> contactNormals, float h, float restitution, float bounceThreshold)
        {
            float invH = 1f / h;
            for (int i = 0; i < positions.Length; i++)
            {
                float3 v = (predicted[i] - positions[i]) * invH;
                float3 n = contactNormals[i];
                if (math.lengthsq(n) > 0f)
                {
                    float approach = math.dot(velocities[i], n);
                    if (approach < -bounceThreshold)
                        v += (-restitution * approach - math.dot(v, n)) * n;
                }
                velocities[i] = v;
                positions[i] = predicted[i];
            }
        }
    }
}
