using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;

namespace SoftBodyDynamics.PackageLint
{
    /// <summary>
    /// Checks what Unity needs to import the package from git, without Unity, and that the documentation's links resolve.
    /// Usage: PackageLint PACKAGE_ROOT [--fix]   (--fix writes missing .meta files with new GUIDs)
    /// Prints PASS/FAIL per rule and ends with "RESULT lint &lt;passed&gt; &lt;failed&gt;".
    /// </summary>
    static class Program
    {
        /// <summary>Unity and package assemblies an asmdef may reference by name.</summary>
        static readonly HashSet<string> s_KnownUnityAssemblies = new HashSet<string>
        {
            "Unity.Mathematics", "Unity.Mathematics.Extensions", "Unity.Burst", "Unity.Collections", "Unity.Entities",
            "Unity.Entities.Hybrid", "Unity.Entities.Graphics", "Unity.Transforms", "Unity.Scenes", "Unity.Deformations",
            "Unity.RenderPipelines.Core.Runtime", "Unity.RenderPipelines.Universal.Runtime",
            "Unity.PerformanceTesting", "UnityEngine.TestRunner", "UnityEditor.TestRunner", "Unity.Physics",
        };

        static int s_Passed, s_Failed;

        static int Main(string[] args)
        {
            if (args.Length < 1 || !Directory.Exists(args[0]))
            {
                Console.Error.WriteLine("usage: PackageLint PACKAGE_ROOT [--fix]");
                return 2;
            }
            string root = Path.GetFullPath(args[0]);
            bool fix = args.Contains("--fix");

            List<string> imported = ImportedPaths(root).ToList();
            CheckMetaFiles(root, imported, fix);
            Dictionary<string, string> guids = CheckGuids(root, imported);
            CheckAsmdefs(root, imported, guids);
            CheckPackageJson(root);
            CheckSolverPurity(root);
            CheckMarkdown(root);

            Console.WriteLine($"RESULT lint {s_Passed} {s_Failed}");
            return s_Failed == 0 ? 0 : 1;
        }

        static void Report(string rule, List<string> problems)
        {
            if (problems.Count == 0) { s_Passed++; Console.WriteLine($"PASS {rule}"); return; }
            s_Failed++;
            Console.WriteLine($"FAIL {rule}");
            foreach (string p in problems.Take(50)) Console.WriteLine($"  - {p}");
            if (problems.Count > 50) Console.WriteLine($"  … and {problems.Count - 50} more");
        }

        /// <summary>Hidden to Unity: names starting with '.', ending with '~', named cvs, or *.tmp (Unity Manual, "Special folder names").</summary>
        static bool IsHidden(string name) =>
            name.StartsWith(".") || name.EndsWith("~") || name.Equals("cvs", StringComparison.OrdinalIgnoreCase)
            || name.EndsWith(".tmp", StringComparison.OrdinalIgnoreCase);

        /// <summary>Every file and folder Unity imports from the package (relative paths, '/' separators).</summary>
        static IEnumerable<string> ImportedPaths(string root)
        {
            var stack = new Stack<string>();
            stack.Push(root);
            while (stack.Count > 0)
            {
                string dir = stack.Pop();
                foreach (string entry in Directory.EnumerateFileSystemEntries(dir).OrderBy(e => e, StringComparer.Ordinal))
                {
                    string name = Path.GetFileName(entry);
                    if (IsHidden(name) || name.EndsWith(".meta")) continue;
                    yield return Rel(root, entry);
                    if (Directory.Exists(entry)) stack.Push(entry);
                }
            }
        }

        static string Rel(string root, string path) => Path.GetRelativePath(root, path).Replace('\\', '/');

        static void CheckMetaFiles(string root, List<string> imported, bool fix)
        {
            var missing = new List<string>();
            foreach (string rel in imported)
            {
                string meta = Path.Combine(root, rel + ".meta");
                if (File.Exists(meta)) continue;
                if (fix)
                {
                    File.WriteAllText(meta, MetaTemplate.For(rel, Directory.Exists(Path.Combine(root, rel))));
                    Console.WriteLine($"  wrote {rel}.meta");
                    continue;
                }
                missing.Add($"{rel} has no .meta (run: dotnet run --project Tools~/PackageLint -- . --fix)");
            }
            Report("every imported file and folder has a .meta", missing);

            var importedSet = new HashSet<string>(imported);
            var orphans = new List<string>();
            foreach (string rel in imported.Where(r => Directory.Exists(Path.Combine(root, r))).Append("."))
            {
                foreach (string meta in Directory.EnumerateFiles(Path.Combine(root, rel), "*.meta"))
                {
                    string asset = Rel(root, meta.Substring(0, meta.Length - 5));
                    if (!importedSet.Contains(asset)) orphans.Add($"{Rel(root, meta)} has no asset beside it");
                }
            }
            Report("no orphan .meta files", orphans);
        }

        static readonly Regex s_GuidLine = new Regex(@"^guid: ([0-9a-f]{32})\s*$", RegexOptions.Multiline);

