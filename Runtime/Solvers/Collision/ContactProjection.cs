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
        /// <summary>
        /// Projects <paramref name="predicted"/> out of the colliders and adds each push to the velocity
        /// (Δv = Δx/h); a particle that approached a surface at v⁻ₙ = v·n &lt; −<paramref name="bounceThreshold"/>
        /// leaves it at −e·v⁻ₙ. Writes each particle's contact normal (zero when free) to
        /// <paramref name="contactNormals"/>. Returns the number of particles in contact.
        /// </summary>
        /// <param name="previous">Positions at the start of the substep (for the swept test and friction).</param>
        /// <param name="h">Substep (s).</param>
        public static int Project(ReadOnlySpan<float3> previous, Span<float3> predicted, Span<float3> velocities,
            Span<float3> contactNormals, ReadOnlySpan<ColliderShape> colliders, float radius, float friction, float h,
            float restitution, float bounceThreshold)
        {
            int contacts = 0;
            float invH = 1f / h;
            for (int i = 0; i < predicted.Length; i++)
            {
                float3 start = predicted[i];
                float3 x = start;
                float3 contactNormal = float3.zero;
                for (int c = 0; c < colliders.Length; c++)
                {
                    float3 n;
                    float depth;
                    // A particle that came from outside leaves through the face it entered (a fast one may
                    // be nearer the far face, or already through a thin box); one that started inside
                    // leaves through the nearest face.
                    if (ParticleCollision.Sweep(colliders[c], previous[i], x, radius, out float3 entry, out n))
                        depth = math.dot(entry - x, n);
                    else if (!ParticleCollision.Penetration(colliders[c], x, radius, out n, out depth))
                        continue;
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
                contactNormals[i] = contactNormal;
                if (math.lengthsq(contactNormal) == 0f)
                    continue;
                contacts++;
                float approach = math.dot(velocities[i], contactNormal);
                float3 v = velocities[i] + (x - start) * invH;
                if (approach < -bounceThreshold)
                    v += (-restitution * approach - math.dot(v, contactNormal)) * contactNormal;
                velocities[i] = v;
                predicted[i] = x;
            }
            return contacts;
        }
    }
}
