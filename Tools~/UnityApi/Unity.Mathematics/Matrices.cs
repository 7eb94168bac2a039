// Stand-in matrix and quaternion types. Semantics per
// https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.float3x3.html
// https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.quaternion.html
// float3x3 is column-major (fields c0, c1, c2); operator * is component-wise, math.mul is the product.
// The conversions between float3x3 and quaternion follow com.unity.mathematics 1.3.2 (matrix.cs, quaternion.cs)
// operation for operation, so they give Unity's bits, including the sign Unity picks for the quaternion.
using System;
using System.Runtime.CompilerServices;

namespace Unity.Mathematics
{
    [Serializable]
    public partial struct float3x3 : IEquatable<float3x3>
    {
        public float3 c0, c1, c2;
        public static readonly float3x3 identity = new float3x3(1f, 0f, 0f, 0f, 1f, 0f, 0f, 0f, 1f);
        public static readonly float3x3 zero;

        [MethodImpl(MethodImplOptions.AggressiveInlining)] public float3x3(float3 c0, float3 c1, float3 c2) { this.c0 = c0; this.c1 = c1; this.c2 = c2; }

        /// <summary>Row-major argument order, as in Unity.Mathematics.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public float3x3(float m00, float m01, float m02, float m10, float m11, float m12, float m20, float m21, float m22)
        {
            c0 = new float3(m00, m10, m20);
            c1 = new float3(m01, m11, m21);
            c2 = new float3(m02, m12, m22);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)] public float3x3(float v) { c0 = v; c1 = v; c2 = v; }

        /// <summary>
        /// Rotation matrix of a unit quaternion, evaluated as Unity does (v2 = v + v; the sign flips of
        /// <c>asuint(v.yxw) ^ npn</c> etc. are negations):
        /// c0 = v2.y·(−y, x, −w) − v2.z·(z, −w, −x) + (1, 0, 0),
        /// c1 = v2.z·(−w, −z, y) − v2.x·(−y, x, −w) + (0, 1, 0),
        /// c2 = v2.x·(z, −w, −x) − v2.y·(−w, −z, y) + (0, 0, 1).
        /// https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.float3x3.-ctor.html#Unity_Mathematics_float3x3__ctor_Unity_Mathematics_quaternion_
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public float3x3(quaternion q)
        {
            float4 v = q.value;
            float4 v2 = v + v;
            float3 yxwNpn = new float3(-v.y, v.x, -v.w);
            float3 zwxPnn = new float3(v.z, -v.w, -v.x);
            float3 wzyNnp = new float3(-v.w, -v.z, v.y);
            c0 = v2.y * yxwNpn - v2.z * zwxPnn + new float3(1f, 0f, 0f);
            c1 = v2.z * wzyNnp - v2.x * yxwNpn + new float3(0f, 1f, 0f);
            c2 = v2.x * zwxPnn - v2.y * wzyNnp + new float3(0f, 0f, 1f);
        }

        public unsafe ref float3 this[int index]
        {
            get
            {
                if ((uint)index >= 3) throw new ArgumentException("index must be between[0...2]");
                fixed (float3x3* array = &this) { return ref ((float3*)array)[index]; }
            }
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3x3 operator +(float3x3 a, float3x3 b) => new float3x3(a.c0 + b.c0, a.c1 + b.c1, a.c2 + b.c2);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3x3 operator -(float3x3 a, float3x3 b) => new float3x3(a.c0 - b.c0, a.c1 - b.c1, a.c2 - b.c2);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3x3 operator *(float3x3 a, float3x3 b) => new float3x3(a.c0 * b.c0, a.c1 * b.c1, a.c2 * b.c2);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3x3 operator *(float3x3 a, float b) => new float3x3(a.c0 * b, a.c1 * b, a.c2 * b);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3x3 operator *(float a, float3x3 b) => new float3x3(a * b.c0, a * b.c1, a * b.c2);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3x3 operator /(float3x3 a, float b) => new float3x3(a.c0 / b, a.c1 / b, a.c2 / b);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3x3 operator -(float3x3 a) => new float3x3(-a.c0, -a.c1, -a.c2);

        [MethodImpl(MethodImplOptions.AggressiveInlining)] public bool Equals(float3x3 o) => c0.Equals(o.c0) && c1.Equals(o.c1) && c2.Equals(o.c2);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public override bool Equals(object o) => o is float3x3 v && Equals(v);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public override int GetHashCode() => (int)math.hash(this);
        public override string ToString() =>
            $"float3x3({c0.x}f, {c1.x}f, {c2.x}f,  {c0.y}f, {c1.y}f, {c2.y}f,  {c0.z}f, {c1.z}f, {c2.z}f)";
    }