        static Dictionary<string, string> CheckGuids(string root, List<string> imported)
        {
            var byGuid = new Dictionary<string, string>();
            var problems = new List<string>();
            foreach (string rel in imported)
            {
                string meta = Path.Combine(root, rel + ".meta");
                if (!File.Exists(meta)) continue;
                string text = File.ReadAllText(meta);
                Match m = s_GuidLine.Match(text);
                if (!m.Success || !text.StartsWith("fileFormatVersion: 2"))
                {
                    problems.Add($"{rel}.meta: no 'fileFormatVersion: 2' header or no 32-hex lowercase guid");
                    continue;
                }
                string guid = m.Groups[1].Value;
                if (guid.All(c => c == '0')) problems.Add($"{rel}.meta: all-zero guid");
                if (byGuid.TryGetValue(guid, out string other)) problems.Add($"{rel}.meta and {other}.meta share guid {guid}");
                else byGuid[guid] = rel;
            }
            Report(".meta GUIDs are well-formed and unique", problems);
            return byGuid;
        }

        static void CheckAsmdefs(string root, List<string> imported, Dictionary<string, string> guids)
        {
            var problems = new List<string>();
            var names = new Dictionary<string, string>();
            var docs = new List<(string rel, JsonElement json)>();
            foreach (string rel in imported.Where(r => r.EndsWith(".asmdef")))
            {
                try
                {
                    JsonElement json = JsonDocument.Parse(File.ReadAllText(Path.Combine(root, rel))).RootElement;
                    string name = json.GetProperty("name").GetString();
                    if (string.IsNullOrWhiteSpace(name)) problems.Add($"{rel}: empty name");
                    else if (names.TryGetValue(name, out string other)) problems.Add($"{rel}: name {name} also used by {other}");
                    else names[name] = rel;
                    docs.Add((rel, json));
                }
                catch (Exception e) when (e is JsonException || e is KeyNotFoundException)
                {
                    problems.Add($"{rel}: {e.Message}");
                }
            }
            foreach (var (rel, json) in docs)
            {
                if (!json.TryGetProperty("references", out JsonElement refs)) continue;
                foreach (JsonElement r in refs.EnumerateArray())
                {
                    string reference = r.GetString() ?? "";
                    if (reference.StartsWith("GUID:"))
                    {
                        string g = reference.Substring(5);
                        if (!guids.TryGetValue(g, out string target) || !target.EndsWith(".asmdef"))
                            problems.Add($"{rel}: reference {reference} is not the GUID of an asmdef in the package");
                    }
                    else if (!names.ContainsKey(reference) && !s_KnownUnityAssemblies.Contains(reference))
                        problems.Add($"{rel}: reference '{reference}' is neither a package asmdef nor a known Unity assembly");
                }
            }
            Report("asmdefs parse, have unique names, and their references resolve", problems);

            // Everything under Tests/ and Benchmarks/ (the benchmarks and the scenarios they share with the headless
            // runner) exists for tests only and must stay out of players.
            var testProblems = new List<string>();
            foreach (var (rel, json) in docs.Where(d => d.rel.StartsWith("Tests/") || d.rel.StartsWith("Benchmarks/")))
            {
                if (!IsTestGated(json)) testProblems.Add($"{rel}: test assembly without the UNITY_INCLUDE_TESTS define constraint");
                if (json.TryGetProperty("autoReferenced", out JsonElement auto) && auto.ValueKind == JsonValueKind.True)
                    testProblems.Add($"{rel}: test assembly with autoReferenced true (game scripts would see it)");
            }
            Report("test assemblies compile only with UNITY_INCLUDE_TESTS", testProblems);

            // An assembly that players compile cannot reference one that only test runs compile.
            var gatedNames = new HashSet<string>(docs.Where(d => IsTestGated(d.json)).Select(d => d.json.GetProperty("name").GetString()));
            var gatedGuids = new HashSet<string>(guids.Where(kv => gatedNames.Contains(AsmdefName(root, kv.Value))).Select(kv => kv.Key));
            var leakProblems = new List<string>();
            foreach (var (rel, json) in docs.Where(d => !IsTestGated(d.json)))
            {
                if (!json.TryGetProperty("references", out JsonElement refs)) continue;
                foreach (JsonElement r in refs.EnumerateArray())
                {
                    string reference = r.GetString() ?? "";
                    bool gated = reference.StartsWith("GUID:") ? gatedGuids.Contains(reference.Substring(5)) : gatedNames.Contains(reference);
                    if (gated) leakProblems.Add($"{rel}: references test-only assembly {reference}, which players do not compile");
                }
            }
            Report("player assemblies reference no test-only assembly", leakProblems);
        }

        static bool IsTestGated(JsonElement asmdef) =>
            asmdef.TryGetProperty("defineConstraints", out JsonElement dc)
            && dc.EnumerateArray().Any(e => e.GetString() == "UNITY_INCLUDE_TESTS");

        /// <summary>The "name" of the asmdef at <paramref name="rel"/>, or null when <paramref name="rel"/> is not a readable asmdef.</summary>
        static string AsmdefName(string root, string rel)
        {
            if (!rel.EndsWith(".asmdef")) return null;
            try { return JsonDocument.Parse(File.ReadAllText(Path.Combine(root, rel))).RootElement.GetProperty("name").GetString(); }
            catch (Exception e) when (e is JsonException || e is KeyNotFoundException || e is IOException) { return null; }
        }

