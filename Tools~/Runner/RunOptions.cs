using System.IO;
using SoftBodyDynamics.Benchmarks.Scenarios;

namespace SoftBodyDynamics.Runner
{
    /// <summary>The main job's command line.</summary>
    sealed class RunOptions
    {
        public const string Usage =
            "usage: bash Tools~/run.sh [--quick | --full] [--filter TEXT] [--method TEXT] [--out DIR] [--repeats N] [--threads N] [--help]\n" +
            "\n" +
            "Runs the benchmark scenarios headless, prints one table per suite and writes report.md (summary first),\n" +
            "results.csv (one row per metric, with its unit) and figures to the output folder.\n" +
            "\n" +
            "  (no option)    every suite with its sweeps cut to what keeps each figure's shape and headline findings (minutes)\n" +
            "  --full         the whole study: every knob value and resolution of every sweep (tens of minutes)\n" +
            "  --quick        a few points of each suite: the smoke test\n" +
            "  --filter TEXT  only the suites whose name contains TEXT (case-insensitive), e.g. MethodStudyCantilever, Fluid, Lavapipe\n" +
            "  --method TEXT  only the scenarios whose method contains TEXT, e.g. \"FEM co-rotational implicit\" (skips the lavapipe parts)\n" +
            "  --out DIR      report folder (default Reports~/latest, relative to the package root)\n" +
            "  --repeats N    timed steps per scenario (default 15; long scenarios time fewer)\n" +
            "  --threads N    worker threads for setting up and evaluating independent scenarios (default: all cores);\n" +
            "                 timed steps always run one at a time with nothing else running\n" +
            "  --help         this text\n" +
            "\n" +
            "Progress goes to stderr, one line per scenario as it starts: [i/N], elapsed time, estimated time left (from the\n" +
            "previous run's timings in the same folder where known). The report is rewritten after every scenario, so an\n" +
            "interrupted run leaves a valid report of what finished.";

        public string OutDir = Path.Combine("Reports~", "latest");
        public RunScope Scope = RunScope.Standard;
        public int Repeats = 15;
        public string Filter;
        /// <summary>Only scenarios whose method text contains this (case-insensitive), e.g. "Neo-Hookean implicit"; null = all.</summary>
        public string Method;
        public bool Help;
        /// <summary>Worker threads for the setup and evaluation of independent scenarios (timed steps always run alone).</summary>
        public int Threads = System.Environment.ProcessorCount;
        /// <summary>Package root: the report parts run from it (default: the working directory).</summary>
        public string Root = ".";

        /// <summary>Warm-up and repeats: the full run's long rule, or the short one of the default and quick runs.</summary>
        public TimingRule Timing => Scope == RunScope.Full ? TimingRule.Full : TimingRule.Short;

        /// <summary>The options, or null (with <paramref name="error"/>) when the command line is not understood.</summary>
        public static RunOptions Parse(string[] args, out string error)
        {
            var o = new RunOptions();
            error = null;
            bool quick = false, full = false;
            for (int i = 0; i < args.Length; i++)
            {
                switch (args[i])
                {
                    case "--out" when i + 1 < args.Length: o.OutDir = args[++i]; break;
                    case "--root" when i + 1 < args.Length: o.Root = args[++i]; break;
                    case "--quick": quick = true; break;
                    case "--full": full = true; break;
                    case "--help":
                    case "-h":
                        o.Help = true; break;
                    case "--repeats" when i + 1 < args.Length && int.TryParse(args[i + 1], out int n) && n > 0:
                        o.Repeats = n; i++; break;
                    case "--threads" when i + 1 < args.Length && int.TryParse(args[i + 1], out int t) && t > 0:
                        o.Threads = t; i++; break;
                    case "--filter" when i + 1 < args.Length: o.Filter = args[++i]; break;
                    case "--method" when i + 1 < args.Length: o.Method = args[++i]; break;
                    default:
                        error = $"not understood: '{args[i]}'";
                        return null;
                }
            }
            if (quick && full)
            {
                error = "--quick and --full exclude each other";
                return null;
            }
            o.Scope = quick ? RunScope.Quick : full ? RunScope.Full : RunScope.Standard;
            return o;
        }

        /// <summary>"default", "full" or "quick", as the report and the progress lines name the scope.</summary>
        public static string ScopeName(RunScope scope) => scope == RunScope.Standard ? "default" : scope == RunScope.Full ? "full" : "quick";
    }
}
