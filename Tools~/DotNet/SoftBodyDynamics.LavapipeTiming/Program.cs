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
//   dotnet run -c Release --project Tools~/DotNet/SoftBodyDynamics.LavapipeTiming [-- --quick | --full] [--out FILE.md]
// (--full, which the main job passes in its full run, times what the default does: 22³ and 46³ cubes, five repeats.)
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
            FluidPass[] passes = buffer.Take(FluidSubstepPasses.Write(c, h, false, buffer)).ToArray();
            var cpu = new Dictionary<FluidPass, List<double>>();
            var gpu = new Dictionary<FluidPass, List<double>>();
            foreach (FluidPass pass in passes) { cpu[pass] = new List<double>(); gpu[pass] = new List<double>(); }

            using var g = new LavapipeFluidSolver(device, shader, c, count) { TimeKernels = true };
            var commands = g;
            var constants = FluidComputeConstants.Of(c, h, h);
            for (int r = 0; r <= repeats; r++)
            {
                g.Upload(b.Particles, b.Status.Count);
                commands.SetConstants(constants);
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
        SoftBodies(device, md, quick ? 8 : 16, repeats);
        Console.Write(md.ToString());
        if (outPath != null)
            File.WriteAllText(outPath, md.ToString());
        Console.WriteLine("RESULT lavapipetiming 1 0");
        return 0;
    }

    /// <summary>
    /// The soft-body kernels: one XPBD substep (one iteration over every colour) of a jelly box of n³ cells, lavapipe
    /// against SpringForces.ProjectColor run colour by colour on one core; and the cluster sums of a lattice body
    /// (clusters of 3³) on lavapipe alone (the CPU computes them inside ClusterGoals, together with the rotations).
    /// </summary>
    static void SoftBodies(LavapipeDevice device, StringBuilder md, int cells, int repeats)
    {
        using var shader = new LavapipeComputeShader(device, LavapipeSoftBodyCommands.ComputePath());
        using var g = new LavapipeSoftBodyCommands(device, shader);
        var issues = new List<ValidationIssue>();
        float edge = 0.02f * cells;
        TetrahedralMesh mesh = BoxTetrahedra.Create(new float3(edge), new int3(cells), new float3(0.5f * edge));
        MassSpringModelData body = MassSpringModelData.FromMesh(mesh, ElasticMaterial.Jelly, new MassSpringBuildSettings(), issues, out _, null);
        int n = body.ParticleCount, m = body.SpringCount;
        var x = new float3[n];
        var v = new float3[n];
        for (int i = 0; i < n; i++)
            x[i] = body.RestPositions[i] * 1.05f;
        var springs = new float4[2 * m];
        SoftBodyComputeStep.PackSprings(body.Springs, springs);
        SoftBodyComputeStep.PackVectors(x, g.Create(SoftBodyComputeBuffer.X, 16L * n).As<float4>());
        SoftBodyComputeStep.PackVectors(v, g.Create(SoftBodyComputeBuffer.V, 16L * n).As<float4>());
        SoftBodyComputeStep.PackVectors(body.RestPositions, g.Create(SoftBodyComputeBuffer.Rest, 16L * n).As<float4>());
        body.InverseMasses.AsSpan().CopyTo(g.Create(SoftBodyComputeBuffer.InverseMass, 4L * n).As<float>());
        springs.AsSpan().CopyTo(g.Create(SoftBodyComputeBuffer.Springs, 32L * m).As<float4>());
        body.Coloring.Elements.AsSpan().CopyTo(g.Create(SoftBodyComputeBuffer.ColorSprings, 4L * m).As<int>());
        g.Create(SoftBodyComputeBuffer.Multipliers, 4L * m);
        g.Create(SoftBodyComputeBuffer.P, 16L * n);
        const float h = 1f / 240f;
        var gpu = new List<double>();
        var cpu = new List<double>();
        var p = new float3[n];
        var lambda = new float3[2 * m];
        for (int r = 0; r <= repeats; r++)
        {
            var commands = g;
            SoftBodyComputeStep.RecordXpbdSubstep(ref commands, n, m, body.Coloring.ColorOffsets, 1, h);
            double ms = g.Flush();
            long t0 = Stopwatch.GetTimestamp();
            for (int i = 0; i < n; i++)
                p[i] = x[i] + h * v[i];
            Array.Clear(lambda, 0, lambda.Length);
            for (int c = 0; c < body.Coloring.ColorCount; c++)
                SpringForces.ProjectColor(body.Springs, body.Coloring.Elements, body.RestPositions, x, body.InverseMasses, h,
                    body.Coloring.ColorOffsets[c], body.Coloring.ColorOffsets[c + 1], p, lambda);
            for (int i = 0; i < n; i++)
                v[i] = (p[i] - x[i]) / h;
            double cms = (Stopwatch.GetTimestamp() - t0) * 1000.0 / Stopwatch.Frequency;
            Array.Clear(v, 0, n);
            if (r > 0) { gpu.Add(ms); cpu.Add(cms); }
        }
        md.AppendLine($"### Soft bodies: XPBD substep, {n} particles, {m} springs in {body.Coloring.ColorCount} colours (one iteration)");
        md.AppendLine();
        md.AppendLine("| kernels | lavapipe ms | C# ms (1 core) | lavapipe / C# | lavapipe ns per spring |");
        md.AppendLine("|---|---:|---:|---:|---:|");
        double gm = Median(gpu), cm = Median(cpu);
        md.AppendLine($"| predict, clear λ, {body.Coloring.ColorCount} colour dispatches, velocities (one submit) | {gm:F3} | {cm:F3} | {gm / cm:F2} | {gm * 1e6 / m:F0} |");
        md.AppendLine();

        ShapeMatchingModelData lattice = LatticeBody.Create(new int3(cells), 0.02f, 3, 1f);
        int ln = lattice.ParticleCount, clusters = lattice.ClusterCount;
        var rest = new float4[clusters];
        for (int c = 0; c < clusters; c++)
            rest[c] = new float4(lattice.ClusterRest[c].RestCenter, lattice.ClusterRest[c].TotalMass);
        SoftBodyComputeStep.PackVectors(lattice.RestPositions, g.Create(SoftBodyComputeBuffer.X, 16L * ln).As<float4>());
        SoftBodyComputeStep.PackVectors(lattice.RestPositions, g.Create(SoftBodyComputeBuffer.Rest, 16L * ln).As<float4>());
        lattice.ClusterOffsets.AsSpan().CopyTo(g.Create(SoftBodyComputeBuffer.ClusterOffsets, 4L * (clusters + 1)).As<int>());
        lattice.ClusterParticles.AsSpan().CopyTo(g.Create(SoftBodyComputeBuffer.ClusterParticles, 4L * lattice.ClusterParticles.Length).As<int>());
        lattice.ClusterWeights.AsSpan().CopyTo(g.Create(SoftBodyComputeBuffer.ClusterWeights, 4L * lattice.ClusterWeights.Length).As<float>());
        rest.AsSpan().CopyTo(g.Create(SoftBodyComputeBuffer.ClusterRest, 16L * clusters).As<float4>());
        g.Create(SoftBodyComputeBuffer.ClusterCenters, 16L * clusters);
        g.Create(SoftBodyComputeBuffer.ClusterApq, 48L * clusters);
        var sums = new List<double>();
        for (int r = 0; r <= repeats; r++)
        {
            var commands = g;
            SoftBodyComputeStep.RecordClusterSums(ref commands, clusters);
            double ms = g.Flush();
            if (r > 0) sums.Add(ms);
        }
        md.AppendLine($"### Soft bodies: cluster sums, {ln} particles in {clusters} clusters of up to 27 ({lattice.ClusterParticles.Length} memberships)");
        md.AppendLine();
        md.AppendLine($"lavapipe {Median(sums):F3} ms, {Median(sums) * 1e6 / lattice.ClusterParticles.Length:F0} ns per membership (one group of 64 threads per cluster).");
        md.AppendLine();
    }

    static double Median(List<double> v)
    {
        var s = v.OrderBy(x => x).ToList();
        return s.Count == 0 ? double.NaN : s[s.Count / 2];
    }
}
