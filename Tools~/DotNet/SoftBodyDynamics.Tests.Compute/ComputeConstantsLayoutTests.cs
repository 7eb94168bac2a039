using System;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Runtime.InteropServices;
using NUnit.Framework;
using SoftBodyDynamics.Lavapipe;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Compute
{
    /// <summary>
    /// Each kernel family's constant buffer is declared twice, in HLSL and in C#: both declare the same fields, of the same
    /// types, in the same order, at the same byte offsets, and are the same size (a multiple of 16 bytes); every 3- or
    /// 4-vector starts a 16-byte row and every 2-vector an 8-byte boundary; and glslang's reflection of every kernel that
    /// reads the buffer places the members where the C# struct has them.
    /// </summary>
    public class ComputeConstantsLayoutTests
    {
        static string KernelsFolder => Path.Combine(Path.GetDirectoryName(LavapipeFluidSolver.ComputePath()), "Kernels");

        [Test]
        public void FluidConstants_HlslAndCSharpAgree() =>
            AssertSameLayout<FluidComputeConstants>("FluidComputeConstants.hlsl", FluidComputeConstants.BufferName, FluidComputeConstants.Bytes);

        [Test]
        public void SoftBodyConstants_HlslAndCSharpAgree() =>
            AssertSameLayout<SoftBodyComputeConstants>("SoftBodyComputeConstants.hlsl", SoftBodyComputeConstants.BufferName, SoftBodyComputeConstants.Bytes);

        [Test]
        public void SurfaceConstants_HlslAndCSharpAgree() =>
            AssertSameLayout<FluidSurfaceConstants>("FluidSurfaceConstants.hlsl", FluidSurfaceConstants.BufferName, FluidSurfaceConstants.Bytes);

        [Test]
        public void FluidConstants_ReflectedOffsetsAreTheCSharpOnes() =>
            AssertReflectionMatches<FluidComputeConstants>(LavapipeFluidSolver.ComputePath(), FluidComputeConstants.BufferName, FluidComputeConstants.Bytes);

        [Test]
        public void SoftBodyConstants_ReflectedOffsetsAreTheCSharpOnes() =>
            AssertReflectionMatches<SoftBodyComputeConstants>(LavapipeSoftBodyCommands.ComputePath(), SoftBodyComputeConstants.BufferName, SoftBodyComputeConstants.Bytes);

        [Test]
        public void SurfaceConstants_ReflectedOffsetsAreTheCSharpOnes() =>
            AssertReflectionMatches<FluidSurfaceConstants>(LavapipeFluidSurface.ComputePath(), FluidSurfaceConstants.BufferName, FluidSurfaceConstants.Bytes);

        static void AssertSameLayout<T>(string header, string bufferName, int bytes) where T : struct
        {
            HlslConstantBuffer hlsl = HlslConstantBuffer.Read(Path.Combine(KernelsFolder, header), bufferName);
            string[] expected = hlsl.Members.Select(m => $"{m.Type} {m.Name} @{m.Offset}").ToArray();
            string[] actual = CSharpFields<T>().Select(f => $"{HlslType(f.FieldType)} {f.Name} @{(int)Marshal.OffsetOf<T>(f.Name)}").ToArray();
            Assert.That(actual, Is.EqualTo(expected), $"the fields of {typeof(T).Name} against cbuffer {bufferName} in {header}");
            Assert.That(Marshal.SizeOf<T>(), Is.EqualTo(hlsl.Size), "struct size against the cbuffer's");
            Assert.That(bytes, Is.EqualTo(hlsl.Size), $"{typeof(T).Name}.Bytes");
            Assert.That(bytes % 16, Is.Zero, "a constant buffer's size is a multiple of 16 bytes");
            foreach (var (name, type, offset) in hlsl.Members)
            {
                if (type.EndsWith("3") || type.EndsWith("4"))
                    Assert.That(offset % 16, Is.Zero, $"{name}: a 3- or 4-vector starts a 16-byte row (std140 then gives the same offsets)");
                if (type.EndsWith("2"))
                    Assert.That(offset % 8, Is.Zero, $"{name}: a 2-vector starts on 8 bytes (std140 then gives the same offset)");
            }
        }

        static void AssertReflectionMatches<T>(string computePath, string bufferName, int bytes) where T : struct
        {
            string[] expected = CSharpFields<T>().Select(f => $"{f.Name} @{(int)Marshal.OffsetOf<T>(f.Name)}").ToArray();
            int readers = 0;
            foreach (CompiledKernel kernel in KernelCompiler.Compile(computePath))
            {
                if (!kernel.ConstantBlocks.TryGetValue(bufferName, out ConstantBlock block))
                    continue;
                readers++;
                Assert.That(block.Members.Select(m => $"{m.Name} @{m.Offset}").ToArray(), Is.EqualTo(expected), $"{kernel.Name}: reflected members");
                Assert.That(block.Size, Is.InRange(bytes - 15, bytes), $"{kernel.Name}: reflected size rounds up to {bytes}");
            }
            Assert.That(readers, Is.Positive, $"no kernel of {Path.GetFileName(computePath)} reads cbuffer {bufferName}");
        }

        /// <summary>The instance fields in layout order.</summary>
        static FieldInfo[] CSharpFields<T>() =>
            typeof(T).GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic)
                .OrderBy(f => (long)Marshal.OffsetOf<T>(f.Name)).ToArray();

        /// <summary>The HLSL spelling of a field's type: Unity.Mathematics vectors share HLSL's names.</summary>
        static string HlslType(Type type)
        {
            if (type == typeof(float)) return "float";
            if (type == typeof(int)) return "int";
            if (type == typeof(uint)) return "uint";
            if (type.Namespace == "Unity.Mathematics") return type.Name;
            throw new NotSupportedException($"no HLSL type for {type}");
        }
    }
}
