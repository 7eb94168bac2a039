using System;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Separating-axis test of a triangle against an axis-aligned box (the 13 axes of Akenine-Möller 2001: the 3 box
    /// normals, the triangle normal and the 9 cross products of box axes with triangle edges), in double.
    /// </summary>
    static class TriangleBoxSeparation
    {
        /// <summary>
        /// The largest gap (m) between the projections of the triangle (a, b, c) and of the box (centre, half-size h)
        /// onto any of the 13 axes (unit length; axes shorter than 1e-12 of the longest edge product are skipped).
        /// Negative: the solids overlap with positive depth on every axis; 0: they touch; positive: they are at least
        /// that far apart (a gap along an axis never exceeds the true distance).
        /// </summary>
        public static double Separation(Double3 a, Double3 b, Double3 c, Double3 center, Double3 h)
        {
            a -= center;
            b -= center;
            c -= center;
            Double3 e0 = b - a, e1 = c - b, e2 = a - c;
            double scale = Math.Max(Length2(e0), Math.Max(Length2(e1), Length2(e2)));
            double gap = double.NegativeInfinity;
            gap = Math.Max(gap, Gap(new Double3(1, 0, 0), a, b, c, h, scale));
            gap = Math.Max(gap, Gap(new Double3(0, 1, 0), a, b, c, h, scale));
            gap = Math.Max(gap, Gap(new Double3(0, 0, 1), a, b, c, h, scale));
            gap = Math.Max(gap, Gap(Double3.Cross(e0, -e2), a, b, c, h, scale * scale));
            Double3 e = e0;
            for (int edge = 0; edge < 3; edge++, e = edge == 1 ? e1 : e2)
            {
                gap = Math.Max(gap, Gap(new Double3(0, -e.z, e.y), a, b, c, h, scale));
                gap = Math.Max(gap, Gap(new Double3(e.z, 0, -e.x), a, b, c, h, scale));
                gap = Math.Max(gap, Gap(new Double3(-e.y, e.x, 0), a, b, c, h, scale));
            }
            return gap;
        }

        static double Length2(Double3 v) => v.x * v.x + v.y * v.y + v.z * v.z;

        static double Gap(Double3 axis, Double3 a, Double3 b, Double3 c, Double3 h, double scale2)
        {
            double length2 = Length2(axis);
            if (!(length2 > 1e-24 * scale2) || length2 == 0.0)
                return double.NegativeInfinity;
            double pa = Double3.Dot(axis, a), pb = Double3.Dot(axis, b), pc = Double3.Dot(axis, c);
            double lo = Math.Min(pa, Math.Min(pb, pc)), hi = Math.Max(pa, Math.Max(pb, pc));
            double r = h.x * Math.Abs(axis.x) + h.y * Math.Abs(axis.y) + h.z * Math.Abs(axis.z);
            return Math.Max(lo - r, -r - hi) / Math.Sqrt(length2);
        }
    }

    /// <summary>A point or vector in double, for bake-time geometry.</summary>
    readonly struct Double3
    {
        /// <summary>Components.</summary>
        public readonly double x, y, z;

        public Double3(double x, double y, double z)
        {
            this.x = x;
            this.y = y;
            this.z = z;
        }

        public static Double3 operator +(Double3 a, Double3 b) => new Double3(a.x + b.x, a.y + b.y, a.z + b.z);
        public static Double3 operator -(Double3 a, Double3 b) => new Double3(a.x - b.x, a.y - b.y, a.z - b.z);
        public static Double3 operator -(Double3 a) => new Double3(-a.x, -a.y, -a.z);
        public static Double3 operator *(double s, Double3 a) => new Double3(s * a.x, s * a.y, s * a.z);

        /// <summary>Dot product.</summary>
        public static double Dot(Double3 a, Double3 b) => a.x * b.x + a.y * b.y + a.z * b.z;

        /// <summary>Cross product.</summary>
        public static Double3 Cross(Double3 a, Double3 b) => new Double3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
    }
}
