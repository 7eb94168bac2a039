// Stand-in vector types. Semantics per the Unity.Mathematics 1.3 API reference:
// https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.float3.html (float2, float4, bool3, int3 alike)
// Members follow com.unity.mathematics 1.3.2 (Unity.Mathematics/float3.gen.cs and the other *.gen.cs files):
// component-wise operators, swizzles with setters, a by-value indexer, GetHashCode = (int)math.hash(this).
using System;
using System.Runtime.CompilerServices;

namespace Unity.Mathematics
{
    [Serializable]
    public partial struct float2 : IEquatable<float2>
    {
        public float x, y;
        public static readonly float2 zero;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public float2(float x, float y) { this.x = x; this.y = y; }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public float2(float v) { x = v; y = v; }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static implicit operator float2(float v) => new float2(v);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float2 operator +(float2 a, float2 b) => new float2(a.x + b.x, a.y + b.y);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float2 operator -(float2 a, float2 b) => new float2(a.x - b.x, a.y - b.y);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float2 operator *(float2 a, float2 b) => new float2(a.x * b.x, a.y * b.y);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float2 operator /(float2 a, float2 b) => new float2(a.x / b.x, a.y / b.y);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float2 operator -(float2 a) => new float2(-a.x, -a.y);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public bool Equals(float2 o) => x == o.x && y == o.y;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public override bool Equals(object o) => o is float2 v && Equals(v);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public override int GetHashCode() => (int)math.hash(this);
        public override string ToString() => $"float2({x}f, {y}f)";
    }

    [Serializable]
    public partial struct float3 : IEquatable<float3>, IFormattable
    {
        public float x, y, z;
        public static readonly float3 zero;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public float3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public float3(float v) { x = v; y = v; z = v; }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public float3(float2 xy, float z) { x = xy.x; y = xy.y; this.z = z; }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static implicit operator float3(float v) => new float3(v);
        public float2 xy { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => new float2(x, y); [MethodImpl(MethodImplOptions.AggressiveInlining)] set { x = value.x; y = value.y; } }
        public float2 xz { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => new float2(x, z); [MethodImpl(MethodImplOptions.AggressiveInlining)] set { x = value.x; z = value.y; } }
        public float3 yzx { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => new float3(y, z, x); [MethodImpl(MethodImplOptions.AggressiveInlining)] set { y = value.x; z = value.y; x = value.z; } }
        public float3 zxy { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => new float3(z, x, y); [MethodImpl(MethodImplOptions.AggressiveInlining)] set { z = value.x; x = value.y; y = value.z; } }

