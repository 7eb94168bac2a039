using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>The families of A = Σ mᵢ pᵢ qᵢᵀ that rotation extraction must survive (stability plan, tests 1–2).</summary>
    public enum RotationCaseKind
    {
        /// <summary>Rest cloud rotated and stretched (det F &gt; 0), well conditioned.</summary>
        RotatedStretched,
        /// <summary>A with independent random entries (either sign of det).</summary>
        RandomMatrix,
        /// <summary>Rest cloud mirrored through a random plane (det F &lt; 0): an inverted cluster.</summary>
        Mirrored,
        /// <summary>Planar rest cloud (cloth cluster): A has rank 2.</summary>
        Coplanar,
        /// <summary>Collinear rest cloud (rope cluster): A has rank 1.</summary>
        Collinear,
        /// <summary>All particles at one point: A = 0.</summary>
        Coincident,
        /// <summary>Cloud flattened to 1e-4 of its size along one axis.</summary>
        FlattenedTo1em4,
        /// <summary>Cloud flattened through itself, to −1e-4 along one axis (barely inverted).</summary>
        FlattenedThroughMinus1em4,
    }

    /// <summary>One generated case: the matrix, how it was made, and the warm start a previous step would give.</summary>
    public struct RotationCase
    {
        public uint Seed;
        public RotationCaseKind Kind;
        public float Scale;
        public float3x3 A;
        /// <summary>The float64 optimum rotated by a random angle of up to <see cref="RotationCases.WarmStartMaxAngle"/>.</summary>
        public quaternion WarmStart;

        public override string ToString() => $"seed {Seed} ({Kind}, scale {Scale:G3}): A = {A}";
    }

    /// <summary>
    /// Seeded generator of rotation-extraction inputs. Each case depends only on its own seed, so a
    /// failing case is reproduced by <see cref="Make(uint)"/> with the printed seed.
    /// </summary>
    public static class RotationCases
    {
        public const int PointsPerCluster = 12;
        /// <summary>Largest rotation between two steps in a warm start: 0.2 rad (12 rad/s at 60 Hz).</summary>
        public const float WarmStartMaxAngle = 0.2f;
        public const int KindCount = 8;

        /// <summary>The seed of the i-th case of a run that starts at <paramref name="baseSeed"/> (never 0).</summary>
        public static uint SeedOf(uint baseSeed, int index)
        {
            uint h = baseSeed * 0x9E3779B9u ^ (uint)index * 0x85EBCA6Bu;
            h ^= h >> 16; h *= 0x7FEB352Du; h ^= h >> 15; h *= 0x846CA68Bu; h ^= h >> 16;
            return h == 0 ? 1u : h;
        }

        /// <summary>Builds the case of a given seed; its kind is chosen by the seed.</summary>
        public static RotationCase Make(uint seed)
        {
            var rng = new Random(seed);
            var kind = (RotationCaseKind)rng.NextInt(0, KindCount);
            return Make(seed, kind, ref rng);
        }

        /// <summary>Builds a case of the given kind from a seed.</summary>
        public static RotationCase Make(uint seed, RotationCaseKind kind)
        {
            var rng = new Random(seed);
            rng.NextInt(0, KindCount); // keep the stream aligned with Make(uint)
            return Make(seed, kind, ref rng);
        }

        static RotationCase Make(uint seed, RotationCaseKind kind, ref Random rng)
        {
            float scale = math.pow(10f, rng.NextFloat(-4f, 4f));
            float3x3 a;
            if (kind == RotationCaseKind.RandomMatrix)
            {
                a = new float3x3(rng.NextFloat3(-1f, 1f), rng.NextFloat3(-1f, 1f), rng.NextFloat3(-1f, 1f)) * (scale * scale);
            }
            else
            {
                // Deformation F = R · diag(s) · Wᵀ: random rotation R, stretches s, random axes W.
                var r = new float3x3(rng.NextQuaternionRotation());
                var w = new float3x3(rng.NextQuaternionRotation());
                float3 s = rng.NextFloat3(new float3(0.5f), new float3(2f));
                if (kind == RotationCaseKind.Mirrored) s.x = -s.x;
                if (kind == RotationCaseKind.FlattenedTo1em4) s.x = 1e-4f;
                if (kind == RotationCaseKind.FlattenedThroughMinus1em4) s.x = -1e-4f;
                float3x3 f = math.mul(r, math.mul(new float3x3(s.x, 0, 0, 0, s.y, 0, 0, 0, s.z), math.transpose(w)));

                float3 plane = rng.NextFloat3Direction();
                float3 line = rng.NextFloat3Direction();
                var rest = new float3[PointsPerCluster];
                var deformed = new float3[PointsPerCluster];
                var mass = new float[PointsPerCluster];
                for (int i = 0; i < PointsPerCluster; i++)
                {
                    float3 q = rng.NextFloat3(-1f, 1f);
                    if (kind == RotationCaseKind.Coplanar) q -= math.dot(q, plane) * plane;
                    if (kind == RotationCaseKind.Collinear) q = math.dot(q, line) * line;
                    if (kind == RotationCaseKind.Coincident) q = float3.zero;
                    mass[i] = rng.NextFloat(0.5f, 2f);
                    rest[i] = q * scale;
                    deformed[i] = math.mul(f, rest[i]);
                }
                // A = Σ mᵢ pᵢ qᵢᵀ exactly as shape matching forms it.
                a = ShapeMatching.Apq(deformed, mass, ShapeMatching.CenterOfMass(deformed, mass),
                    rest, ShapeMatching.CenterOfMass(rest, mass));
            }

            var reference = Svd3x3Double.Decompose(a);
            quaternion qRef = Svd3x3Double.RotationQuaternion(reference);
            float3 axis = rng.NextFloat3Direction();
            float angle = rng.NextFloat(0f, WarmStartMaxAngle);
            quaternion warm = math.normalize(math.mul(quaternion.AxisAngle(axis, angle), qRef));
            return new RotationCase { Seed = seed, Kind = kind, Scale = scale, A = a, WarmStart = warm };
        }
    }
}
