using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Axis-aligned bounds of a point set (m).</summary>
    public struct AxisAlignedBox
    {
        /// <summary>Smallest coordinate on each axis (m).</summary>
        public float3 Min;
        /// <summary>Largest coordinate on each axis (m).</summary>
        public float3 Max;

        /// <summary>Size on each axis (m).</summary>
        public float3 Extent => Max - Min;
        /// <summary>Midpoint (m).</summary>
        public float3 Center => 0.5f * (Min + Max);
        /// <summary>Largest of the three extents (m): the "body size" used by the builder.</summary>
        public float LongestExtent => math.cmax(Extent);

        /// <summary>Length of the diagonal (m), evaluated in double so that large finite boxes do not overflow early.</summary>
        public float Diagonal
        {
            get
            {
                double x = (double)Max.x - Min.x, y = (double)Max.y - Min.y, z = (double)Max.z - Min.z;
                return (float)Math.Sqrt(x * x + y * y + z * z);
            }
        }

        /// <summary>The bounds of <paramref name="points"/> (all finite); a zero box at the origin when there are none.</summary>
        public static AxisAlignedBox Of(ReadOnlySpan<float3> points)
        {
            if (points.Length == 0)
                return default;
            float3 min = points[0], max = points[0];
            for (int i = 1; i < points.Length; i++)
            {
                min = math.min(min, points[i]);
                max = math.max(max, points[i]);
            }
            return new AxisAlignedBox { Min = min, Max = max };
        }
    }
}
