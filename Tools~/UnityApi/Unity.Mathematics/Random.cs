// Stand-in for Unity.Mathematics.Random (xorshift32 generator). Semantics per
// https://docs.unity3d.com/Packages/com.unity.mathematics@1.3/api/Unity.Mathematics.Random.html
// The seed must be non-zero.
using System;

namespace Unity.Mathematics
{
    [Serializable]
    public partial struct Random
    {
        public uint state;

        public Random(uint seed)
        {
            if (seed == 0) throw new ArgumentException("Seed must be non-zero");
            state = seed;
            NextState();
        }

        public void InitState(uint seed = 0x6E624EB7u)
        {
            if (seed == 0) throw new ArgumentException("Seed must be non-zero");
            state = seed;
            NextState();
        }

        private uint NextState()
        {
            uint t = state;
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            return t;
        }

        public uint NextUInt() => NextState() - 1u;
        public uint NextUInt(uint max) => (uint)(((ulong)NextState() * max) >> 32);
        public int NextInt(int min, int max) => min + (int)(((ulong)NextState() * (ulong)(uint)(max - min)) >> 32);
        public float NextFloat() => math.asfloat(0x3f800000u | (NextState() >> 9)) - 1.0f;
        public float NextFloat(float min, float max) => NextFloat() * (max - min) + min;
        public float3 NextFloat3() => new float3(NextFloat(), NextFloat(), NextFloat());
        public float3 NextFloat3(float3 min, float3 max) => NextFloat3() * (max - min) + min;
        public float3 NextFloat3Direction()
        {
            float z = NextFloat() * 2f - 1f;
            float r = math.sqrt(math.max(1f - z * z, 0f));
            math.sincos(NextFloat() * 2f * math.PI, out float s, out float c);
            return new float3(c * r, s * r, z);
        }
        public quaternion NextQuaternionRotation()
        {
            float3 rnd = NextFloat3(new float3(2f * math.PI, 2f * math.PI, 1f), default);
            float u1 = rnd.z;
            float r1 = math.sqrt(1f - u1), r2 = math.sqrt(u1);
            math.sincos(rnd.x, out float s1, out float c1);
            math.sincos(rnd.y, out float s2, out float c2);
            var q = new quaternion(s1 * r1, c1 * r1, s2 * r2, c2 * r2);
            return new quaternion(q.value.w < 0f ? -q.value : q.value);
        }
        public bool NextBool() => (NextState() & 1) == 1;
    }
}
