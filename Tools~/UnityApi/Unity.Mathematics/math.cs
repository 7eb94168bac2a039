// Stand-in for the static class Unity.Mathematics.math. Semantics per
// https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.html
// Each member follows com.unity.mathematics 1.3.2 (Unity.Mathematics/math.cs, matrix.cs, matrix.gen.cs,
// quaternion.cs): the same formula with the same order of float operations, so results are bit-identical
// to Unity's managed (non-Burst) build. Tools~/DotNet/SoftBodyDynamics.Tests.MathematicsStandIn checks them.
using System;
using System.Runtime.CompilerServices;

namespace Unity.Mathematics
{
    public static partial class math
    {
        public const float PI = 3.14159265358979323846f;
        public const float EPSILON = 1.1920928955078125e-7f;
        public const float FLT_MIN_NORMAL = 1.175494351e-38f;
        public const float INFINITY = float.PositiveInfinity;

        // ---- construction helpers
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float2 float2(float x, float y) => new float2(x, y);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 float3(float x, float y, float z) => new float3(x, y, z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 float3(float v) => new float3(v);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 float4(float x, float y, float z, float w) => new float4(x, y, z, w);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 float4(float3 xyz, float w) => new float4(xyz, w);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3x3 float3x3(float3 c0, float3 c1, float3 c2) => new float3x3(c0, c1, c2);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3x3 float3x3(quaternion q) => new float3x3(q);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int3 int3(int x, int y, int z) => new int3(x, y, z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static quaternion quaternion(float4 v) => new quaternion(v);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static quaternion quaternion(float3x3 m) => new quaternion(m);

        // ---- scalar
        // Unity's managed source rounds System.Math.Sqrt((double)x) to float; that is the correctly rounded float square
        // root (53 ≥ 2·24 + 2 bits, so the double rounding is innocuous), the bits MathF.Sqrt (sqrtss, as Burst emits) gives.
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float sqrt(float x) => MathF.Sqrt(x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float rsqrt(float x) => 1.0f / sqrt(x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float rcp(float x) => 1.0f / x;
        /// <summary>Clears the sign bit (NaN stays NaN).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float abs(float x) => asfloat(asuint(x) & 0x7FFFFFFFu);
        /// <summary>max(−x, x): int.MinValue stays int.MinValue (no overflow exception).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int abs(int x) => max(-x, x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float min(float a, float b) => float.IsNaN(b) || a < b ? a : b;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float max(float a, float b) => float.IsNaN(b) || a > b ? a : b;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int min(int a, int b) => a < b ? a : b;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int max(int a, int b) => a > b ? a : b;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static uint min(uint a, uint b) => a < b ? a : b;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static uint max(uint a, uint b) => a > b ? a : b;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float clamp(float x, float a, float b) => max(a, min(b, x));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int clamp(int x, int a, int b) => max(a, min(b, x));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float saturate(float x) => clamp(x, 0f, 1f);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float sign(float x) => (x > 0f ? 1f : 0f) - (x < 0f ? 1f : 0f);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float select(float a, float b, bool c) => c ? b : a;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float lerp(float a, float b, float t) => a + t * (b - a);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float pow(float x, float y) => (float)System.Math.Pow(x, y);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float exp(float x) => (float)System.Math.Exp(x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float log(float x) => (float)System.Math.Log(x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float sin(float x) => (float)System.Math.Sin(x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float cos(float x) => (float)System.Math.Cos(x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float acos(float x) => (float)System.Math.Acos(x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float asin(float x) => (float)System.Math.Asin(x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float atan2(float y, float x) => (float)System.Math.Atan2(y, x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float floor(float x) => (float)System.Math.Floor(x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float ceil(float x) => (float)System.Math.Ceiling(x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float round(float x) => (float)System.Math.Round(x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static void sincos(float x, out float s, out float c) { s = sin(x); c = cos(x); }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool isfinite(float x) => abs(x) < float.PositiveInfinity;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool isnan(float x) => (asuint(x) & 0x7FFFFFFF) > 0x7F800000;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static uint asuint(float x) => (uint)BitConverter.SingleToInt32Bits(x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int asint(float x) => BitConverter.SingleToInt32Bits(x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float asfloat(uint x) => BitConverter.Int32BitsToSingle((int)x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float asfloat(int x) => BitConverter.Int32BitsToSingle(x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static double sqrt(double x) => System.Math.Sqrt(x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static double abs(double x) => BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(x) & 0x7FFFFFFFFFFFFFFF);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static double max(double a, double b) => double.IsNaN(b) || a > b ? a : b;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static double min(double a, double b) => double.IsNaN(b) || a < b ? a : b;

        // ---- bool vectors
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool any(bool3 x) => x.x || x.y || x.z;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool all(bool3 x) => x.x && x.y && x.z;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool any(bool4 x) => x.x || x.y || x.z || x.w;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool all(bool4 x) => x.x && x.y && x.z && x.w;

        // ---- float3
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float dot(float3 a, float3 b) => a.x * b.x + a.y * b.y + a.z * b.z;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 cross(float3 a, float3 b) => (a * b.yzx - a.yzx * b).yzx;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float lengthsq(float3 x) => dot(x, x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float length(float3 x) => sqrt(dot(x, x));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float distance(float3 a, float3 b) => length(b - a);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float distancesq(float3 a, float3 b) => lengthsq(b - a);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 normalize(float3 x) => rsqrt(dot(x, x)) * x;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 normalizesafe(float3 x, float3 defaultvalue = default)
        {
            float len = dot(x, x);
            return select(defaultvalue, x * rsqrt(len), len > FLT_MIN_NORMAL);
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 select(float3 a, float3 b, bool c) => c ? b : a;
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.select.html#Unity_Mathematics_math_select_Unity_Mathematics_float3_Unity_Mathematics_float3_Unity_Mathematics_bool3_
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 select(float3 a, float3 b, bool3 c) => new float3(c.x ? b.x : a.x, c.y ? b.y : a.y, c.z ? b.z : a.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 abs(float3 x) => new float3(abs(x.x), abs(x.y), abs(x.z));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 min(float3 a, float3 b) => new float3(min(a.x, b.x), min(a.y, b.y), min(a.z, b.z));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 max(float3 a, float3 b) => new float3(max(a.x, b.x), max(a.y, b.y), max(a.z, b.z));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 clamp(float3 x, float3 a, float3 b) => max(a, min(b, x));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 lerp(float3 a, float3 b, float t) => a + t * (b - a);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 sign(float3 x) => new float3(sign(x.x), sign(x.y), sign(x.z));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 floor(float3 x) => new float3(floor(x.x), floor(x.y), floor(x.z));
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.round.html#Unity_Mathematics_math_round_Unity_Mathematics_float3_
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 round(float3 x) => new float3(round(x.x), round(x.y), round(x.z));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float csum(float3 x) => x.x + x.y + x.z;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float cmax(float3 x) => max(max(x.x, x.y), x.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float cmin(float3 x) => min(min(x.x, x.y), x.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 isfinite(float3 x) => new bool3(isfinite(x.x), isfinite(x.y), isfinite(x.z));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 isnan(float3 x) => new bool3(isnan(x.x), isnan(x.y), isnan(x.z));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int3 int3(float3 v) => new int3((int)v.x, (int)v.y, (int)v.z);

        // ---- float4
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float dot(float4 a, float4 b) => a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float length(float4 x) => sqrt(dot(x, x));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float lengthsq(float4 x) => dot(x, x);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 normalize(float4 x) => rsqrt(dot(x, x)) * x;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 select(float4 a, float4 b, bool c) => c ? b : a;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 abs(float4 x) => new float4(abs(x.x), abs(x.y), abs(x.z), abs(x.w));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool4 isfinite(float4 x) => new bool4(isfinite(x.x), isfinite(x.y), isfinite(x.z), isfinite(x.w));

        // ---- float3x3
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 mul(float3x3 a, float3 b) => a.c0 * b.x + a.c1 * b.y + a.c2 * b.z;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3x3 mul(float3x3 a, float3x3 b) => new float3x3(mul(a, b.c0), mul(a, b.c1), mul(a, b.c2));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3x3 transpose(float3x3 v) =>
            new float3x3(v.c0.x, v.c0.y, v.c0.z, v.c1.x, v.c1.y, v.c1.z, v.c2.x, v.c2.y, v.c2.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float determinant(float3x3 m)
        {
            float3 c0 = m.c0, c1 = m.c1, c2 = m.c2;
            float m00 = c1.y * c2.z - c1.z * c2.y;
            float m01 = c0.y * c2.z - c0.z * c2.y;
            float m02 = c0.y * c1.z - c0.z * c1.y;
            return c0.x * m00 - c1.x * m01 + c2.x * m02;
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3x3 inverse(float3x3 m)
        {
            float3 c0 = m.c0, c1 = m.c1, c2 = m.c2;
            float3 t0 = new float3(c1.x, c2.x, c0.x), t1 = new float3(c1.y, c2.y, c0.y), t2 = new float3(c1.z, c2.z, c0.z);
            float3 m0 = t1 * t2.yzx - t1.yzx * t2;
            float3 m1 = t0.yzx * t2 - t0 * t2.yzx;
            float3 m2 = t0 * t1.yzx - t0.yzx * t1;
            float rcpDet = 1.0f / csum(t0.zxy * m0);
            return new float3x3(m0, m1, m2) * rcpDet;
        }

        // ---- quaternion
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float dot(quaternion a, quaternion b) => dot(a.value, b.value);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float length(quaternion q) => sqrt(dot(q.value, q.value));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float lengthsq(quaternion q) => dot(q.value, q.value);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static quaternion normalize(quaternion q) => new quaternion(rsqrt(dot(q.value, q.value)) * q.value);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static quaternion normalizesafe(quaternion q)
        {
            float len = dot(q.value, q.value);
            return new quaternion(select(Mathematics.quaternion.identity.value, q.value * rsqrt(len), len > FLT_MIN_NORMAL));
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static quaternion conjugate(quaternion q) => new quaternion(-q.value.x, -q.value.y, -q.value.z, q.value.w);
        /// <summary>rcp(|q|²)·q, then the vector part negated (Unity's order of operations).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static quaternion inverse(quaternion q)
        {
            float4 x = q.value;
            return new quaternion(rcp(dot(x, x)) * x * new float4(-1.0f, -1.0f, -1.0f, 1.0f));
        }
        /// <summary>
        /// Hamilton product a·b (apply b, then a), evaluated as Unity does:
        /// a.wwww·b + (a.xyzx·b.wwwx + a.yzxy·b.zxyy)·(1, 1, 1, −1) − a.zxyz·b.yzxz.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static quaternion mul(quaternion a, quaternion b)
        {
            float4 p = a.value, q = b.value;
            float4 wwww = new float4(p.w) * q;
            float4 sum = new float4(p.x * q.w, p.y * q.w, p.z * q.w, p.x * q.x)
                         + new float4(p.y * q.z, p.z * q.x, p.x * q.y, p.y * q.y);
            float4 last = new float4(p.z * q.y, p.x * q.z, p.y * q.x, p.z * q.z);
            return new quaternion(wwww + sum * new float4(1.0f, 1.0f, 1.0f, -1.0f) - last);
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 rotate(quaternion q, float3 v)
        {
            float3 t = 2f * cross(q.value.xyz, v);
            return v + q.value.w * t + cross(q.value.xyz, t);
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 mul(quaternion q, float3 v) => rotate(q, v);

        // ---- hashes (what GetHashCode returns, cast to int): csum(asuint(v) * primes) + prime, wrapping
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.hash.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static uint hash(float2 v) =>
            unchecked(asuint(v.x) * 0xFA3A3285u + asuint(v.y) * 0xAD55999Du + 0xDCDD5341u);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static uint hash(float3 v) =>
            unchecked(asuint(v.x) * 0x9B13B92Du + asuint(v.y) * 0x4ABF0813u + asuint(v.z) * 0x86068063u + 0xD75513F9u);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static uint hash(float4 v) =>
            unchecked(asuint(v.x) * 0xE69626FFu + asuint(v.y) * 0xBD010EEBu + asuint(v.z) * 0x9CEDE1D1u + asuint(v.w) * 0x43BE0B51u + 0xAF836EE1u);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static uint hash(int3 v) =>
            unchecked((uint)v.x * 0x4C7F6DD1u + (uint)v.y * 0x4822A3E9u + (uint)v.z * 0xAAC3C25Du + 0xD21D0945u);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static uint hash(float3x3 v) =>
            unchecked(asuint(v.c0.x) * 0x713BD06Fu + asuint(v.c1.x) * 0xB5D0BF63u + asuint(v.c2.x) * 0x56A1530Du
                      + asuint(v.c0.y) * 0x753AD6ADu + asuint(v.c1.y) * 0xF9102C5Fu + asuint(v.c2.y) * 0x804B722Du
                      + asuint(v.c0.z) * 0xD19764C7u + asuint(v.c1.z) * 0x9881FB9Fu + asuint(v.c2.z) * 0x738E50E5u
                      + 0x4FC93C25u);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static uint hash(quaternion q) => hash(q.value);
    }
}
