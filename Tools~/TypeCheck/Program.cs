using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.Json;
using System.Text.RegularExpressions;

namespace SoftBodyDynamics.Tools.TypeCheck
{
    /// <summary>
    /// Type-checks the Unity side of the package without Unity.
    /// <list type="number">
    /// <item>Finds every *.asmdef (and *.asmref) the way Unity does (plus the importable samples in Samples~): folders whose name ends in '~' or starts
    /// with '.' are skipped, and each .cs file belongs to the assembly of its nearest enclosing folder that has
    /// an asmdef or asmref.</item>
    /// <item>Writes one csproj per asmdef into Tools~/TypeCheck/obj/generated/ (git-ignored): references to other
    /// package asmdefs by name, to the reference declarations in Tools~/UnityApi/&lt;Assembly&gt;/ for Unity
    /// assemblies, UnityEngine unless noEngineReferences, UnityEditor for Editor-only asmdefs, NUnit when
    /// nunit.framework.dll is a precompiled reference, and the defines Unity would set.</item>
    /// <item>Builds them all with one <c>dotnet build</c> of a generated solution and prints
    /// <c>PASS name</c> / <c>FAIL name</c> per assembly, then <c>RESULT typecheck &lt;passed&gt; &lt;failed&gt;</c>.</item>
    /// </list>
    /// Assemblies with no .cs files are compiled empty and counted (their references are still checked).
    /// Assemblies whose defineConstraints are not met are reported as SKIP and not counted.
    /// </summary>
    static class Program
    {
        /// <summary>Defines Unity sets for an Editor compilation of this package's test and benchmark assemblies.</summary>
        static readonly string[] k_BaseDefines =
        {
            "UNITY_EDITOR", "UNITY_INCLUDE_TESTS", "UNITY_2022_3_OR_NEWER", "UNITY_6000_0_OR_NEWER",
        };

        /// <summary>
        /// Unity assembly names the package may reference. A reference to one of these resolves to
        /// Tools~/UnityApi/&lt;name&gt;/&lt;name&gt;.csproj when that project exists; when it does not, nothing of the
        /// assembly is used yet and no reference is added. Any other name that is not a package asmdef is an error.
        /// </summary>
        static readonly HashSet<string> k_UnityAssemblies = new HashSet<string>(StringComparer.Ordinal)
        {
            "UnityEngine", "UnityEditor",
            "Unity.Mathematics", "Unity.Mathematics.Extensions",
            "Unity.Entities", "Unity.Entities.Hybrid", "Unity.Transforms", "Unity.Collections", "Unity.Burst",
            "Unity.Entities.Graphics", "Unity.Deformations", "Unity.Scenes",
            "Unity.PerformanceTesting", "UnityEngine.TestRunner", "UnityEditor.TestRunner",
            "Unity.RenderPipelines.Core.Runtime", "Unity.RenderPipelines.Universal.Runtime", "Unity.Physics",
        };

        /// <summary>Precompiled references the tool can stand in for, and the NuGet package that does.</summary>
        const string k_NUnitDll = "nunit.framework.dll";
        const string k_NUnitVersion = "3.14.0";

        sealed class Asmdef
        {
            public string Name;
            public string Path;          // absolute path of the .asmdef
            public string Folder;        // absolute folder
            public string Guid;          // from the .meta, if any
            public List<string> References = new List<string>();
            public List<string> IncludePlatforms = new List<string>();
            public List<string> PrecompiledReferences = new List<string>();
            public List<string> DefineConstraints = new List<string>();
            public List<string> VersionDefines = new List<string>();
            public bool AllowUnsafe;
            public bool OverrideReferences;
            public bool NoEngineReferences;
            public List<string> Files = new List<string>();
            // Results of planning.
            public List<string> Problems = new List<string>();
            public List<string> Notes = new List<string>();
            public HashSet<string> Defines;
            public List<Asmdef> PackageRefs = new List<Asmdef>();
            public List<string> StubRefs = new List<string>();
            public bool Skipped;
            public string SkipReason;
            public string ProjectPath;
        }

        static int Main(string[] args)
        {
            try
            {
                return Run(args);
            }
            catch (Exception e)
            {
                Console.Error.WriteLine("typecheck: " + e);
                Console.WriteLine("RESULT typecheck 0 1");
                return 2;
            }
        }

