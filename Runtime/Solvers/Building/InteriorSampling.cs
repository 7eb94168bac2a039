using System;
using System.Collections.Generic;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Interior particles for a closed surface: points of a <see cref="CubicLattice"/> over the surface
    /// particles' bounds that lie strictly inside the mesh, by the generalised winding number
    /// (<see cref="WindingNumber"/>). A lattice point is kept when |w| &gt; 1/2, it is farther than
    /// <see cref="OnSurfaceFraction"/>·s from every triangle it lies over (points on the surface are not
    /// strictly inside), and no surface particle is closer than s/2 to it.
    /// <para>
    /// Along each x-row, w can only change where the row meets the surface, so it is evaluated (O(triangles))
    /// only at points whose segment from the previous point may pass within the on-surface band of a
    /// triangle (<see cref="LatticeRowTriangles"/>, conservative); elsewhere it is carried over, starting
    /// from w = 0 at x = −∞. This skips only evaluations whose result is already known, so the points are
    /// the same as testing every lattice point. Points are visited z-major, then y, then x; the result is
    /// deterministic.
    /// </para>
    /// </summary>
    public static class InteriorSampling
    {
        /// <summary>Automatic spacing: the longest bounds extent divided by this (about 7 interior points across).</summary>
        public const float AutoSpacingDivisions = 8f;

        /// <summary>Lattice points within this fraction of the spacing of a face's plane (and over the face) count as on the surface.</summary>
        public const double OnSurfaceFraction = 1e-4;

        /// <summary>Most lattice points (in the bounds) that one call may visit: 2²⁴.</summary>
        public const double MaxLatticePoints = 1 << 24;

        enum Side : byte { Outside, Inside, OnSurface }

        /// <summary>The spacing used for "auto" (m): longest extent / <see cref="AutoSpacingDivisions"/>.</summary>
        public static float AutoSpacing(in AxisAlignedBox bounds) => bounds.LongestExtent / AutoSpacingDivisions;

        /// <summary>
        /// Appends to <paramref name="output"/> the lattice points strictly inside the closed, consistently
        /// wound surface (<paramref name="surfaceParticles"/>, <paramref name="triangles"/>), at most
        /// <paramref name="maxPoints"/> of them. Returns how many were found: when that exceeds
        /// <paramref name="maxPoints"/>, the search stopped at <paramref name="maxPoints"/> + 1.
        /// </summary>
        /// <param name="surfaceParticles">Welded surface positions (m).</param>
        /// <param name="triangles">Particle indices, three per triangle; the mesh must be closed.</param>
        /// <param name="spacing">Lattice spacing (m, &gt; 0, with at most <see cref="MaxLatticePoints"/> points in the bounds).</param>
        /// <param name="maxPoints">Most points to append (≥ 0).</param>
        public static int Sample(ReadOnlySpan<float3> surfaceParticles, ReadOnlySpan<int> triangles, float spacing,
            int maxPoints, List<float3> output)
        {
            if (!(spacing > 0f) || !math.isfinite(spacing))
                throw new ArgumentOutOfRangeException(nameof(spacing), spacing, "The spacing must be finite and positive.");
            AxisAlignedBox bounds = AxisAlignedBox.Of(surfaceParticles);
            if (CubicLattice.PointCount(bounds, spacing) > MaxLatticePoints)
                throw new ArgumentOutOfRangeException(nameof(spacing), spacing, "The lattice has too many points for these bounds.");

            var lattice = new CubicLattice(bounds, spacing);
            float exclusion = 0.5f * spacing;
            var grid = new PointGrid(bounds.Min, exclusion);
            for (int i = 0; i < surfaceParticles.Length; i++)
                grid.Add(surfaceParticles[i], i);
            var winding = new WindingNumber(surfaceParticles, triangles);
            double onSurface = OnSurfaceFraction * spacing;
            // The box margin covers the on-surface band, plus float32 round-off of coordinates up to the bounds' size.
            double margin = onSurface + 4.0 * math.EPSILON * math.max(math.cmax(math.abs(bounds.Min)), math.cmax(math.abs(bounds.Max)));
            LatticeRowTriangles rows = LatticeRowTriangles.TryBuild(surfaceParticles, triangles, lattice, margin);
            var mayCross = new bool[lattice.CountX];

            int found = 0;
            for (int k = 0; k < lattice.CountZ; k++)
            for (int j = 0; j < lattice.CountY; j++)
            {
                if (rows != null)
                {
                    if (rows.IsEmpty(j, k, lattice))
                        continue;
                    rows.MarkRow(j, k, lattice, mayCross);
                }
                Side previous = Side.Outside;
                for (int i = 0; i < lattice.CountX; i++)
                {
                    float3 p = lattice.Point(i, j, k);
                    Side side = rows != null && !mayCross[i] && previous != Side.OnSurface ? previous : Classify(winding, p, onSurface);
                    previous = side;
                    if (side != Side.Inside || grid.LowestIndexWithin(p, exclusion, inclusive: false) >= 0)
                        continue;
                    found++;
                    if (found > maxPoints)
                        return found;
                    output.Add(p);
                }
            }
            return found;
        }

        static Side Classify(WindingNumber winding, float3 p, double onSurface)
        {
            if (!winding.TryEvaluate(p, onSurface, out double w))
                return Side.OnSurface;
            return Math.Abs(w) > 0.5 ? Side.Inside : Side.Outside;
        }
    }
}