        /// <summary>
        /// The element at <paramref name="index"/>, by value with a setter, as in Unity.Mathematics 1.3.2
        /// (<c>unsafe public float this[int index] { get; set; }</c>, not a ref return). The range check is Unity's
        /// ENABLE_UNITY_COLLECTIONS_CHECKS one, on in the Editor.
        /// https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.float3.Item.html
        /// </summary>
        public unsafe float this[int index]
        {
            get
            {
                if ((uint)index >= 3) throw new ArgumentException("index must be between[0...2]");
                fixed (float3* array = &this) { return ((float*)array)[index]; }
            }
            set
            {
                if ((uint)index >= 3) throw new ArgumentException("index must be between[0...2]");
                fixed (float* array = &x) { array[index] = value; }
            }
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 operator +(float3 a, float3 b) => new float3(a.x + b.x, a.y + b.y, a.z + b.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 operator -(float3 a, float3 b) => new float3(a.x - b.x, a.y - b.y, a.z - b.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 operator *(float3 a, float3 b) => new float3(a.x * b.x, a.y * b.y, a.z * b.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 operator /(float3 a, float3 b) => new float3(a.x / b.x, a.y / b.y, a.z / b.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 operator +(float3 a, float b) => new float3(a.x + b, a.y + b, a.z + b);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 operator -(float3 a, float b) => new float3(a.x - b, a.y - b, a.z - b);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 operator *(float3 a, float b) => new float3(a.x * b, a.y * b, a.z * b);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 operator *(float a, float3 b) => new float3(a * b.x, a * b.y, a * b.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 operator /(float3 a, float b) => new float3(a.x / b, a.y / b, a.z / b);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 operator /(float a, float3 b) => new float3(a / b.x, a / b.y, a / b.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float3 operator -(float3 a) => new float3(-a.x, -a.y, -a.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator <(float3 a, float3 b) => new bool3(a.x < b.x, a.y < b.y, a.z < b.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator >(float3 a, float3 b) => new bool3(a.x > b.x, a.y > b.y, a.z > b.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator <=(float3 a, float3 b) => new bool3(a.x <= b.x, a.y <= b.y, a.z <= b.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator >=(float3 a, float3 b) => new bool3(a.x >= b.x, a.y >= b.y, a.z >= b.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator ==(float3 a, float3 b) => new bool3(a.x == b.x, a.y == b.y, a.z == b.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static bool3 operator !=(float3 a, float3 b) => new bool3(a.x != b.x, a.y != b.y, a.z != b.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public bool Equals(float3 o) => x == o.x && y == o.y && z == o.z;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public override bool Equals(object o) => o is float3 v && Equals(v);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public override int GetHashCode() => (int)math.hash(this);
        public override string ToString() => $"float3({x}f, {y}f, {z}f)";
        public string ToString(string format, IFormatProvider formatProvider) =>
            $"float3({x.ToString(format, formatProvider)}f, {y.ToString(format, formatProvider)}f, {z.ToString(format, formatProvider)}f)";
    }

    [Serializable]
    public partial struct float4 : IEquatable<float4>
    {
        public float x, y, z, w;
        public static readonly float4 zero;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public float4(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public float4(float3 xyz, float w) { x = xyz.x; y = xyz.y; z = xyz.z; this.w = w; }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public float4(float v) { x = v; y = v; z = v; w = v; }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static implicit operator float4(float v) => new float4(v);
        public float3 xyz { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => new float3(x, y, z); [MethodImpl(MethodImplOptions.AggressiveInlining)] set { x = value.x; y = value.y; z = value.z; } }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 operator +(float4 a, float4 b) => new float4(a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 operator -(float4 a, float4 b) => new float4(a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 operator *(float4 a, float4 b) => new float4(a.x * b.x, a.y * b.y, a.z * b.z, a.w * b.w);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 operator *(float4 a, float b) => new float4(a.x * b, a.y * b, a.z * b, a.w * b);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 operator *(float a, float4 b) => new float4(a * b.x, a * b.y, a * b.z, a * b.w);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 operator /(float4 a, float b) => new float4(a.x / b, a.y / b, a.z / b, a.w / b);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static float4 operator -(float4 a) => new float4(-a.x, -a.y, -a.z, -a.w);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public bool Equals(float4 o) => x == o.x && y == o.y && z == o.z && w == o.w;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public override bool Equals(object o) => o is float4 v && Equals(v);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public override int GetHashCode() => (int)math.hash(this);
        public override string ToString() => $"float4({x}f, {y}f, {z}f, {w}f)";
    }

    [Serializable]
    public partial struct int3 : IEquatable<int3>
    {
        public int x, y, z;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public int3(int x, int y, int z) { this.x = x; this.y = y; this.z = z; }
        /// <summary>All components set to <paramref name="v"/> (https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.int3.-ctor.html).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public int3(int v) { x = v; y = v; z = v; }
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int3 operator *(int3 a, int b) => new int3(a.x * b, a.y * b, a.z * b);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int3 operator /(int3 a, int b) => new int3(a.x / b, a.y / b, a.z / b);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int3 operator +(int3 a, int3 b) => new int3(a.x + b.x, a.y + b.y, a.z + b.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public static int3 operator -(int3 a, int3 b) => new int3(a.x - b.x, a.y - b.y, a.z - b.z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public bool Equals(int3 o) => x == o.x && y == o.y && z == o.z;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public override bool Equals(object o) => o is int3 v && Equals(v);
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public override int GetHashCode() => (int)math.hash(this);
        public override string ToString() => $"int3({x}, {y}, {z})";
    }

    /// <summary>https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.int2.html</summary>
    [Serializable]
    public partial struct int2
    {
        public int x, y;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public int2(int x, int y) { this.x = x; this.y = y; }

        /// <summary>
        /// The element at <paramref name="index"/>, by value with a setter, as in Unity.Mathematics 1.3.2.
        /// https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.int2.Item.html
        /// </summary>
        public unsafe int this[int index]
        {
            get
            {
                if ((uint)index >= 2) throw new ArgumentException("index must be between[0...1]");
                fixed (int2* array = &this) { return ((int*)array)[index]; }
            }
            set
            {
                if ((uint)index >= 2) throw new ArgumentException("index must be between[0...1]");
                fixed (int* array = &x) { array[index] = value; }
            }
        }

        public override string ToString() => $"int2({x}, {y})";
    }

    /// <summary>https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.int4.html</summary>
    [Serializable]
    public partial struct int4
    {
        public int x, y, z, w;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public int4(int x, int y, int z, int w) { this.x = x; this.y = y; this.z = z; this.w = w; }

        /// <summary>
        /// The element at <paramref name="index"/>, by value with a setter, as in Unity.Mathematics 1.3.2.
        /// https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.int4.Item.html
        /// </summary>
        public unsafe int this[int index]
        {
            get
            {
                if ((uint)index >= 4) throw new ArgumentException("index must be between[0...3]");
                fixed (int4* array = &this) { return ((int*)array)[index]; }
            }
            set
            {
                if ((uint)index >= 4) throw new ArgumentException("index must be between[0...3]");
                fixed (int* array = &x) { array[index] = value; }
            }
        }

        public override string ToString() => $"int4({x}, {y}, {z}, {w})";
    }

    [Serializable]
    public partial struct bool3
    {
        public bool x, y, z;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public bool3(bool x, bool y, bool z) { this.x = x; this.y = y; this.z = z; }
    }

    [Serializable]
    public partial struct bool4
    {
        public bool x, y, z, w;
        [MethodImpl(MethodImplOptions.AggressiveInlining)] public bool4(bool x, bool y, bool z, bool w) { this.x = x; this.y = y; this.z = z; this.w = w; }
    }
}