        static int Run(string[] args)
        {
            var watch = Stopwatch.StartNew();
            var root = System.IO.Path.GetFullPath(args.Length > 0 ? args[0] : Directory.GetCurrentDirectory());
            var toolDir = System.IO.Path.Combine(root, "Tools~", "TypeCheck");
            var stubRoot = System.IO.Path.Combine(root, "Tools~", "UnityApi");
            var genDir = System.IO.Path.Combine(toolDir, "obj", "generated");
            bool verbose = args.Contains("--verbose");

            // 1. Scan the package as Unity imports it.
            var asmdefs = new List<Asmdef>();
            var asmrefs = new Dictionary<string, string>(StringComparer.Ordinal); // folder -> referenced name/GUID
            var csFiles = new List<string>();
            var globalProblems = new List<string>();
            Scan(root, root, asmdefs, asmrefs, csFiles, globalProblems);

            var byName = new Dictionary<string, Asmdef>(StringComparer.Ordinal);
            var byFolder = new Dictionary<string, Asmdef>(StringComparer.Ordinal);
            foreach (var a in asmdefs)
            {
                if (byName.ContainsKey(a.Name))
                    globalProblems.Add($"error: two asmdefs named '{a.Name}': {Rel(root, byName[a.Name].Path)} and {Rel(root, a.Path)}");
                else
                    byName[a.Name] = a;
                if (byFolder.ContainsKey(a.Folder))
                    globalProblems.Add($"error: folder {Rel(root, a.Folder)} has more than one asmdef");
                else
                    byFolder[a.Folder] = a;
            }
            var byGuid = asmdefs.Where(a => a.Guid != null).GroupBy(a => a.Guid).ToDictionary(g => g.Key, g => g.First());

            // asmref folders join the assembly they name.
            foreach (var kv in asmrefs)
            {
                var target = Resolve(kv.Value, byName, byGuid);
                if (target == null)
                    globalProblems.Add($"error: {Rel(root, kv.Key)}: asmref to unknown assembly '{kv.Value}'");
                else if (byFolder.ContainsKey(kv.Key))
                    globalProblems.Add($"error: folder {Rel(root, kv.Key)} has both an asmdef and an asmref");
                else
                    byFolder[kv.Key] = target;
            }

            // 2. Nearest enclosing folder with an asmdef/asmref owns each script.
            foreach (var file in csFiles)
            {
                var dir = System.IO.Path.GetDirectoryName(file);
                Asmdef owner = null;
                while (dir != null && dir.Length >= root.Length)
                {
                    if (byFolder.TryGetValue(dir, out owner)) break;
                    dir = System.IO.Path.GetDirectoryName(dir);
                }
                if (owner == null)
                    globalProblems.Add($"error: {Rel(root, file)} is in no assembly (a package script needs an enclosing asmdef)");
                else
                    owner.Files.Add(file);
            }

            // 3. Defines, constraints, references.
            foreach (var a in asmdefs)
            {
                a.Defines = new HashSet<string>(k_BaseDefines, StringComparer.Ordinal);
                foreach (var d in a.VersionDefines) a.Defines.Add(d); // every versioned package counts as present
                var unmet = a.DefineConstraints.Where(c => !ConstraintHolds(c, a.Defines)).ToList();
                if (unmet.Count > 0)
                {
                    a.Skipped = true;
                    a.SkipReason = "defineConstraints not met: " + string.Join(", ", unmet);
                }
            }
            foreach (var a in asmdefs.Where(x => !x.Skipped))
            {
                foreach (var r in a.References.Distinct())
                {
                    var pkg = Resolve(r, byName, byGuid);
                    if (pkg != null)
                    {
                        if (pkg == a) a.Problems.Add($"error: references itself ('{r}')");
                        else if (pkg.Skipped) a.Notes.Add($"reference '{pkg.Name}' dropped: that assembly is not compiled ({pkg.SkipReason})");
                        else a.PackageRefs.Add(pkg);
                        continue;
                    }
                    if (r.StartsWith("GUID:", StringComparison.Ordinal))
                    {
                        a.Problems.Add($"error: reference '{r}' matches no package asmdef (.meta GUID) and Unity assemblies must be referenced by name here");
                        continue;
                    }
                    if (!k_UnityAssemblies.Contains(r) && !File.Exists(StubProject(stubRoot, r)))
                    {
                        a.Problems.Add($"error: reference '{r}' is neither a package asmdef nor a known Unity assembly");
                        continue;
                    }
                    if (File.Exists(StubProject(stubRoot, r))) a.StubRefs.Add(r);
                    else if (verbose) a.Notes.Add($"reference '{r}': no declarations yet (nothing of it is used)");
                }
                bool editorOnly = a.IncludePlatforms.Count == 1 && a.IncludePlatforms[0] == "Editor";
                if (!a.NoEngineReferences)
                {
                    AddStub(a, "UnityEngine", stubRoot);
                    if (editorOnly) AddStub(a, "UnityEditor", stubRoot);
                }
                foreach (var p in a.PrecompiledReferences)
                {
                    if (!a.OverrideReferences)
                        a.Notes.Add($"precompiledReferences '{p}' ignored: Unity reads them only with overrideReferences");
                    else if (!string.Equals(p, k_NUnitDll, StringComparison.OrdinalIgnoreCase))
                        a.Problems.Add($"error: precompiled reference '{p}' has no stand-in in the type-check");
                }
            }

            // Reference cycles are an error in Unity too.
            foreach (var a in asmdefs.Where(x => !x.Skipped))
                if (ReachesItself(a))
                    a.Problems.Add("error: cyclic assembly references");

            // 4. Generate projects.
            Directory.CreateDirectory(genDir);
            WriteIfChanged(System.IO.Path.Combine(genDir, "Directory.Build.props"),
                "<Project>\n  <!-- Generated: stops Tools~/Directory.Build.props (SBD_DOTNET) from reaching the Unity-side projects. -->\n</Project>\n");
            WriteIfChanged(System.IO.Path.Combine(genDir, "Directory.Build.targets"), "<Project />\n");
            var built = asmdefs.Where(x => !x.Skipped && x.Problems.Count == 0 && !DependsOnBroken(x)).OrderBy(x => x.Name, StringComparer.Ordinal).ToList();
            foreach (var a in asmdefs.Where(x => !x.Skipped))
                a.ProjectPath = System.IO.Path.Combine(genDir, a.Name, a.Name + ".csproj");
            foreach (var a in built)
                WriteIfChanged(a.ProjectPath, ProjectText(root, stubRoot, a));
            var sln = new StringBuilder("<Solution>\n");
            foreach (var a in built)
                sln.Append($"  <Project Path=\"{Xml(a.Name)}/{Xml(a.Name)}.csproj\" />\n");
            sln.Append("</Solution>\n");
            var slnPath = System.IO.Path.Combine(genDir, "TypeCheck.slnx");
            WriteIfChanged(slnPath, sln.ToString());

            // 5. Build.
            var diagnostics = new Dictionary<string, List<string>>(StringComparer.Ordinal); // project path -> lines
            var warnings = new Dictionary<string, List<string>>(StringComparer.Ordinal);
            int exit = 0;
            string rawOutput = "";
            if (built.Count > 0)
            {
                (exit, rawOutput) = Exec("dotnet", new[]
                {
                    "build", slnPath, "-nologo", "-tl:off", "-v:m", "-clp:NoSummary;ForceNoAlign",
                    "-p:GenerateFullPaths=true", "-p:Configuration=Debug",
                });
                ParseDiagnostics(rawOutput, diagnostics, warnings);
            }

            // 6. Report.
            foreach (var p in globalProblems) Console.WriteLine(p);
            var failedNames = new HashSet<string>(StringComparer.Ordinal);
            var stubFailures = diagnostics.Keys.Where(k => k.StartsWith(stubRoot, StringComparison.Ordinal)).ToList();
            foreach (var s in stubFailures)
            {
                Console.WriteLine($"FAIL {System.IO.Path.GetFileNameWithoutExtension(s)} (Unity API declarations in {Rel(root, System.IO.Path.GetDirectoryName(s))})");
                foreach (var line in diagnostics[s]) Console.WriteLine("  " + Shorten(root, line));
            }
            int passed = 0, failed = 0;
            foreach (var a in Topological(asmdefs.Where(x => !x.Skipped).ToList()))
            {
                var own = a.Problems.ToList();
                if (a.ProjectPath != null && diagnostics.TryGetValue(a.ProjectPath, out var errs)) own.AddRange(errs);
                var brokenDeps = a.PackageRefs.Where(d => failedNames.Contains(d.Name)).Select(d => d.Name)
                    .Concat(a.StubRefs.Where(s => stubFailures.Contains(StubProject(stubRoot, s))))
                    .ToList();
                bool fail = own.Count > 0 || brokenDeps.Count > 0 || (exit != 0 && built.Contains(a) && !OutputExists(a));
                var summary = $"{a.Name} ({a.Files.Count} file{(a.Files.Count == 1 ? "" : "s")}, {Rel(root, a.Path)})";
                if (fail)
                {
                    failed++;
                    failedNames.Add(a.Name);
                    Console.WriteLine("FAIL " + summary);
                    foreach (var line in own) Console.WriteLine("  " + Shorten(root, line));
                    if (brokenDeps.Count > 0) Console.WriteLine("  not compiled: depends on failed " + string.Join(", ", brokenDeps));
                    else if (own.Count == 0) Console.WriteLine("  build failed without a diagnostic for this project (see the build output above)");
                }
                else
                {
                    passed++;
                    Console.WriteLine("PASS " + summary);
                }
                if (a.ProjectPath != null && warnings.TryGetValue(a.ProjectPath, out var warns))
                    foreach (var w in warns) Console.WriteLine("  " + Shorten(root, w));
                foreach (var n in a.Notes) Console.WriteLine("  note: " + n);
            }
            foreach (var a in asmdefs.Where(x => x.Skipped).OrderBy(x => x.Name, StringComparer.Ordinal))
                Console.WriteLine($"SKIP {a.Name} ({a.SkipReason})");

            bool unexplained = exit != 0 && failed == 0 && stubFailures.Count == 0;
            if (unexplained || (verbose && exit != 0))
            {
                Console.WriteLine("dotnet build exited with " + exit + "; its output:");
                Console.WriteLine(rawOutput);
            }
            // Failed Unity API declaration projects count as failed assemblies; so does each package-level problem
            // (e.g. a script in no assembly) and a build failure that no project explains.
            failed += stubFailures.Count + globalProblems.Count + (unexplained ? 1 : 0);
            Console.WriteLine($"typecheck: {asmdefs.Count} asmdefs, {watch.Elapsed.TotalSeconds:F1} s");
            Console.WriteLine($"RESULT typecheck {passed} {failed}");
            return failed == 0 ? 0 : 1;
        }

