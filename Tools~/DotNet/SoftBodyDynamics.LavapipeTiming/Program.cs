using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Lavapipe;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

// Per pass of one weakly compressible substep of the throughput cube (FluidThroughputScenario.CubeParameters): the
// time of its kernels on lavapipe (each dispatch submitted alone, so a few tens of µs of submit overhead are included)
// and of the C# pass on one core, median of the repeats after a warm-up. Lavapipe runs the kernels on this machine's
// CPU cores through LLVM: the ratio says how the kernels compare with the C# on the same CPU, not how fast a GPU is.
//   dotnet run -c Release --project Tools~/DotNet/SoftBodyDynamics.LavapipeTiming [-- --quick] [--out FILE.md]
static class Program
{
    static int Main(string[] args)
    {
        bool quick = args.Contains("--quick");
        int outIndex = Array.IndexOf(args, "--out");
        string outPath = outIndex >= 0 && outIndex + 1 < args.Length ? args[outIndex + 1] : null;
        int[] sides = quick ? new[] { 12 } : new[] { 22, 46 };
        int repeats = quick ? 3 : 5;
        var md = new StringBuilder();
        using var device = new LavapipeDevice();
        using var shader = new LavapipeComputeShader(device, LavapipeFluidSolver.ComputePath());
        md.AppendLine($"Device: {device.DeviceName} ({Environment.ProcessorCount} cores). Median of {repeats} repeats after one warm-up.");
        md.AppendLine();
        foreach (int side in sides)
        {
            FluidParameters p = FluidThroughputScenario.CubeParameters(side);
            var c = new FluidConstants(p);
            float edge = side * p.ParticleSpacing;
            var b = new FluidBuffers(side * side * side, c.Grid);
            int count = FluidScene.FillBlock(b, float3.zero, new float3(edge), p.ParticleSpacing);
            float h = 0.9f * FluidSolver.CflSubstep(c, 0f, 1f);
            FluidSolver.Step(c, ReadOnlySpan<ColliderShape>.Empty, h, b.Particles, b.Scratch, ref b.Status);
            var buffer = new FluidPass[FluidSubstepPasses.MaxPasses];
            FluidPass[] passes = buffer.Take(FluidSubstepPasses.Write(c.Parameters, false, buffer)).ToArray();
            var cpu = new Dictionary<FluidPass, List<double>>();
            var gpu = new Dictionary<FluidPass, List<double>>();
            foreach (FluidPass pass in passes) { cpu[pass] = new List<double>(); gpu[pass] = new List<double>(); }

            using var g = new LavapipeFluidSolver(device, shader, c, count) { TimeKernels = true };
            var commands = g;
            var constants = FluidComputeConstants.Of(c, h, h);
            for (int r = 0; r <= repeats; r++)
            {
                g.Upload(b.Particles, b.Status.Count);
                constants.Set(ref commands);
                foreach (FluidPass pass in passes)
                {
                    double before = g.KernelMilliseconds.Values.Sum(v => v.Milliseconds);
                    FluidComputeStep.RecordPass(ref commands, c, pass);
                    if (r > 0)
                        gpu[pass].Add(g.KernelMilliseconds.Values.Sum(v => v.Milliseconds) - before);
                }
                var counters = new FluidPassCounters();
                int live = b.Status.Count;
                foreach (FluidPass pass in passes)
                {
                    long t0 = Stopwatch.GetTimestamp();
                    FluidPasses.Run(pass, c, ReadOnlySpan<ColliderShape>.Empty, b.Particles, b.Scratch, 0, 1, ref live, h, ref counters);
                    double ms = (Stopwatch.GetTimestamp() - t0) * 1000.0 / Stopwatch.Frequency;
                    if (r > 0)
                        cpu[pass].Add(ms);
                }
            }
            md.AppendLine($"### {count} particles (cube of {side}³, Δx = {p.ParticleSpacing} m)");
            md.AppendLine();
            md.AppendLine("| pass | lavapipe ms | C# ms (1 core) | lavapipe / C# | lavapipe ns per particle |");
            md.AppendLine("|---|---:|---:|---:|---:|");
            double totalGpu = 0, totalCpu = 0;
            foreach (FluidPass pass in passes)
            {
                double gm = Median(gpu[pass]), cm = Median(cpu[pass]);
                totalGpu += gm; totalCpu += cm;
                md.AppendLine($"| {pass} | {gm:F3} | {cm:F3} | {gm / cm:F2} | {gm * 1e6 / count:F0} |");
            }
            md.AppendLine($"| **substep** | **{totalGpu:F3}** | **{totalCpu:F3}** | **{totalGpu / totalCpu:F2}** | **{totalGpu * 1e6 / count:F0}** |");
            md.AppendLine();
        }
        Console.Write(md.ToString());
        if (outPath != null)
            File.WriteAllText(outPath, md.ToString());
        Console.WriteLine("RESULT lavapipetiming 1 0");
        return 0;
    }

    static double Median(List<double> v)
    {
        var s = v.OrderBy(x => x).ToList();
        return s.Count == 0 ? double.NaN : s[s.Count / 2];
    }
}
