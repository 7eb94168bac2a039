using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Generalised winding number of a closed triangle mesh (Jacobson, Kavan &amp; Sorkine-Hornung 2013):
    /// w(p) = Σ Ω_t(p) / 4π, with each triangle's signed solid angle from Van Oosterom &amp; Strackee (1983),
    /// tan(Ω/2) = a·(b × c) / (|a||b||c| + (a·b)|c| + (a·c)|b| + (b·c)|a|), where a, b, c run from p to the
    /// corners. For a closed, consistently wound mesh w is 1 inside (−1 if the triangles face inwards)
    /// and 0 outside. Evaluated in double: O(triangles) per point, no acceleration structure.
    /// </summary>
    public sealed class WindingNumber
    {
        /// <summary>
        /// With the point within the on-surface distance of a triangle's plane, the point counts as on
        /// that triangle when the solid-angle denominator is at most this fraction of |a||b||c|: exactly 0
        /// on the triangle's edges, negative inside it, and computed in double to about 1e-15 relative.
        /// </summary>
        const double k_OnTriangleDenominatorFraction = 1e-9;

        readonly double[] m_Corners;
        readonly int m_TriangleCount;

        /// <summary>Prepares the triangles of <paramref name="triangles"/> that do not repeat a particle.</summary>
        /// <param name="positions">Particle positions (m).</param>
        /// <param name="triangles">Particle indices (in range), three per triangle.</param>
        public WindingNumber(ReadOnlySpan<float3> positions, ReadOnlySpan<int> triangles)
        {
            m_Corners = new double[3 * triangles.Length];
            for (int t = 0; t < triangles.Length / 3; t++)
            {
                int a = triangles[3 * t], b = triangles[3 * t + 1], c = triangles[3 * t + 2];
                if (MeshTopology.RepeatsParticle(a, b, c))
                    continue;
                int o = 9 * m_TriangleCount++;
                Store(positions[a], o);
                Store(positions[b], o + 3);
                Store(positions[c], o + 6);
            }
        }

        void Store(float3 p, int offset)
        {
            m_Corners[offset] = p.x;
            m_Corners[offset + 1] = p.y;
            m_Corners[offset + 2] = p.z;
        }

        /// <summary>
        /// The winding number at <paramref name="point"/>, or false when the point lies on the surface:
        /// within <paramref name="onSurfaceDistance"/> (m) of a triangle's plane while inside or on the
        /// edge of that triangle, where the solid angle jumps and w is not defined.
        /// </summary>
        public bool TryEvaluate(float3 point, double onSurfaceDistance, out double winding)
        {
            double px = point.x, py = point.y, pz = point.z;
            double sum = 0.0;
            for (int t = 0; t < m_TriangleCount; t++)
            {
                int o = 9 * t;
                double ax = m_Corners[o] - px, ay = m_Corners[o + 1] - py, az = m_Corners[o + 2] - pz;
                double bx = m_Corners[o + 3] - px, by = m_Corners[o + 4] - py, bz = m_Corners[o + 5] - pz;
                double cx = m_Corners[o + 6] - px, cy = m_Corners[o + 7] - py, cz = m_Corners[o + 8] - pz;
                double la = Math.Sqrt(ax * ax + ay * ay + az * az);
                double lb = Math.Sqrt(bx * bx + by * by + bz * bz);
                double lc = Math.Sqrt(cx * cx + cy * cy + cz * cz);
                double det = ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
                double denominator = la * lb * lc + (ax * bx + ay * by + az * bz) * lc
                                     + (ax * cx + ay * cy + az * cz) * lb + (bx * cx + by * cy + bz * cz) * la;

                // |det| = 6 × volume of (p, corners) = distance to the plane × |(b − a) × (c − a)|.
                double ux = bx - ax, uy = by - ay, uz = bz - az, vx = cx - ax, vy = cy - ay, vz = cz - az;
                double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
                double doubleArea = Math.Sqrt(nx * nx + ny * ny + nz * nz);
                if (Math.Abs(det) <= onSurfaceDistance * doubleArea
                    && denominator <= k_OnTriangleDenominatorFraction * la * lb * lc)
                {
                    winding = 0.0;
                    return false;
                }
                sum += Math.Atan2(det, denominator);
            }
            winding = sum / (2.0 * Math.PI);
            return true;
        }
    }
}