        // ---------------------------------------------------------------- scanning

        static void Scan(string root, string dir, List<Asmdef> asmdefs, Dictionary<string, string> asmrefs,
            List<string> csFiles, List<string> problems)
        {
            foreach (var file in Directory.GetFiles(dir).OrderBy(f => f, StringComparer.Ordinal))
            {
                var name = System.IO.Path.GetFileName(file);
                if (name.StartsWith(".", StringComparison.Ordinal)) continue;
                if (name.EndsWith(".cs", StringComparison.Ordinal)) csFiles.Add(file);
                else if (name.EndsWith(".asmdef", StringComparison.Ordinal))
                {
                    try { asmdefs.Add(ReadAsmdef(file)); }
                    catch (Exception e) { problems.Add($"error: {Rel(root, file)}: cannot read asmdef: {e.Message}"); }
                }
                else if (name.EndsWith(".asmref", StringComparison.Ordinal))
                {
                    try
                    {
                        using var doc = JsonDocument.Parse(File.ReadAllText(file), JsonOptions);
                        asmrefs[dir] = doc.RootElement.GetProperty("reference").GetString();
                    }
                    catch (Exception e) { problems.Add($"error: {Rel(root, file)}: cannot read asmref: {e.Message}"); }
                }
            }
            foreach (var sub in Directory.GetDirectories(dir).OrderBy(d => d, StringComparer.Ordinal))
            {
                var name = System.IO.Path.GetFileName(sub);
                // Unity ignores hidden folders, folders ending in '~', and 'cvs' folders. Samples~ is the
                // exception we check too: Unity compiles a sample once the user imports it into Assets.
                bool samples = string.Equals(name, "Samples~", StringComparison.Ordinal) && dir == root;
                if (!samples && (name.StartsWith(".", StringComparison.Ordinal) || name.EndsWith("~", StringComparison.Ordinal)
                    || string.Equals(name, "cvs", StringComparison.OrdinalIgnoreCase)))
                    continue;
                Scan(root, sub, asmdefs, asmrefs, csFiles, problems);
            }
        }

