using System;
using System.Collections.Generic;

// The attribute the check looks for, declared here so that the self-test's fixtures are Burst entry points.
namespace Unity.Burst
{
    [AttributeUsage(AttributeTargets.Struct | AttributeTargets.Class | AttributeTargets.Method)]
    sealed class BurstCompileAttribute : Attribute { }
}

// Debug's logging as UnityEngine declares it, for the fixtures.
namespace UnityEngine
{
    static class Debug
    {
        public static void Log(object message) => System.Console.WriteLine(message);
        public static void LogWarning(object message) => System.Console.WriteLine(message);
    }
}

namespace SoftBodyDynamics.Tools.BurstCheck.Fixtures
{
    using Unity.Burst;

    /// <summary>
    /// Jobs for the self-test (<c>burstcheck.sh --self-test</c>): each breaks one rule, named by the text its problem must
    /// contain (<see cref="ExpectAttribute"/>); <see cref="Clean"/> breaks none, though it uses what Burst allows.
    /// </summary>
    [AttributeUsage(AttributeTargets.Struct | AttributeTargets.Method)]
    sealed class ExpectAttribute : Attribute
    {
        public readonly string Problem;
        public ExpectAttribute(string problem) { Problem = problem; }
    }

    interface IOffset { float Of(float a, float b); }

    struct Direct : IOffset { public float Of(float a, float b) => a - b; }

    interface IScale { float Of(float a); }

    struct Allocating : IScale { public float Of(float a) => new float[] { a }[0]; }

    static class Helpers
    {
        public static readonly float[] Table = { 1f, 2f };
        public static int Counter;

        public static float Generic<T>(T offset, float a) where T : struct, IOffset => offset.Of(a, 1f);

        public static float Scaled<T>(T scale, float a) where T : struct, IScale => scale.Of(a);

        public static float Checked(float x)
        {
            if (!(x >= 0f))
                throw new ArgumentException("x must be non-negative");
            return (float)Math.Sqrt(x);
        }
    }

    [BurstCompile, Expect("")]
    struct Clean
    {
        public float Value;
        public void Execute()
        {
            Span<float> scratch = stackalloc float[4];
            scratch[0] = Helpers.Table[1];
            try { Value = (float)Math.Sqrt(Helpers.Checked(Value)) + Helpers.Generic(new Direct(), scratch[0]); }
            finally { Value += 1f; }
        }
    }

    [BurstCompile, Expect("new managed array")]
    struct NewArray { public void Execute() { var a = new int[3]; a[0] = 1; } }

    [BurstCompile, Expect("new managed array")]
    struct ThroughAGenericArgument { public float Value; public void Execute() => Value = Helpers.Scaled(new Allocating(), 2f); }

    [BurstCompile, Expect("new managed object System.Collections.Generic.List")]
    struct NewList { public void Execute() { var l = new List<int>(); _ = l; } }

    [BurstCompile, Expect("boxing")]
    struct Boxing { public int Value; public void Execute() { object o = Value; Value = o.GetHashCode(); } }

    [BurstCompile, Expect("try/catch")]
    struct Catching
    {
        public float Value;
        public void Execute() { try { Value = Helpers.Checked(Value); } catch (ArgumentException) { Value = 0f; } }
    }

    [BurstCompile, Expect("")]
    struct Logging
    {
        public int Count;
        public float Time;
        public void Execute()
        {
            Count++;
            Time += 1f;
            UnityEngine.Debug.LogWarning("a literal");
            UnityEngine.Debug.LogWarning(string.Format("{0} of {1}", Count, Time));
            UnityEngine.Debug.LogWarning(string.Format("{0} {1} {2} {3}", Count, Count, Time, Time));
        }
    }

    [BurstCompile, Expect("log argument of type")]
    struct LoggingAStruct
    {
        public Direct Value;
        public void Execute() { Value = default; UnityEngine.Debug.Log(string.Format("{0}", Value)); }
    }

    [BurstCompile, Expect("outside a throw")]
    struct Formatting { public int Value; public void Execute() { Value = string.Concat("a", "b").Length; } }

    [BurstCompile, Expect("static field")]
    struct WritingAStatic { public void Execute() => Helpers.Counter++; }

    [BurstCompile, Expect("job field")]
    struct ManagedField { public int[] Data; public void Execute() => Data = null; }

    [BurstCompile, Expect("System.Int32.ToString, which Burst does not support")]
    struct PrimitiveToString { public int Value; public void Execute() => Value = Value.ToString().Length; }

    [BurstCompile, Expect("which Burst does not support")]
    struct ConsoleCall { public void Execute() => Console.Beep(); }

    struct SystemLike
    {
        [BurstCompile, Expect("delegate")]
        public static int OnUpdate() { Func<int> f = Helpers.Table.GetHashCode; return f(); }
    }
}
