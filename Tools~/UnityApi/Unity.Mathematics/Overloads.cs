// Overloads com.unity.mathematics 1.3.2 has beside the ones the package calls, declared so that a call Unity binds to
// them binds to them here too, instead of silently converting to another overload (math.min(long, long) to the float
// one, math.length(float) to length(float3)); OverloadConformanceTests finds the ones still missing. Same formulas as
// the package source (math.cs, float2/3/4.gen.cs, int3.gen.cs, math_unity_conversion.cs).

using System.Runtime.CompilerServices;

namespace Unity.Mathematics
{
    public static partial class math
    {
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.abs.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static long abs(long x) => max(-x, x);
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.min.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static long min(long x, long y) => x < y ? x : y;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static ulong min(ulong x, ulong y) => x < y ? x : y;
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.max.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static long max(long x, long y) => x > y ? x : y;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static ulong max(ulong x, ulong y) => x > y ? x : y;
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.clamp.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static long clamp(long valueToClamp, long lowerBound, long upperBound) => max(lowerBound, min(upperBound, valueToClamp));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static uint clamp(uint valueToClamp, uint lowerBound, uint upperBound) => max(lowerBound, min(upperBound, valueToClamp));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static ulong clamp(ulong valueToClamp, ulong lowerBound, ulong upperBound) => max(lowerBound, min(upperBound, valueToClamp));
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.select.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int select(int falseValue, int trueValue, bool test) => test ? trueValue : falseValue;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static uint select(uint falseValue, uint trueValue, bool test) => test ? trueValue : falseValue;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static long select(long falseValue, long trueValue, bool test) => test ? trueValue : falseValue;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static ulong select(ulong falseValue, ulong trueValue, bool test) => test ? trueValue : falseValue;
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.sign.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int sign(int x) => (x > 0 ? 1 : 0) - (x < 0 ? 1 : 0);
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.asint.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int asint(uint x) => unchecked((int)x);
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.asuint.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static uint asuint(int x) => unchecked((uint)x);
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.dot.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float dot(float x, float y) => x * y;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int dot(int x, int y) => x * y;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static uint dot(uint x, uint y) => x * y;
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.length.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float length(float x) => abs(x);
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.lengthsq.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float lengthsq(float x) => x * x;
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.distance.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float distance(float x, float y) => abs(y - x);
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.distancesq.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float distancesq(float x, float y) => (y - x) * (y - x);
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.float3.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 float3(int v) => new float3(v);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 float3(uint v) => new float3(v);
        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.math.int3.html
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int3 int3(int v) => new int3(v, v, v);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int3 int3(uint v) => new int3(unchecked((int)v), unchecked((int)v), unchecked((int)v));
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int3 int3(float v) => new int3((int)v, (int)v, (int)v);
    }

    // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.float2.html
    public partial struct float2
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float2 operator +(float2 lhs, float rhs) => new float2(lhs.x + rhs, lhs.y + rhs);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float2 operator +(float lhs, float2 rhs) => new float2(lhs + rhs.x, lhs + rhs.y);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float2 operator -(float2 lhs, float rhs) => new float2(lhs.x - rhs, lhs.y - rhs);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float2 operator -(float lhs, float2 rhs) => new float2(lhs - rhs.x, lhs - rhs.y);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float2 operator *(float2 lhs, float rhs) => new float2(lhs.x * rhs, lhs.y * rhs);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float2 operator *(float lhs, float2 rhs) => new float2(lhs * rhs.x, lhs * rhs.y);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float2 operator /(float2 lhs, float rhs) => new float2(lhs.x / rhs, lhs.y / rhs);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float2 operator /(float lhs, float2 rhs) => new float2(lhs / rhs.x, lhs / rhs.y);
    }

    // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.float3.html
    public partial struct float3
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public float3(int v) { x = v; y = v; z = v; }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public float3(uint v) { x = v; y = v; z = v; }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 operator +(float lhs, float3 rhs) => new float3(lhs + rhs.x, lhs + rhs.y, lhs + rhs.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 operator -(float lhs, float3 rhs) => new float3(lhs - rhs.x, lhs - rhs.y, lhs - rhs.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator <(float3 lhs, float rhs) => new bool3(lhs.x < rhs, lhs.y < rhs, lhs.z < rhs);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator <(float lhs, float3 rhs) => new bool3(lhs < rhs.x, lhs < rhs.y, lhs < rhs.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator <=(float3 lhs, float rhs) => new bool3(lhs.x <= rhs, lhs.y <= rhs, lhs.z <= rhs);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator <=(float lhs, float3 rhs) => new bool3(lhs <= rhs.x, lhs <= rhs.y, lhs <= rhs.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator >(float3 lhs, float rhs) => new bool3(lhs.x > rhs, lhs.y > rhs, lhs.z > rhs);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator >(float lhs, float3 rhs) => new bool3(lhs > rhs.x, lhs > rhs.y, lhs > rhs.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator >=(float3 lhs, float rhs) => new bool3(lhs.x >= rhs, lhs.y >= rhs, lhs.z >= rhs);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator >=(float lhs, float3 rhs) => new bool3(lhs >= rhs.x, lhs >= rhs.y, lhs >= rhs.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator ==(float3 lhs, float rhs) => new bool3(lhs.x == rhs, lhs.y == rhs, lhs.z == rhs);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator ==(float lhs, float3 rhs) => new bool3(lhs == rhs.x, lhs == rhs.y, lhs == rhs.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator !=(float3 lhs, float rhs) => new bool3(lhs.x != rhs, lhs.y != rhs, lhs.z != rhs);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator !=(float lhs, float3 rhs) => new bool3(lhs != rhs.x, lhs != rhs.y, lhs != rhs.z);
    }

    // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.float4.html
    public partial struct float4
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 operator +(float4 lhs, float rhs) => new float4(lhs.x + rhs, lhs.y + rhs, lhs.z + rhs, lhs.w + rhs);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 operator +(float lhs, float4 rhs) => new float4(lhs + rhs.x, lhs + rhs.y, lhs + rhs.z, lhs + rhs.w);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 operator -(float4 lhs, float rhs) => new float4(lhs.x - rhs, lhs.y - rhs, lhs.z - rhs, lhs.w - rhs);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 operator -(float lhs, float4 rhs) => new float4(lhs - rhs.x, lhs - rhs.y, lhs - rhs.z, lhs - rhs.w);
    }
}