        static readonly JsonDocumentOptions JsonOptions = new JsonDocumentOptions
        {
            CommentHandling = JsonCommentHandling.Skip,
            AllowTrailingCommas = true,
        };

        static Asmdef ReadAsmdef(string path)
        {
            using var doc = JsonDocument.Parse(File.ReadAllText(path), JsonOptions);
            var r = doc.RootElement;
            var a = new Asmdef
            {
                Path = path,
                Folder = System.IO.Path.GetDirectoryName(path),
                Name = r.TryGetProperty("name", out var n) ? n.GetString() : null,
                AllowUnsafe = Bool(r, "allowUnsafeCode"),
                OverrideReferences = Bool(r, "overrideReferences"),
                NoEngineReferences = Bool(r, "noEngineReferences"),
            };
            if (string.IsNullOrEmpty(a.Name)) throw new InvalidDataException("no \"name\"");
            a.References.AddRange(Strings(r, "references"));
            a.IncludePlatforms.AddRange(Strings(r, "includePlatforms"));
            a.PrecompiledReferences.AddRange(Strings(r, "precompiledReferences"));
            a.DefineConstraints.AddRange(Strings(r, "defineConstraints"));
            if (r.TryGetProperty("versionDefines", out var vds) && vds.ValueKind == JsonValueKind.Array)
                foreach (var vd in vds.EnumerateArray())
                    if (vd.TryGetProperty("define", out var d) && !string.IsNullOrEmpty(d.GetString()))
                        a.VersionDefines.Add(d.GetString());
            var meta = path + ".meta";
            if (File.Exists(meta))
            {
                var m = Regex.Match(File.ReadAllText(meta), @"^guid:\s*([0-9a-fA-F]{32})", RegexOptions.Multiline);
                if (m.Success) a.Guid = m.Groups[1].Value.ToLowerInvariant();
            }
            return a;
        }