    [Serializable]
    public partial struct quaternion : IEquatable<quaternion>
    {
        public float4 value;
        public static readonly quaternion identity = new quaternion(0f, 0f, 0f, 1f);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public quaternion(float x, float y, float z, float w) { value = new float4(x, y, z, w); }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public quaternion(float4 value) { this.value = value; }

        /// <summary>
        /// Quaternion of an orthonormal rotation matrix, by Unity's branch-free method: with u, v, w the columns,
        /// s = sign bit of u.x and t = v.y ± w.z (w.z negated when u.x &lt; 0), it forms
        /// (1 + |u.x|, u.y, w.x, v.z) + (t, v.x, u.z, w.y) with per-lane sign flips, then swaps lanes by the
        /// signs of u.x and t and normalizes. The result is one of ±q, chosen exactly as Unity chooses.
        /// https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.quaternion.-ctor.html#Unity_Mathematics_quaternion__ctor_Unity_Mathematics_float3x3_
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public quaternion(float3x3 m)
        {
            const uint S = 0x80000000u;
            float3 u = m.c0, v = m.c1, w = m.c2;
            uint uSign = math.asuint(u.x) & S;
            float t = v.y + math.asfloat(math.asuint(w.z) ^ uSign);
            uint uMask = (uint)((int)uSign >> 31);
            uint tMask = (uint)(math.asint(t) >> 31);
            float tr = 1.0f + math.abs(u.x);

            // sign_flips = (0, S, S, S) ^ (uMask & (0, S, 0, S)) ^ (tMask & (S, S, S, 0))
            uint f0 = 0u ^ (uMask & 0u) ^ (tMask & S);
            uint f1 = S ^ (uMask & S) ^ (tMask & S);
            uint f2 = S ^ (uMask & 0u) ^ (tMask & S);
            uint f3 = S ^ (uMask & S) ^ (tMask & 0u);
            float4 a = new float4(tr, u.y, w.x, v.z) + new float4(
                math.asfloat(math.asuint(t) ^ f0), math.asfloat(math.asuint(v.x) ^ f1),
                math.asfloat(math.asuint(u.z) ^ f2), math.asfloat(math.asuint(w.y) ^ f3));

            // value = select(value, value.zwxy, u.x < 0); then value = select(value.wzyx, value, t < 0)
            float4 b = new float4(Blend(a.x, a.z, uMask), Blend(a.y, a.w, uMask), Blend(a.z, a.x, uMask), Blend(a.w, a.y, uMask));
            float4 c = new float4(Blend(b.w, b.x, tMask), Blend(b.z, b.y, tMask), Blend(b.y, b.z, tMask), Blend(b.x, b.w, tMask));
            value = math.normalize(c);
        }

        /// <summary>The bits of <paramref name="whenClear"/> where <paramref name="mask"/> is 0, of <paramref name="whenSet"/> where it is 1.</summary>
        static float Blend(float whenClear, float whenSet, uint mask) =>
            math.asfloat((math.asuint(whenClear) & ~mask) | (math.asuint(whenSet) & mask));

        /// <summary>Rotation of <paramref name="angle"/> radians about the unit vector <paramref name="axis"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static quaternion AxisAngle(float3 axis, float angle)
        {
            math.sincos(0.5f * angle, out float s, out float c);
            return new quaternion(new float4(axis * s, c));
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)] public bool Equals(quaternion o) => value.Equals(o.value);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public override bool Equals(object o) => o is quaternion v && Equals(v);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public override int GetHashCode() => (int)math.hash(this);
        public override string ToString() => $"quaternion({value.x}f, {value.y}f, {value.z}f, {value.w}f)";
    }
}
