using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Signed distance (m) from a point to the surface of a collider primitive, in float64 and written from the
    /// geometry alone (no code shared with <see cref="ParticleCollision"/>): negative inside. A particle of radius r
    /// at x overlaps the collider by r − SignedDistance(x) when that is positive. Tests use it as the oracle for
    /// "outside every collider".
    /// </summary>
    public static class ColliderDistance
    {
        public static double SignedDistance(in ColliderShape shape, float3 point)
        {
            double px = point.x, py = point.y, pz = point.z;
            switch (shape.Type)
            {
                case ColliderShapeType.Plane:
                {
                    // The solid is the half-space behind the unit normal n: d = (x − p)·n / |n|.
                    double nx = shape.Axis.x, ny = shape.Axis.y, nz = shape.Axis.z;
                    double length = Math.Sqrt(nx * nx + ny * ny + nz * nz);
                    return ((px - shape.Center.x) * nx + (py - shape.Center.y) * ny + (pz - shape.Center.z) * nz) / length;
                }
                case ColliderShapeType.Sphere:
                    return Length(px - shape.Center.x, py - shape.Center.y, pz - shape.Center.z) - shape.Radius;
                case ColliderShapeType.Capsule:
                {
                    // Distance to the segment a–b, minus the radius.
                    double ax = shape.Center.x, ay = shape.Center.y, az = shape.Center.z;
                    double bx = shape.Axis.x - ax, by = shape.Axis.y - ay, bz = shape.Axis.z - az;
                    double len2 = bx * bx + by * by + bz * bz;
                    double t = len2 > 0 ? ((px - ax) * bx + (py - ay) * by + (pz - az) * bz) / len2 : 0;
                    t = Math.Max(0, Math.Min(1, t));
                    return Length(px - ax - t * bx, py - ay - t * by, pz - az - t * bz) - shape.Radius;
                }
                case ColliderShapeType.Box:
                {
                    // Into the box frame with the rotation matrix of the normalised quaternion (transpose = inverse).
                    double qx = shape.Rotation.value.x, qy = shape.Rotation.value.y, qz = shape.Rotation.value.z, qw = shape.Rotation.value.w;
                    double qn = Math.Sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
                    qx /= qn; qy /= qn; qz /= qn; qw /= qn;
                    double r00 = 1 - 2 * (qy * qy + qz * qz), r01 = 2 * (qx * qy - qz * qw), r02 = 2 * (qx * qz + qy * qw);
                    double r10 = 2 * (qx * qy + qz * qw), r11 = 1 - 2 * (qx * qx + qz * qz), r12 = 2 * (qy * qz - qx * qw);
                    double r20 = 2 * (qx * qz - qy * qw), r21 = 2 * (qy * qz + qx * qw), r22 = 1 - 2 * (qx * qx + qy * qy);
                    double dx = px - shape.Center.x, dy = py - shape.Center.y, dz = pz - shape.Center.z;
                    double lx = r00 * dx + r10 * dy + r20 * dz;
                    double ly = r01 * dx + r11 * dy + r21 * dz;
                    double lz = r02 * dx + r12 * dy + r22 * dz;
                    // Standard box distance: outside, the length of the positive excess; inside, the largest (least negative) excess.
                    double ex = Math.Abs(lx) - shape.HalfExtents.x, ey = Math.Abs(ly) - shape.HalfExtents.y, ez = Math.Abs(lz) - shape.HalfExtents.z;
                    double outside = Length(Math.Max(ex, 0), Math.Max(ey, 0), Math.Max(ez, 0));
                    double inside = Math.Min(Math.Max(ex, Math.Max(ey, ez)), 0);
                    return outside + inside;
                }
                default:
                    throw new ArgumentOutOfRangeException(nameof(shape), shape.Type, "unknown collider type");
            }
        }

        /// <summary>How far a particle of radius <paramref name="radius"/> at <paramref name="point"/> overlaps the collider (m, 0 when clear).</summary>
        public static double Overlap(in ColliderShape shape, float3 point, float radius) =>
            Math.Max(0, radius - SignedDistance(shape, point));

        static double Length(double x, double y, double z) => Math.Sqrt(x * x + y * y + z * z);
    }
}
