using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Explicit conversions between UnityEngine vectors and Unity.Mathematics types, written out so the
    /// authoring code does not depend on the implicit operators Unity.Mathematics adds inside Unity.
    /// </summary>
    public static class UnityMathConversions
    {
        public static float3 ToFloat3(Vector3 v) => new float3(v.x, v.y, v.z);

        public static Vector3 ToVector3(float3 v) => new Vector3(v.x, v.y, v.z);

        public static quaternion ToQuaternion(Quaternion q) => new quaternion(q.x, q.y, q.z, q.w);

        public static Quaternion ToUnityQuaternion(quaternion q) => new Quaternion(q.value.x, q.value.y, q.value.z, q.value.w);
    }
}
