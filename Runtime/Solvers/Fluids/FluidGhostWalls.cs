using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The walls within a kernel radius of one particle as mirror planes: the domain's faces (none on a periodic axis) and
    /// each collider's tangent plane at its closest point, at most <see cref="MaxWalls"/>. The SPH sums see beyond each
    /// wall the particle's neighbours mirrored through it (ghost fluid, Colagrossi &amp; Landrini 2003; Morris et al. 1997),
    /// and through every set of walls at once, so that an edge or a corner is filled by the double and triple images. A
    /// ghost carries its source's density, its velocity mirrored in the wall's frame (free slip: the normal part relative to
    /// a moving collider's surface reversed) and its pressure extrapolated hydrostatically,
    /// pⱼ + ρⱼ·g·(x_g − xⱼ) (Adami et al. 2012, eq. 27, for walls at rest), so that a fluid at rest differentiates its pressure
    /// beside a wall as it does inside. A rest lattice half a spacing off the walls continues itself in its images: its
    /// density, trace and pressure gradient are exactly the interior's, corners included.
    /// Offsets are relative to the particle: a source at y = xⱼ − xᵢ (the nearest image on periodic axes).
    /// </summary>
    public struct FluidGhostWalls
    {
        /// <summary>Most walls one particle mirrors through (a box corner has three; one more for a collider).</summary>
        public const int MaxWalls = 4;

        float3 m_N0, m_N1, m_N2, m_N3;
        float m_D0, m_D1, m_D2, m_D3;
        float m_U0, m_U1, m_U2, m_U3;
        int m_C0, m_C1, m_C2, m_C3;
        /// <summary>Walls found, 0 … <see cref="MaxWalls"/>.</summary>
        public int Count;

        /// <summary>The non-empty sets of walls, as bit masks 1 … <see cref="Subsets"/>; each gives one image of every source.</summary>
        public int Subsets => (1 << Count) - 1;

        /// <summary>Unit normal into the fluid of wall <paramref name="k"/>.</summary>
        public float3 Normal(int k) => k == 0 ? m_N0 : k == 1 ? m_N1 : k == 2 ? m_N2 : m_N3;

        /// <summary>Distance (m, ≥ 0) from the particle to wall <paramref name="k"/>.</summary>
        public float Distance(int k) => k == 0 ? m_D0 : k == 1 ? m_D1 : k == 2 ? m_D2 : m_D3;

        /// <summary>Speed (m/s) of wall <paramref name="k"/> along its normal: a moving collider's surface velocity there, 0 for a face.</summary>
        public float NormalSpeed(int k) => k == 0 ? m_U0 : k == 1 ? m_U1 : k == 2 ? m_U2 : m_U3;

        /// <summary>Index in the colliders of wall <paramref name="k"/>, −1 for a domain face.</summary>
        public int Collider(int k) => k == 0 ? m_C0 : k == 1 ? m_C1 : k == 2 ? m_C2 : m_C3;

        /// <summary>Bit mask of the walls that are colliders with index ≥ <paramref name="first"/> (the moving ones of a coupled step).</summary>
        public int CollidersFrom(int first)
        {
            int mask = 0;
            for (int k = 0; k < Count; k++)
                if (Collider(k) >= first)
                    mask |= 1 << k;
            return mask;
        }

        /// <summary>
        /// The walls within h of <paramref name="xi"/>: faces first (x, y, z; below, then above), then the colliders in order, the
        /// first <see cref="MaxWalls"/> found; of two walls facing the same way (<see cref="SameWallCosine"/>) only the nearer. A
        /// particle inside a collider or beyond a face is taken at the wall (d = 0).
        /// </summary>
        public static FluidGhostWalls Near(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, float3 xi)
        {
            var walls = new FluidGhostWalls();
            float h = c.Kernels.H;
            float3 lo = c.Parameters.DomainMin, hi = c.Parameters.DomainMax;
            for (int a = 0; a < 3; a++)
            {
                // A periodic axis has no faces.
                if (c.Period[a] > 0f)
                    continue;
                float3 axis = float3.zero;
                axis[a] = 1f;
                float below = xi[a] - lo[a], above = hi[a] - xi[a];
                if (below < h)
                    walls.Add(axis, below, 0f, -1);
                if (above < h)
                    walls.Add(-axis, above, 0f, -1);
            }
            for (int w = 0; w < colliders.Length && walls.Count < MaxWalls; w++)
                // Penetration with radius h reports depth = h − d for every point closer than h to the surface.
                if (ParticleCollision.Penetration(colliders[w], xi, h, out float3 normal, out float depth))
                {
                    float d = h - depth;
                    walls.Add(normal, d, math.dot(colliders[w].VelocityAt(xi - d * normal), normal), w);
                }
            return walls;
        }

        /// <summary>Cosine above which two walls face the same way: the fluid sees only the nearer (a collider lying on a face counts once).</summary>
        public const float SameWallCosine = 0.99f;

        void Add(float3 n, float d, float normalSpeed, int collider)
        {
            if (!(d >= -float.MaxValue))
                return;
            d = math.max(d, 0f);
            for (int k = 0; k < Count; k++)
            {
                if (!(math.dot(n, Normal(k)) > SameWallCosine))
                    continue;
                if (d < Distance(k))
                    Set(k, n, d, normalSpeed, collider);
                return;
            }
            if (Count >= MaxWalls)
                return;
            Set(Count, n, d, normalSpeed, collider);
            Count++;
        }

        void Set(int k, float3 n, float d, float u, int collider)
        {
            switch (k)
            {
                case 0: m_N0 = n; m_D0 = d; m_U0 = u; m_C0 = collider; break;
                case 1: m_N1 = n; m_D1 = d; m_U1 = u; m_C1 = collider; break;
                case 2: m_N2 = n; m_D2 = d; m_U2 = u; m_C2 = collider; break;
                default: m_N3 = n; m_D3 = d; m_U3 = u; m_C3 = collider; break;
            }
        }

        /// <summary>
        /// Mirrors the source offset <paramref name="y"/> (xⱼ − xᵢ) and its velocity <paramref name="v"/> through every wall of
        /// <paramref name="subset"/>, in wall order: y ← y − 2·s·n with s = y·n + d its height above the wall, v ← v − 2(v·n − u)·n
        /// with u the wall's <see cref="NormalSpeed"/>.
        /// False when the source is not strictly on the fluid side of one of them (its image would lie in the fluid).
        /// </summary>
        public bool Mirror(int subset, ref float3 y, ref float3 v)
        {
            for (int k = 0; k < Count; k++)
            {
                if ((subset & (1 << k)) == 0)
                    continue;
                float3 n = Normal(k);
                float s = math.dot(y, n) + Distance(k);
                if (!(s > 0f))
                    return false;
                y -= 2f * s * n;
                v -= 2f * (math.dot(v, n) - NormalSpeed(k)) * n;
            }
            return true;
        }

        /// <summary>
        /// <see cref="Mirror(int, ref float3, ref float3)"/>, and false too when <paramref name="subset"/> is one collider's wall
        /// and the image, at <paramref name="xi"/> + y, lies outside that collider: a tangent plane beside a box's edge or on a
        /// sphere extends beyond the solid, and an image there would stand where fluid is (counted twice). A plane's images are
        /// all in it; a set of several walls keeps its images (they fill the corners between a collider and a face).
        /// </summary>
        public bool Mirror(int subset, float3 xi, ReadOnlySpan<ColliderShape> colliders, ref float3 y, ref float3 v)
        {
            if (!Mirror(subset, ref y, ref v))
                return false;
            if ((subset & (subset - 1)) != 0)
                return true;
            int k = 0;
            while (subset >> k != 1)
                k++;
            int w = Collider(k);
            return w < 0 || colliders[w].Type == ColliderShapeType.Plane || ParticleCollision.Contains(colliders[w], xi + y);
        }
    }
}
