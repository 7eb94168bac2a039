using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Shape-matching bodies on managed arrays kept apart by <see cref="BodyContacts"/>: their particles gathered in world
    /// space (position + the body's origin), resolved, and the changes written back, for tests and benchmarks.
    /// </summary>
    public sealed class ShapeMatchingContacts
    {
        readonly ShapeMatchingInstance[] m_Bodies;
        readonly float3[] m_Positions, m_Velocities;
        readonly float[] m_InverseMasses, m_Radii;
        readonly int[] m_Owners, m_Starts, m_Sorted, m_Buckets;

        public BodyContactSettings Settings = BodyContactSettings.Default;

        public ShapeMatchingContacts(params ShapeMatchingInstance[] bodies)
        {
            m_Bodies = bodies;
            int n = 0;
            foreach (var b in bodies)
                n += b.Positions.Length;
            m_Positions = new float3[n];
            m_Velocities = new float3[n];
            m_InverseMasses = new float[n];
            m_Radii = new float[n];
            m_Owners = new int[n];
            m_Starts = new int[BodyContacts.TableSize(n) + 1];
            m_Sorted = new int[n];
            m_Buckets = new int[n];
            // Owners and inverse masses never change; positions, velocities and radii are read each resolve.
            int k = 0;
            for (int b = 0; b < bodies.Length; b++)
            {
                float[] masses = bodies[b].Model.Masses, inverse = bodies[b].Model.InverseMasses;
                bool pins = inverse != null && inverse.Length == masses.Length;
                for (int i = 0; i < masses.Length; i++, k++)
                {
                    m_InverseMasses[k] = pins ? inverse[i] : 1f / masses[i];
                    m_Owners[k] = b;
                }
            }
        }

        /// <summary>
        /// A step of <paramref name="dt"/> among <paramref name="colliders"/> as the bodies' substeps (the most any body takes),
        /// each body one substep, then the contacts between them; returns the last substep's report and the deepest overlap any
        /// substep left in <paramref name="worstAfter"/>.
        /// </summary>
        public BodyContactReport Step(float dt, ReadOnlySpan<ColliderShape> colliders, out float worstAfter)
        {
            int substeps = 1;
            foreach (var b in m_Bodies)
                substeps = Math.Max(substeps, ShapeMatchingSolver.SubstepCount(b.Parameters, dt));
            float h = dt / substeps;
            var report = new BodyContactReport();
            worstAfter = 0f;
            for (int s = 0; s < substeps; s++)
            {
                foreach (var b in m_Bodies)
                {
                    int own = b.Parameters.Body.Substeps;
                    b.Parameters.Body.Substeps = 1;
                    b.Step(h, colliders);
                    b.Parameters.Body.Substeps = own;
                }
                report = Resolve(h);
                worstAfter = Math.Max(worstAfter, report.MaxOverlapAfter);
            }
            return report;
        }

        /// <summary>The contacts between the bodies as they stand, after a substep of <paramref name="h"/> (s).</summary>
        public BodyContactReport Resolve(float h)
        {
            int k = 0;
            for (int b = 0; b < m_Bodies.Length; b++)
            {
                var body = m_Bodies[b];
                for (int i = 0; i < body.Positions.Length; i++, k++)
                {
                    m_Positions[k] = body.Positions[i] + body.Status.Origin;
                    m_Velocities[k] = body.Velocities[i];
                    m_Radii[k] = body.Parameters.Body.ParticleRadius;
                }
            }
            var report = BodyContacts.Resolve(new BodyContactParticles(m_Positions, m_Velocities, m_InverseMasses, m_Radii, m_Owners),
                Settings, h, m_Starts, m_Sorted, m_Buckets);
            k = 0;
            foreach (var body in m_Bodies)
                for (int i = 0; i < body.Positions.Length; i++, k++)
                {
                    body.Positions[i] = m_Positions[k] - body.Status.Origin;
                    body.Velocities[i] = m_Velocities[k];
                }
            return report;
        }
    }
}