        static bool Bool(JsonElement e, string name) =>
            e.TryGetProperty(name, out var v) && (v.ValueKind == JsonValueKind.True);

        static IEnumerable<string> Strings(JsonElement e, string name)
        {
            if (!e.TryGetProperty(name, out var v) || v.ValueKind != JsonValueKind.Array) yield break;
            foreach (var s in v.EnumerateArray())
                if (s.ValueKind == JsonValueKind.String && !string.IsNullOrWhiteSpace(s.GetString()))
                    yield return s.GetString().Trim();
        }

        static Asmdef Resolve(string reference, Dictionary<string, Asmdef> byName, Dictionary<string, Asmdef> byGuid)
        {
            if (reference.StartsWith("GUID:", StringComparison.Ordinal))
                return byGuid.TryGetValue(reference.Substring(5).ToLowerInvariant(), out var g) ? g : null;
            return byName.TryGetValue(reference, out var a) ? a : null;
        }

        /// <summary>Unity's defineConstraints: each entry is a symbol, "!symbol", or an "a || b" disjunction of those.</summary>
        static bool ConstraintHolds(string constraint, HashSet<string> defines)
        {
            foreach (var term in constraint.Split(new[] { "||" }, StringSplitOptions.RemoveEmptyEntries))
            {
                var t = term.Trim();
                bool neg = t.StartsWith("!", StringComparison.Ordinal);
                var sym = neg ? t.Substring(1).Trim() : t;
                if (defines.Contains(sym) != neg) return true;
            }
            return false;
        }

        static void AddStub(Asmdef a, string name, string stubRoot)
        {
            if (!a.StubRefs.Contains(name) && File.Exists(StubProject(stubRoot, name))) a.StubRefs.Add(name);
        }

        static string StubProject(string stubRoot, string name) =>
            System.IO.Path.Combine(stubRoot, name, name + ".csproj");

        static bool ReachesItself(Asmdef start)
        {
            var seen = new HashSet<Asmdef>();
            var stack = new Stack<Asmdef>(start.PackageRefs);
            while (stack.Count > 0)
            {
                var x = stack.Pop();
                if (x == start) return true;
                if (!seen.Add(x)) continue;
                foreach (var y in x.PackageRefs) stack.Push(y);
            }
            return false;
        }

