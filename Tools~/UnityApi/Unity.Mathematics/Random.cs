// Stand-in for Unity.Mathematics.Random (xorshift32 generator). Semantics per
// https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.html
// Every member is written from com.unity.mathematics 1.3.2 Unity.Mathematics/random.cs: the same state
// sequence, the same draws in the same order and the same float operations, so a seed gives the same
// numbers here as in Unity. The seed checks behave as in the Editor, where ENABLE_UNITY_COLLECTIONS_CHECKS
// is defined: a zero seed or a zero state throws.
using System;

namespace Unity.Mathematics
{
    [Serializable]
    public partial struct Random
    {
        public uint state;

        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.-ctor.html
        public Random(uint seed)
        {
            state = seed;
            CheckInitState();
            NextState();
        }

        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.InitState.html
        // (no seed check of its own: a zero seed fails in NextState, as in Unity)
        public void InitState(uint seed = 0x6E624EB7u)
        {
            state = seed;
            NextState();
        }

        /// <summary>Returns the current state and advances it by one xorshift32 step (13, 17, 5).</summary>
        private uint NextState()
        {
            CheckState();
            uint t = state;
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            return t;
        }

        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.NextBool.html
        public bool NextBool() => (NextState() & 1) == 1;

        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.NextUInt.html
        public uint NextUInt() => NextState() - 1u;

        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.NextUInt.html
        public uint NextUInt(uint max) => (uint)((NextState() * (ulong)max) >> 32);

        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.NextInt.html
        public int NextInt(int min, int max)
        {
            CheckNextIntMinMax(min, max);
            uint range = (uint)(max - min);
            return (int)(NextState() * (ulong)range >> 32) + min;
        }

        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.NextFloat.html
        // 23 random mantissa bits under the exponent of 1.0, minus 1: uniform in [0, 1).
        public float NextFloat() => math.asfloat(0x3f800000u | (NextState() >> 9)) - 1.0f;

        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.NextFloat.html
        public float NextFloat(float min, float max) => NextFloat() * (max - min) + min;

        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.NextFloat2.html
        // (Unity draws x, then y: uint2(NextState(), NextState()))
        public float2 NextFloat2()
        {
            float x = NextFloat();
            float y = NextFloat();
            return new float2(x, y);
        }

        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.NextFloat3.html
        // (Unity draws x, then y, then z)
        public float3 NextFloat3()
        {
            float x = NextFloat();
            float y = NextFloat();
            float z = NextFloat();
            return new float3(x, y, z);
        }

        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.NextFloat3.html#Unity_Mathematics_Random_NextFloat3_Unity_Mathematics_float3_
        public float3 NextFloat3(float3 max) => NextFloat3() * max;

        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.NextFloat3.html#Unity_Mathematics_Random_NextFloat3_Unity_Mathematics_float3_Unity_Mathematics_float3_
        public float3 NextFloat3(float3 min, float3 max) => NextFloat3() * (max - min) + min;

        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.NextFloat3Direction.html
        // z uniform in [-1, 1) and an angle uniform in [0, 2π): uniform on the unit sphere.
        public float3 NextFloat3Direction()
        {
            float2 rnd = NextFloat2();
            float z = rnd.x * 2.0f - 1.0f;
            float r = math.sqrt(math.max(1.0f - z * z, 0.0f));
            float angle = rnd.y * math.PI * 2.0f;
            math.sincos(angle, out float s, out float c);
            return new float3(c * r, s * r, z);
        }

        // https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.NextQuaternionRotation.html
        // Shoemake's uniform rotation from (θ, ρ, u) = NextFloat3(2π, 2π, 1) (the max-only overload), with w ≥ 0.
        public quaternion NextQuaternionRotation()
        {
            float3 rnd = NextFloat3(new float3(2.0f * math.PI, 2.0f * math.PI, 1.0f));
            float u1 = rnd.z;
            float i = math.sqrt(1.0f - u1);
            float j = math.sqrt(u1);
            math.sincos(rnd.x, out float sinTheta, out float cosTheta);
            math.sincos(rnd.y, out float sinRho, out float cosRho);
            var q = new quaternion(i * sinTheta, i * cosTheta, j * sinRho, j * cosRho);
            return new quaternion(q.value.w < 0.0f ? -q.value : q.value);
        }

        private void CheckInitState()
        {
            if (state == 0)
                throw new ArgumentException("Seed must be non-zero");
        }

        private void CheckState()
        {
            if (state == 0)
                throw new ArgumentException("Invalid state 0. Random object has not been properly initialized");
        }

        private static void CheckNextIntMinMax(int min, int max)
        {
            if (min > max)
                throw new ArgumentException("min must be less than or equal to max");
        }
    }
}
