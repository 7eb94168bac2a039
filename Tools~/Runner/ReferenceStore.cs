using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using System.Text;
using System.Text.Json;
using System.Text.Json.Nodes;
using System.Text.Json.Serialization;
using SoftBodyDynamics.Benchmarks.Scenarios;

namespace SoftBodyDynamics.Runner
{
    /// <summary>
    /// The float64 reference values of the suites that have them (<see cref="IScenarioSuiteStoredReference"/>), stored in
    /// <see cref="FileName"/> with the SHA-256 of the sources they come from (<see cref="SourceFolders"/>). A default or
    /// quick run uses the stored values when the sources are unchanged and computes the rest; a full run always computes
    /// them. A run that computed them writes the file into its report folder and says whether the stored values agree.
    /// </summary>
    static class ReferenceStore
    {
        /// <summary>The stored file: in Tools~/Runner (committed) and in a full run's report folder (written).</summary>
        public const string FileName = "reference-values.json";

        /// <summary>Folders (package-relative) whose .cs files the references are computed from: the float64 solvers, and the scenes and targets of the method study.</summary>
        public static readonly string[] SourceFolders = { "Benchmarks/Scenarios/Reference", "Benchmarks/Scenarios/SoftBody/Methods" };

        /// <summary>Files of the method-study folder that define a reference: the targets and the scenes (the bodies of the methods do not count).</summary>
        static bool IsSource(string relativePath) =>
            relativePath.StartsWith(SourceFolders[0] + "/", StringComparison.Ordinal) ||
            relativePath.EndsWith("Targets.cs", StringComparison.Ordinal) || relativePath.EndsWith("Scene.cs", StringComparison.Ordinal);

        static readonly JsonSerializerOptions s_Json = new JsonSerializerOptions
        {
            IncludeFields = true,
            NumberHandling = JsonNumberHandling.AllowNamedFloatingPointLiterals,
            WriteIndented = true,
        };

        /// <summary>SHA-256 (hex) over the path and bytes of every reference source under <paramref name="root"/>, in ordinal path order.</summary>
        public static string SourceHash(string root)
        {
            var files = new List<string>();
            foreach (string folder in SourceFolders)
            {
                string dir = Path.Combine(root, folder);
                if (!Directory.Exists(dir))
                    continue;
                foreach (string f in Directory.EnumerateFiles(dir, "*.cs", SearchOption.AllDirectories))
                {
                    string rel = Path.GetRelativePath(root, f).Replace('\\', '/');
                    if (IsSource(rel))
                        files.Add(rel);
                }
            }
            files.Sort(StringComparer.Ordinal);
            using (var sha = IncrementalHash.CreateHash(HashAlgorithmName.SHA256))
            {
                foreach (string rel in files)
                {
                    sha.AppendData(Encoding.UTF8.GetBytes(rel + "\n"));
                    sha.AppendData(File.ReadAllBytes(Path.Combine(root, rel)));
                }
                return Convert.ToHexString(sha.GetHashAndReset()).ToLowerInvariant();
            }
        }

        /// <summary>
        /// Hands each suite its stored values when <paramref name="path"/> holds values of the sources hashed to
        /// <paramref name="sourceHash"/>; returns the names of the suites that took them.
        /// </summary>
        /// <param name="computedBy">The stored file's "computed" entry (e.g. "default run, 2026-11-27"); null when nothing was used.</param>
        public static List<string> Use(string path, string sourceHash, IEnumerable<IScenarioSuiteStoredReference> suites, out string why,
            out string computedBy)
        {
            computedBy = null;
            var used = new List<string>();
            if (!File.Exists(path))
            {
                why = "no stored values";
                return used;
            }
            JsonObject stored = JsonNode.Parse(File.ReadAllText(path))?.AsObject();
            if (stored == null || (string)stored["sources"] != sourceHash)
            {
                why = "the reference sources changed since they were stored";
                return used;
            }
            var values = stored["references"]?.AsObject();
            foreach (IScenarioSuiteStoredReference suite in suites)
            {
                JsonNode node = values?[((IScenarioSuite)suite).Name];
                if (node == null)
                    continue;
                suite.UseReference(node.Deserialize(suite.ReferenceType, s_Json));
                used.Add(((IScenarioSuite)suite).Name);
            }
            why = used.Count > 0 ? "stored" : "none of this run's suites is stored";
            if (used.Count > 0)
                computedBy = (string)stored["computed"] ?? "earlier run";
            return used;
        }

        /// <summary>Writes the (computed) reference values of <paramref name="suites"/> with their source hash to <paramref name="path"/>.</summary>
        public static void Write(string path, string sourceHash, IEnumerable<IScenarioSuiteStoredReference> suites, string computedBy)
        {
            var references = new JsonObject();
            foreach (IScenarioSuiteStoredReference suite in suites.OrderBy(s => ((IScenarioSuite)s).Name, StringComparer.Ordinal))
                references[((IScenarioSuite)suite).Name] = JsonSerializer.SerializeToNode(suite.Reference(), suite.ReferenceType, s_Json);
            var root = new JsonObject
            {
                ["sources"] = sourceHash,
                ["computed"] = computedBy,
                ["references"] = references,
            };
            string tmp = path + ".tmp";
            File.WriteAllText(tmp, root.ToJsonString(s_Json) + "\n");
            File.Move(tmp, path, true);
        }

        /// <summary>
        /// Names of the suites whose values in <paramref name="computedPath"/> differ from those in <paramref name="storedPath"/>
        /// (timings of the reference left out); null when the stored file is missing or of other sources.
        /// </summary>
        public static List<string> Differences(string storedPath, string computedPath)
        {
            if (!File.Exists(storedPath) || !File.Exists(computedPath))
                return null;
            JsonObject stored = JsonNode.Parse(File.ReadAllText(storedPath))?.AsObject();
            JsonObject computed = JsonNode.Parse(File.ReadAllText(computedPath))?.AsObject();
            if (stored == null || computed == null || (string)stored["sources"] != (string)computed["sources"])
                return null;
            var differ = new List<string>();
            foreach (KeyValuePair<string, JsonNode> entry in computed["references"].AsObject())
            {
                JsonNode old = stored["references"]?[entry.Key];
                if (old == null || !SameValues(old, entry.Value))
                    differ.Add(entry.Key);
            }
            return differ;
        }

        /// <summary>Equal JSON trees, ignoring fields named "Seconds" (how long a reference took is not part of it).</summary>
        static bool SameValues(JsonNode a, JsonNode b)
        {
            if (a is JsonObject oa && b is JsonObject ob)
            {
                var keys = oa.Select(p => p.Key).Union(ob.Select(p => p.Key)).Where(k => k != "Seconds");
                return keys.All(k => oa[k] != null && ob[k] != null ? SameValues(oa[k], ob[k]) : oa[k] == null && ob[k] == null);
            }
            if (a is JsonArray aa && b is JsonArray ab)
                return aa.Count == ab.Count && aa.Zip(ab, SameValues).All(x => x);
            return a?.ToJsonString() == b?.ToJsonString();
        }
    }
}
