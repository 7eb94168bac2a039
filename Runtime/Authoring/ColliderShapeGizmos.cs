using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>Wireframe drawing of a world-space <see cref="ColliderShape"/> with <see cref="Gizmos"/>.</summary>
    public static class ColliderShapeGizmos
    {
        /// <summary>Half the side of the square drawn for an (infinite) plane (m).</summary>
        public const float PlaneDisplayHalfSize = 5f;

        /// <summary>Draws <paramref name="shape"/>; a shape with a NaN or infinite field is skipped (validation reports it).</summary>
        public static void Draw(in ColliderShape shape, Color color)
        {
            if (!IsFinite(shape))
                return;
            Matrix4x4 previousMatrix = Gizmos.matrix;
            Gizmos.color = color;
            switch (shape.Type)
            {
                case ColliderShapeType.Plane:
                    DrawPlane(shape.Center, shape.Axis);
                    break;
                case ColliderShapeType.Sphere:
                    Gizmos.matrix = Matrix4x4.identity;
                    Gizmos.DrawWireSphere(UnityMathConversions.ToVector3(shape.Center), shape.Radius);
                    break;
                case ColliderShapeType.Box:
                    Gizmos.matrix = Matrix4x4.TRS(UnityMathConversions.ToVector3(shape.Center),
                        UnityMathConversions.ToUnityQuaternion(shape.Rotation), Vector3.one);
                    Gizmos.DrawWireCube(Vector3.zero, UnityMathConversions.ToVector3(2f * shape.HalfExtents));
                    break;
                case ColliderShapeType.Capsule:
                    DrawCapsule(shape.Center, shape.Axis, shape.Radius);
                    break;
            }
            Gizmos.matrix = previousMatrix;
        }

        static void DrawPlane(float3 point, float3 normal)
        {
            // A square in the plane, its diagonals, and the outward normal.
            Gizmos.matrix = Matrix4x4.identity;
            Basis(normal, out float3 u, out float3 v);
            float h = PlaneDisplayHalfSize;
            float3 a = point + h * (u + v), b = point + h * (u - v), c = point - h * (u + v), d = point - h * (u - v);
            Line(a, b);
            Line(b, c);
            Line(c, d);
            Line(d, a);
            Line(a, c);
            Line(b, d);
            Line(point, point + normal);
        }

        static void DrawCapsule(float3 pointA, float3 pointB, float radius)
        {
            Gizmos.matrix = Matrix4x4.identity;
            Gizmos.DrawWireSphere(UnityMathConversions.ToVector3(pointA), radius);
            Gizmos.DrawWireSphere(UnityMathConversions.ToVector3(pointB), radius);
            float3 axis = pointB - pointA;
            Basis(math.normalizesafe(axis, new float3(0f, 1f, 0f)), out float3 u, out float3 v);
            Line(pointA + radius * u, pointB + radius * u);
            Line(pointA - radius * u, pointB - radius * u);
            Line(pointA + radius * v, pointB + radius * v);
            Line(pointA - radius * v, pointB - radius * v);
        }

        /// <summary>Two unit vectors perpendicular to <paramref name="n"/> and to each other.</summary>
        static void Basis(float3 n, out float3 u, out float3 v)
        {
            float3 helper = math.abs(n.y) < 0.9f ? new float3(0f, 1f, 0f) : new float3(1f, 0f, 0f);
            u = math.normalizesafe(math.cross(helper, n), new float3(1f, 0f, 0f));
            v = math.cross(n, u);
        }

        static bool IsFinite(in ColliderShape shape) =>
            math.all(math.isfinite(shape.Center)) && math.all(math.isfinite(shape.Axis)) && math.all(math.isfinite(shape.HalfExtents))
            && math.all(math.isfinite(shape.Rotation.value)) && math.isfinite(shape.Radius);

        static void Line(float3 a, float3 b) =>
            Gizmos.DrawLine(UnityMathConversions.ToVector3(a), UnityMathConversions.ToVector3(b));
    }
}