        static readonly Regex s_SemVer = new Regex(@"^\d+\.\d+\.\d+(-[0-9A-Za-z.-]+)?$");

        static void CheckPackageJson(string root)
        {
            var problems = new List<string>();
            try
            {
                JsonElement p = JsonDocument.Parse(File.ReadAllText(Path.Combine(root, "package.json"))).RootElement;
                string name = p.GetProperty("name").GetString() ?? "";
                if (!Regex.IsMatch(name, @"^[a-z0-9][a-z0-9._-]*$") || name.Count(c => c == '.') < 2)
                    problems.Add($"name '{name}' is not a reverse-domain lowercase package name");
                if (!s_SemVer.IsMatch(p.GetProperty("version").GetString() ?? "")) problems.Add("version is not semver");
                if (!Regex.IsMatch(p.GetProperty("unity").GetString() ?? "", @"^\d{4}\.\d+$")) problems.Add("unity is not 'YYYY.N'");
                if (string.IsNullOrWhiteSpace(p.GetProperty("displayName").GetString())) problems.Add("displayName is empty");
                if (string.IsNullOrWhiteSpace(p.GetProperty("description").GetString())) problems.Add("description is empty");
                foreach (JsonProperty d in p.GetProperty("dependencies").EnumerateObject())
                    if (!s_SemVer.IsMatch(d.Value.GetString() ?? "")) problems.Add($"dependency {d.Name}: '{d.Value}' is not a version");
                if (p.TryGetProperty("samples", out JsonElement samples))
                    foreach (JsonElement s in samples.EnumerateArray())
                    {
                        string path = s.GetProperty("path").GetString() ?? "";
                        if (!path.StartsWith("Samples~/")) problems.Add($"sample path '{path}' is not under Samples~/");
                        if (!Directory.Exists(Path.Combine(root, path))) problems.Add($"sample path '{path}' does not exist");
                        if (string.IsNullOrWhiteSpace(s.GetProperty("displayName").GetString())) problems.Add($"sample '{path}' has no displayName");
                    }
                foreach (string f in new[] { "README.md", "CHANGELOG.md", "LICENSE.md", "Documentation~/index.md" })
                    if (!File.Exists(Path.Combine(root, f))) problems.Add($"{f} is missing");
            }
            catch (Exception e) when (e is JsonException || e is KeyNotFoundException || e is IOException || e is InvalidOperationException)
            {
                problems.Add($"package.json: {e.Message}");
            }
            Report("package.json is valid and its sample paths exist", problems);
        }

        static readonly Regex s_EngineUsing = new Regex(@"^\s*using\s+(static\s+)?(UnityEngine|UnityEditor|Unity\.Entities|Unity\.Collections|Unity\.Jobs|Unity\.Burst)\b", RegexOptions.Multiline);

        static void CheckSolverPurity(string root)
        {
            var problems = new List<string>();
            string dir = Path.Combine(root, "Runtime", "Solvers");
            if (Directory.Exists(dir))
                foreach (string file in Directory.EnumerateFiles(dir, "*.cs", SearchOption.AllDirectories))
                {
                    string text = File.ReadAllText(file);
                    foreach (Match m in s_EngineUsing.Matches(text))
                        problems.Add($"{Rel(root, file)}: '{m.Value.Trim()}' (Runtime/Solvers depends on Unity.Mathematics only)");
                    if (Regex.IsMatch(text, @"\busing\s+System\.Linq\b"))
                        problems.Add($"{Rel(root, file)}: System.Linq in solver code (not Burst-compatible)");
                }
            Report("Runtime/Solvers uses Unity.Mathematics only (no engine, ECS or LINQ)", problems);
        }

        /// <summary>Largest README.md in bytes: the README is a front page; the manual holds the details.</summary>
        const int k_MaxReadmeBytes = 9000;

        static void CheckMarkdown(string root)
        {
            var files = new List<string> { "README.md", "CHANGELOG.md" };
            string docs = Path.Combine(root, "Documentation~");
            if (Directory.Exists(docs))
                files.AddRange(Directory.EnumerateFiles(docs, "*.md").Select(f => Rel(root, f)).OrderBy(f => f, StringComparer.Ordinal));
            var problems = new List<string>();
            foreach (string f in files.Where(f => !File.Exists(Path.Combine(root, f)))) problems.Add($"{f} is missing");
            problems.AddRange(MarkdownLinks.Check(root, files.Where(f => File.Exists(Path.Combine(root, f)))));
            Report("Markdown links resolve (README.md, CHANGELOG.md, Documentation~/*.md)", problems);

            var size = new List<string>();
            var readme = new FileInfo(Path.Combine(root, "README.md"));
            if (readme.Exists && readme.Length > k_MaxReadmeBytes)
                size.Add($"README.md is {readme.Length} bytes; move details into Documentation~ and link them");
            Report($"README.md is at most {k_MaxReadmeBytes} bytes", size);
        }
    }
}
