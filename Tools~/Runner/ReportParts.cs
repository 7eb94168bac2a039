using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using SoftBodyDynamics.Benchmarks.Scenarios;

namespace SoftBodyDynamics.Runner
{
    /// <summary>
    /// A part of the report made by another program of Tools~/DotNet (built by run.sh): the runner starts it, passes the
    /// scope and the report folder, and puts the Markdown it wrote under its own heading.
    /// </summary>
    sealed class ReportPart
    {
        /// <summary>Name for --filter and the timings, e.g. "LavapipeGpuFluidKernels".</summary>
        public string Name;
        /// <summary>Heading in the report.</summary>
        public string Title;
        /// <summary>Project folder under Tools~/DotNet (also the assembly name).</summary>
        public string Project;
        /// <summary>Arguments for a scope and the report folder.</summary>
        public Func<RunScope, string, IEnumerable<string>> Arguments;
        /// <summary>File the program writes, relative to the report folder: its Markdown.</summary>
        public string Fragment;

        public PartResult Run(RunOptions options, string dir)
        {
            string dll = Path.Combine(Path.GetFullPath(options.Root), "Tools~", "DotNet", Project, "bin", "Release", "net10.0", Project + ".dll");
            var result = new PartResult { Part = this };
            if (!File.Exists(dll))
            {
                result.Failure = $"{dll} is not built (run.sh builds it)";
                Console.Error.WriteLine($"{Title}: {result.Failure}");
                return result;
            }
            var psi = new ProcessStartInfo("dotnet") { UseShellExecute = false, WorkingDirectory = Path.GetFullPath(options.Root) };
            psi.ArgumentList.Add(dll);
            foreach (string a in Arguments(options.Scope, dir))
                psi.ArgumentList.Add(a);
            using (Process p = Process.Start(psi))
            {
                p.WaitForExit();
                if (p.ExitCode != 0)
                    result.Failure = $"{Project} exited with code {p.ExitCode}";
            }
            string fragment = Path.Combine(dir, Fragment);
            if (result.Failure == null && !File.Exists(fragment))
                result.Failure = $"{Project} wrote no {Fragment}";
            if (result.Failure == null)
                result.Markdown = File.ReadAllText(fragment);
            else
                Console.Error.WriteLine($"{Title}: {result.Failure}");
            return result;
        }
    }

    sealed class PartResult
    {
        public ReportPart Part;
        public string Markdown;
        public string Failure;
        public bool Succeeded => Failure == null;
    }

    /// <summary>The report parts, in report order.</summary>
    static class ReportParts
    {
        public static IReadOnlyList<ReportPart> All { get; } = new[]
        {
            new ReportPart
            {
                Name = "LavapipeGpuFluidKernels",
                Title = "GPU fluid kernels on lavapipe (CPU driver; not a GPU number)",
                Project = "SoftBodyDynamics.LavapipeTiming",
                Arguments = (scope, dir) => Scoped(scope, "--out", Path.Combine(dir, "lavapipe.md")),
                Fragment = "lavapipe.md",
            },
            new ReportPart
            {
                Name = "LavapipeGpuFluidRenderer",
                Title = "Screen-space fluid renderer on lavapipe",
                Project = "SoftBodyDynamics.FluidSurfaceRender",
                Arguments = (scope, dir) => Scoped(scope, "--out", dir),
                Fragment = "surface.md",
            },
        };

        static IEnumerable<string> Scoped(RunScope scope, params string[] args)
        {
            if (scope == RunScope.Quick)
                yield return "--quick";
            else if (scope == RunScope.Full)
                yield return "--full";
            foreach (string a in args)
                yield return a;
        }
    }
}
