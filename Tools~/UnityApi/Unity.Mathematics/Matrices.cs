// Stand-in matrix and quaternion types. Semantics per
// https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.float3x3.html
// https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.quaternion.html
// float3x3 is column-major (fields c0, c1, c2); operator * is component-wise, math.mul is the product.
using System;

namespace Unity.Mathematics
{
    [Serializable]
    public partial struct float3x3 : IEquatable<float3x3>
    {
        public float3 c0, c1, c2;
        public static readonly float3x3 identity = new float3x3(1f, 0f, 0f, 0f, 1f, 0f, 0f, 0f, 1f);
        public static readonly float3x3 zero;

        public float3x3(float3 c0, float3 c1, float3 c2) { this.c0 = c0; this.c1 = c1; this.c2 = c2; }

        /// <summary>Row-major argument order, as in Unity.Mathematics.</summary>
        public float3x3(float m00, float m01, float m02, float m10, float m11, float m12, float m20, float m21, float m22)
        {
            c0 = new float3(m00, m10, m20);
            c1 = new float3(m01, m11, m21);
            c2 = new float3(m02, m12, m22);
        }

        public float3x3(float v) { c0 = v; c1 = v; c2 = v; }

        /// <summary>Rotation matrix of a unit quaternion.</summary>
        public float3x3(quaternion q)
        {
            float x = q.value.x, y = q.value.y, z = q.value.z, w = q.value.w;
            float x2 = x + x, y2 = y + y, z2 = z + z;
            float xx = x * x2, yy = y * y2, zz = z * z2;
            float xy = x * y2, xz = x * z2, yz = y * z2;
            float wx = w * x2, wy = w * y2, wz = w * z2;
            c0 = new float3(1f - (yy + zz), xy + wz, xz - wy);
            c1 = new float3(xy - wz, 1f - (xx + zz), yz + wx);
            c2 = new float3(xz + wy, yz - wx, 1f - (xx + yy));
        }

        public unsafe ref float3 this[int index]
        {
            get
            {
                if ((uint)index >= 3) throw new ArgumentException("index must be between[0...2]");
                fixed (float3x3* array = &this) { return ref ((float3*)array)[index]; }
            }
        }

        public static float3x3 operator +(float3x3 a, float3x3 b) => new float3x3(a.c0 + b.c0, a.c1 + b.c1, a.c2 + b.c2);
        public static float3x3 operator -(float3x3 a, float3x3 b) => new float3x3(a.c0 - b.c0, a.c1 - b.c1, a.c2 - b.c2);
        public static float3x3 operator *(float3x3 a, float3x3 b) => new float3x3(a.c0 * b.c0, a.c1 * b.c1, a.c2 * b.c2);
        public static float3x3 operator *(float3x3 a, float b) => new float3x3(a.c0 * b, a.c1 * b, a.c2 * b);
        public static float3x3 operator *(float a, float3x3 b) => new float3x3(a * b.c0, a * b.c1, a * b.c2);
        public static float3x3 operator /(float3x3 a, float b) => new float3x3(a.c0 / b, a.c1 / b, a.c2 / b);
        public static float3x3 operator -(float3x3 a) => new float3x3(-a.c0, -a.c1, -a.c2);

        public bool Equals(float3x3 o) => c0.Equals(o.c0) && c1.Equals(o.c1) && c2.Equals(o.c2);
        public override bool Equals(object o) => o is float3x3 v && Equals(v);
        public override int GetHashCode() => HashCode.Combine(c0, c1, c2);
        public override string ToString() =>
            $"float3x3({c0.x}f, {c1.x}f, {c2.x}f,  {c0.y}f, {c1.y}f, {c2.y}f,  {c0.z}f, {c1.z}f, {c2.z}f)";
    }

    [Serializable]
    public partial struct quaternion : IEquatable<quaternion>
    {
        public float4 value;
        public static readonly quaternion identity = new quaternion(0f, 0f, 0f, 1f);
        public quaternion(float x, float y, float z, float w) { value = new float4(x, y, z, w); }
        public quaternion(float4 value) { this.value = value; }

        /// <summary>Quaternion of an orthonormal rotation matrix.</summary>
        public quaternion(float3x3 m)
        {
            // Shepperd's method: pick the largest of w, x, y, z to divide by.
            float t = m.c0.x + m.c1.y + m.c2.z;
            if (t > 0f)
            {
                float s = math.sqrt(t + 1f) * 2f;
                value = new float4((m.c1.z - m.c2.y) / s, (m.c2.x - m.c0.z) / s, (m.c0.y - m.c1.x) / s, 0.25f * s);
            }
            else if (m.c0.x > m.c1.y && m.c0.x > m.c2.z)
            {
                float s = math.sqrt(1f + m.c0.x - m.c1.y - m.c2.z) * 2f;
                value = new float4(0.25f * s, (m.c1.x + m.c0.y) / s, (m.c2.x + m.c0.z) / s, (m.c1.z - m.c2.y) / s);
            }
            else if (m.c1.y > m.c2.z)
            {
                float s = math.sqrt(1f + m.c1.y - m.c0.x - m.c2.z) * 2f;
                value = new float4((m.c1.x + m.c0.y) / s, 0.25f * s, (m.c2.y + m.c1.z) / s, (m.c2.x - m.c0.z) / s);
            }
            else
            {
                float s = math.sqrt(1f + m.c2.z - m.c0.x - m.c1.y) * 2f;
                value = new float4((m.c2.x + m.c0.z) / s, (m.c2.y + m.c1.z) / s, 0.25f * s, (m.c0.y - m.c1.x) / s);
            }
            value = math.normalize(value);
        }

        /// <summary>Rotation of <paramref name="angle"/> radians about the unit vector <paramref name="axis"/>.</summary>
        public static quaternion AxisAngle(float3 axis, float angle)
        {
            math.sincos(0.5f * angle, out float s, out float c);
            return new quaternion(new float4(axis * s, c));
        }

        public bool Equals(quaternion o) => value.Equals(o.value);
        public override bool Equals(object o) => o is quaternion v && Equals(v);
        public override int GetHashCode() => value.GetHashCode();
        public override string ToString() => $"quaternion({value.x}f, {value.y}f, {value.z}f, {value.w}f)";
    }
}
