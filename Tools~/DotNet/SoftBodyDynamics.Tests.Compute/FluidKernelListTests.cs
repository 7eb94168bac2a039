using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;
using SoftBodyDynamics.Lavapipe;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Compute
{
    /// <summary>The compute file and the C# side agree on kernels and sizes, and the kernels keep the portable rules.</summary>
    public class FluidKernelListTests
    {
        [Test]
        public void Pragmas_AreTheKernelEnumInOrder()
        {
            var pragmas = KernelCompiler.Kernels(LavapipeFluidSolver.ComputePath()).Select(k => k.Name).ToArray();
            Assert.That(pragmas, Is.EqualTo(Enum.GetNames(typeof(FluidKernel))));
        }

        [Test]
        public void SoftBodyPragmas_AreTheKernelEnumInOrder()
        {
            var pragmas = KernelCompiler.Kernels(LavapipeSoftBodyCommands.ComputePath()).Select(k => k.Name).ToArray();
            Assert.That(pragmas, Is.EqualTo(Enum.GetNames(typeof(SoftBodyKernel))));
        }

        [Test]
        public void ThreadGroups_AreAtMost256AndParticleKernelsUseTheLayoutSize()
        {
            LavapipeComputeShader shader = Lavapipe.FluidShader;
            for (int k = 0; k < shader.KernelCount; k++)
            {
                var size = shader.ThreadGroupSize(k);
                string name = shader.KernelName(k);
                Assert.That(size.x * size.y * size.z, Is.LessThanOrEqualTo(256), name);
                bool single = name.StartsWith("Commit") || name == "ClearStats";
                if (!single)
                    Assert.That(size.x, Is.EqualTo(FluidComputeLayout.ThreadGroupSize), name);
            }
        }

        [Test]
        public void Buffers_PerKernelAreAtMostTheLayoutBound()
        {
            LavapipeComputeShader shader = Lavapipe.FluidShader;
            int most = 0;
            for (int k = 0; k < shader.KernelCount; k++)
                most = Math.Max(most, shader.Compiled(k).Bindings.Count(b => !b.Uniform));
            Assert.That(most, Is.EqualTo(FluidComputeLayout.MaxBuffersPerKernel), "FluidBackendChoice checks the device against this bound");
        }

        [Test]
        public void Sources_KeepThePortableRules()
        {
            // Every kernel of the package: the simulation's and the renderer's share one folder.
            string dir = Path.GetDirectoryName(LavapipeFluidSolver.ComputePath());
            string[] files = Directory.GetFiles(dir, "*.hlsl", SearchOption.AllDirectories).Concat(Directory.GetFiles(dir, "*.compute")).ToArray();
            Assert.That(files.Select(Path.GetFileName), Does.Contain("FluidSurfaceSplat.hlsl").And.Contain("FluidScan.hlsl"));
            // Array sizes given by macros: #define NAME <number> or a product of such names, across every file.
            var sizes = new Dictionary<string, int>();
            for (int pass = 0; pass < 3; pass++)
                foreach (string file in files)
                foreach (Match d in Regex.Matches(File.ReadAllText(file), @"#define\s+(\w+)\s+\(?\s*(\w+)(?:\s*\*\s*(\w+))?\s*\)?\s*$", RegexOptions.Multiline))
                {
                    int Size(string term) => int.TryParse(term, out int n) ? n : sizes.TryGetValue(term, out int v) ? v : -1;
                    int a = Size(d.Groups[2].Value), b = d.Groups[3].Success ? Size(d.Groups[3].Value) : 1;
                    if (a > 0 && b > 0)
                        sizes[d.Groups[1].Value] = a * b;
                }
            foreach (string file in files)
            {
                string text = Regex.Replace(File.ReadAllText(file), @"//[^\n]*", "");
                string name = Path.GetFileName(file);
                Assert.That(Regex.IsMatch(text, @"StructuredBuffer\s*<\s*(float|int|uint|half)3\s*>"), Is.False, name + ": a 3-vector in a structured buffer");
                Assert.That(Regex.IsMatch(text, @"\bWave[A-Z]\w*\s*\("), Is.False, name + ": a wave intrinsic");
                Assert.That(Regex.IsMatch(text, @"\b(u?int64_t|double)\b"), Is.False, name + ": a 64-bit type");
                // groupshared per file (a kernel uses at most its file's): e.g. the scan's 512 uints (2 KB), the cluster sums'
                // 3 × 64 float3 (2.3 KB), under OpenGL ES 3.1's 16 KB.
                int bytes = 0;
                foreach (Match m in Regex.Matches(text, @"groupshared\s+(\w+)\s+\w+\s*\[\s*(\w+)\s*\]"))
                {
                    string count = m.Groups[2].Value;
                    int elements = int.TryParse(count, out int literal) ? literal : sizes[count];
                    int size = m.Groups[1].Value switch { "float3" => 12, "float4" or "uint4" => 16, "float2" or "uint2" => 8, _ => 4 };
                    bytes += elements * size;
                }
                Assert.That(bytes, Is.LessThanOrEqualTo(16 * 1024), name + ": groupshared over 16 KB");
            }
        }
    }
}
