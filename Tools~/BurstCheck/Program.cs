using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Mono.Cecil;

namespace SoftBodyDynamics.Tools.BurstCheck
{
    /// <summary>
    /// Burst-compatibility check without Unity. Reads the package assemblies that the type-check built
    /// (Tools~/TypeCheck/obj/generated/*/bin/…, so run typecheck.sh first) with the Unity stand-ins beside them, follows
    /// every method reachable from a [BurstCompile] entry point (<see cref="BurstChecker"/>) and prints each problem with
    /// the call path that reaches it, then <c>RESULT burstcheck &lt;entry points clean&gt; &lt;entry points with problems&gt;</c>.
    /// <c>--self-test</c> checks the rules on the jobs of Fixtures.cs instead.
    /// </summary>
    static class Program
    {
        static int Main(string[] args)
        {
            if (args.Contains("--self-test"))
                return SelfTest();
            string root = args.Length > 0 ? args[0] : Directory.GetCurrentDirectory();
            string generated = Path.Combine(root, "Tools~", "TypeCheck", "obj", "generated");
            List<string> dlls = Directory.Exists(generated)
                ? Directory.GetFiles(generated, "SoftBodyDynamics*.dll", SearchOption.AllDirectories)
                    .Where(f => f.Contains(Path.DirectorySeparatorChar + "bin" + Path.DirectorySeparatorChar))
                    .GroupBy(Path.GetFileName).Select(g => g.OrderByDescending(File.GetLastWriteTimeUtc).First())
                    // Runtime assemblies only: Burst compiles no Editor, test or benchmark code of the package.
                    .Where(f => !Path.GetFileName(f).Contains(".Tests") && !Path.GetFileName(f).Contains(".Benchmarks")
                        && !Path.GetFileName(f).Contains(".Editor") && !Path.GetFileName(f).Contains(".Samples"))
                    .ToList()
                : new List<string>();
            if (dlls.Count == 0)
            {
                Console.WriteLine($"burstcheck: no package assemblies under {generated}; run Tools~/TypeCheck/typecheck.sh first");
                Console.WriteLine("RESULT burstcheck 0 1");
                return 1;
            }
            var resolver = new DefaultAssemblyResolver();
            foreach (string folder in dlls.Select(Path.GetDirectoryName).Distinct())
                resolver.AddSearchDirectory(folder);
            resolver.AddSearchDirectory(Path.GetDirectoryName(typeof(object).Assembly.Location));
            var parameters = new ReaderParameters { AssemblyResolver = resolver };
            List<AssemblyDefinition> package = dlls.Select(f => AssemblyDefinition.ReadAssembly(f, parameters)).ToList();
            var checker = new BurstChecker(package);
            checker.Run();
            foreach (var (path, problem) in checker.Problems)
                Console.WriteLine($"FAIL {problem}\n     via {path}");
            // Each failing root (an entry point, or a job type with a managed field) counts once.
            var roots = new HashSet<string>(checker.Problems.Select(p => p.Path.Split(" → ")[0]), StringComparer.Ordinal);
            int bad = roots.Count, clean = checker.EntryPoints.Count(e => !roots.Contains(e));
            Console.WriteLine($"burstcheck: {checker.EntryPoints.Count} entry points in {string.Join(", ", package.Select(a => a.Name.Name))}; {checker.MethodsChecked} methods checked");
            Console.WriteLine($"RESULT burstcheck {clean} {bad}");
            return bad == 0 ? 0 : 1;
        }

        static int SelfTest()
        {
            string self = typeof(Program).Assembly.Location;
            var resolver = new DefaultAssemblyResolver();
            resolver.AddSearchDirectory(Path.GetDirectoryName(self));
            resolver.AddSearchDirectory(Path.GetDirectoryName(typeof(object).Assembly.Location));
            AssemblyDefinition assembly = AssemblyDefinition.ReadAssembly(self, new ReaderParameters { AssemblyResolver = resolver });
            var checker = new BurstChecker(new[] { assembly });
            checker.Run();
            int passed = 0, failed = 0;
            foreach (TypeDefinition type in assembly.MainModule.GetTypes().Where(t => t.Namespace.EndsWith(".Fixtures", StringComparison.Ordinal)))
            foreach (ICustomAttributeProvider fixture in new ICustomAttributeProvider[] { type }.Concat(type.Methods))
            {
                CustomAttribute expect = fixture.CustomAttributes.FirstOrDefault(a => a.AttributeType.Name == "ExpectAttribute");
                if (expect == null)
                    continue;
                string text = (string)expect.ConstructorArguments[0].Value;
                string name = fixture is MethodDefinition m ? $"{type.FullName}.{m.Name}" : type.FullName;
                // The fixture's own paths: its entry point (a method) or its Execute and the job type itself.
                List<string> found = checker.Problems
                    .Where(p => p.Path == name || p.Path.StartsWith(name + (fixture is MethodDefinition ? " " : "."), StringComparison.Ordinal))
                    .Select(p => p.Problem).ToList();
                bool ok = text.Length == 0 ? found.Count == 0 : found.Any(p => p.Contains(text, StringComparison.Ordinal));
                Console.WriteLine($"{(ok ? "PASS" : "FAIL")} {name}: expected {(text.Length == 0 ? "no problem" : $"\"{text}\"")}, found [{string.Join("; ", found)}]");
                if (ok) passed++; else failed++;
            }
            Console.WriteLine($"RESULT burstcheck-selftest {passed} {failed}");
            return failed == 0 && passed > 0 ? 0 : 1;
        }
    }
}