        static bool DependsOnBroken(Asmdef a)
        {
            var seen = new HashSet<Asmdef>();
            var stack = new Stack<Asmdef>(a.PackageRefs);
            while (stack.Count > 0)
            {
                var x = stack.Pop();
                if (!seen.Add(x)) continue;
                if (x.Problems.Count > 0) return true;
                foreach (var y in x.PackageRefs) stack.Push(y);
            }
            return false;
        }

        static List<Asmdef> Topological(List<Asmdef> all)
        {
            var result = new List<Asmdef>();
            var state = new Dictionary<Asmdef, int>();
            void Visit(Asmdef a)
            {
                if (state.TryGetValue(a, out var s)) return; // 1 = in progress (cycle, reported elsewhere), 2 = done
                state[a] = 1;
                foreach (var d in a.PackageRefs.OrderBy(x => x.Name, StringComparer.Ordinal)) Visit(d);
                state[a] = 2;
                result.Add(a);
            }
            foreach (var a in all.OrderBy(x => x.Name, StringComparer.Ordinal)) Visit(a);
            return result;
        }

        // ---------------------------------------------------------------- generation

        static string ProjectText(string root, string stubRoot, Asmdef a)
        {
            var genFolder = System.IO.Path.GetDirectoryName(a.ProjectPath);
            var sb = new StringBuilder();
            sb.Append("<Project Sdk=\"Microsoft.NET.Sdk\">\n");
            sb.Append($"  <!-- Generated by Tools~/TypeCheck from {Xml(Rel(root, a.Path))}. Do not edit. -->\n");
            sb.Append("  <PropertyGroup>\n");
            sb.Append("    <TargetFramework>netstandard2.1</TargetFramework>\n");
            sb.Append($"    <AssemblyName>{Xml(a.Name)}</AssemblyName>\n");
            sb.Append("    <LangVersion>9.0</LangVersion>\n");
            sb.Append("    <Nullable>disable</Nullable>\n");
            sb.Append("    <ImplicitUsings>disable</ImplicitUsings>\n");
            sb.Append($"    <AllowUnsafeBlocks>{(a.AllowUnsafe ? "true" : "false")}</AllowUnsafeBlocks>\n");
            sb.Append("    <TreatWarningsAsErrors>false</TreatWarningsAsErrors>\n");
            sb.Append("    <WarningLevel>4</WarningLevel>\n");
            if (a.Files.Count == 0)
                sb.Append("    <NoWarn>$(NoWarn);CS2008</NoWarn> <!-- no scripts yet: compiled empty -->\n");
            sb.Append($"    <DefineConstants>$(DefineConstants);{Xml(string.Join(";", a.Defines.OrderBy(x => x, StringComparer.Ordinal)))}</DefineConstants>\n");
            sb.Append("    <EnableDefaultItems>false</EnableDefaultItems>\n");
            sb.Append("    <GenerateAssemblyInfo>false</GenerateAssemblyInfo>\n");
            sb.Append("    <GenerateTargetFrameworkAttribute>false</GenerateTargetFrameworkAttribute>\n");
            sb.Append("    <ProduceReferenceAssembly>false</ProduceReferenceAssembly>\n");
            sb.Append("    <GenerateDocumentationFile>false</GenerateDocumentationFile>\n");
            sb.Append("    <!-- asmdef references are not transitive in Unity. -->\n");
            sb.Append("    <DisableTransitiveProjectReferences>true</DisableTransitiveProjectReferences>\n");
            sb.Append("  </PropertyGroup>\n");
            sb.Append("  <ItemGroup>\n");
            foreach (var f in a.Files.OrderBy(x => x, StringComparer.Ordinal))
                sb.Append($"    <Compile Include=\"{Xml(f)}\" Link=\"{Xml(System.IO.Path.GetRelativePath(a.Folder, f))}\" />\n");
            sb.Append("  </ItemGroup>\n");
            sb.Append("  <ItemGroup>\n");
            foreach (var d in a.PackageRefs.OrderBy(x => x.Name, StringComparer.Ordinal))
                sb.Append($"    <ProjectReference Include=\"{Xml(System.IO.Path.GetRelativePath(genFolder, d.ProjectPath))}\" />\n");
            foreach (var s in a.StubRefs.OrderBy(x => x, StringComparer.Ordinal))
                sb.Append($"    <ProjectReference Include=\"{Xml(System.IO.Path.GetRelativePath(genFolder, StubProject(stubRoot, s)))}\" />\n");
            if (a.OverrideReferences && a.PrecompiledReferences.Any(p => string.Equals(p, k_NUnitDll, StringComparison.OrdinalIgnoreCase)))
                sb.Append($"    <PackageReference Include=\"NUnit\" Version=\"{k_NUnitVersion}\" />\n");
            sb.Append("  </ItemGroup>\n");
            sb.Append("</Project>\n");
            return sb.ToString();
        }

        static void WriteIfChanged(string path, string text)
        {
            Directory.CreateDirectory(System.IO.Path.GetDirectoryName(path));
            if (File.Exists(path) && File.ReadAllText(path) == text) return;
            File.WriteAllText(path, text);
        }

        static bool OutputExists(Asmdef a) =>
            File.Exists(System.IO.Path.Combine(System.IO.Path.GetDirectoryName(a.ProjectPath), "bin", "Debug", "netstandard2.1", a.Name + ".dll"));

        // ---------------------------------------------------------------- build output

        static (int, string) Exec(string file, string[] args)
        {
            var psi = new ProcessStartInfo(file)
            {
                RedirectStandardOutput = true,
                RedirectStandardError = true,
                UseShellExecute = false,
            };
            foreach (var a in args) psi.ArgumentList.Add(a);
            psi.Environment["MSBUILDTERMINALLOGGER"] = "off";
            psi.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";
            psi.Environment["DOTNET_NOLOGO"] = "1";
            using var p = Process.Start(psi);
            var sb = new StringBuilder();
            var lockObj = new object();
            p.OutputDataReceived += (_, e) => { if (e.Data != null) lock (lockObj) sb.AppendLine(e.Data); };
            p.ErrorDataReceived += (_, e) => { if (e.Data != null) lock (lockObj) sb.AppendLine(e.Data); };
            p.BeginOutputReadLine();
            p.BeginErrorReadLine();
            p.WaitForExit();
            return (p.ExitCode, sb.ToString());
        }

        // "<file>(<line>,<col>): error CS0117: <message> [<project>]" (or "<project> : error NU1101: ... [<project or sln>]")
        static readonly Regex k_Diagnostic = new Regex(
            @"^\s*(?<origin>.*?)\s*:\s*(?<kind>error|warning)\s+(?<code>[A-Za-z]+\d+)\s*:\s*(?<msg>.*?)(\s*\[(?<proj>[^\]]+)\])?\s*$",
            RegexOptions.Compiled);

        static void ParseDiagnostics(string output, Dictionary<string, List<string>> errors, Dictionary<string, List<string>> warnings)
        {
            foreach (var raw in output.Split('\n'))
            {
                var line = raw.TrimEnd('\r');
                var m = k_Diagnostic.Match(line);
                if (!m.Success) continue;
                var proj = m.Groups["proj"].Success ? m.Groups["proj"].Value.Trim() : null;
                var origin = m.Groups["origin"].Value.Trim();
                // Restore and MSBuild errors name the project as their origin; the bracket then may be the solution.
                if (proj == null || !proj.EndsWith(".csproj", StringComparison.Ordinal))
                    proj = origin.EndsWith(".csproj", StringComparison.Ordinal) ? origin : proj ?? "(build)";
                var text = $"{origin}: {m.Groups["kind"].Value} {m.Groups["code"].Value}: {m.Groups["msg"].Value}";
                var dict = m.Groups["kind"].Value == "error" ? errors : warnings;
                if (!dict.TryGetValue(proj, out var list)) dict[proj] = list = new List<string>();
                if (!list.Contains(text)) list.Add(text);
            }
        }

        // ---------------------------------------------------------------- helpers

        static string Rel(string root, string path) => System.IO.Path.GetRelativePath(root, path).Replace('\\', '/');

        static string Shorten(string root, string line) => line.Replace(root + System.IO.Path.DirectorySeparatorChar, "");

        static string Xml(string s) => s.Replace("&", "&amp;").Replace("<", "&lt;").Replace(">", "&gt;").Replace("\"", "&quot;");
    }
}
